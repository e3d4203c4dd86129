// The power-law indenter f(r) = c r^n and its MDR image g(x) = kappa(n) c x^n.
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

/// n > 0: n = 1 is a cone, n = 2 a parabola (c = 1/(2R)), large n approaches a flat punch.
class PowerLawProfile final : public Profile {
 public:
  PowerLawProfile(double coefficient, double exponent);

  /// kappa(n) = sqrt(pi) Gamma(n/2 + 1) / Gamma(n/2 + 1/2), the factor of eq. 4 for r^n.
  static double image_factor(double exponent);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  double mdr_image_slope(double x) const override;
  double contact_radius_at_depth(double depth) const override;
  double nonadhesive_force_per_modulus(double contact_radius) const override;

 private:
  double coefficient_;        ///< c [m^(1-n)]
  double exponent_;           ///< n [1]
  double image_coefficient_;  ///< kappa(n) c [m^(1-n)]
};

}  // namespace mdrsim
