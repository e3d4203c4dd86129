// The parabolic indenter f(r) = r^2/(2R) and its MDR image g(x) = x^2/R (paper eq. 6).
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

class ParabolicProfile final : public Profile {
 public:
  explicit ParabolicProfile(double radius);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  bool always_one_disk() const override { return true; }
  bool cheap_image() const override { return true; }
  double mdr_image_slope(double x) const override { return 2.0 * x / radius_; }
  double contact_radius_at_depth(double depth) const override;
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  std::optional<double> jkr_scale_radius() const override { return radius_; }

 private:
  double radius_;  ///< R, the radius of curvature at the tip [m]
};

}  // namespace mdrsim
