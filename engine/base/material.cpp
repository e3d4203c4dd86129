// Effective moduli of the MDR foundation from E and nu (paper eq. 8).
#include "engine/base/material.hpp"

namespace mdrsim {

Material Material::from_youngs_modulus(double e, double nu, double work_of_adhesion) {
  const double shear_modulus = e / (2.0 * (1.0 + nu));
  return {e / (1.0 - nu * nu), 4.0 * shear_modulus / (2.0 - nu), work_of_adhesion};
}

}  // namespace mdrsim
