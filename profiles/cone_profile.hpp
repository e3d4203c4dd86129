// The cone f(r) = r tan(theta) and its MDR image g(x) = (pi/2) x tan(theta).
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

/// A rigid cone whose flank makes the angle theta with the surface, 0 < theta < 90 degrees.
class ConeProfile final : public Profile {
 public:
  explicit ConeProfile(double slope_angle_deg);

  double shape(double radius) const override;
  /// Eq. 4 with f' = tan(theta): g = x tan(theta) integral_0^x dr/sqrt(x^2 - r^2).
  double mdr_image(double x) const override;
  bool always_one_disk() const override { return true; }
  bool cheap_image() const override { return true; }
  double mdr_image_slope(double) const override { return image_slope_; }
  double contact_radius_at_depth(double depth) const override;
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  /// The power law's with n = 1: F0 = 54 dgamma^2/(pi E* tan^3 theta),
  /// a0 = 18 dgamma/(pi E* tan^2 theta), d0 = 3 dgamma/(E* tan theta).
  std::optional<PullOffScales> pull_off_scales(double effective_modulus,
                                               double work_of_adhesion) const override;

 private:
  double slope_;        ///< tan(theta) [1]
  double image_slope_;  ///< (pi/2) tan(theta) [1]
};

}  // namespace mdrsim
