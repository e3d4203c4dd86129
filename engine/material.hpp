// The elastic half-space and the interface: effective moduli (paper eqs. 8-9) and adhesion.
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

struct Material {
  double effective_modulus;        ///< E* = E/(1 - nu^2) [Pa]
  double effective_shear_modulus;  ///< G* = 4G/(2 - nu) [Pa]
  double work_of_adhesion;         ///< dgamma [J/m^2]

  /// From Young's modulus E [Pa] and Poisson's ratio nu (paper eq. 8).
  static Material from_youngs_modulus(double youngs_modulus, double poisson_ratio,
                                      double work_of_adhesion);

  InterfaceProperties interface_properties() const {
    return {effective_modulus, effective_shear_modulus, work_of_adhesion};
  }
};

}  // namespace mdrsim
