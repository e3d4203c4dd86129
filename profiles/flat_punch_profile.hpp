// The flat cylindrical punch of radius A: f = 0 for r <= A, a wall outside; g = 0 for x <= A.
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

/// Its glued contact has radius A whatever the depth (fixed_contact_radius): the boundary
/// spring starts at the punch edge. All springs have g = 0 and the same stretch, so once
/// the edge spring lets go every inner one (smaller dl) follows at once: a single cascade.
class FlatPunchProfile final : public Profile {
 public:
  explicit FlatPunchProfile(double radius);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  bool always_one_disk() const override { return true; }
  bool cheap_image() const override { return true; }
  double mdr_image_slope(double x) const override;
  double contact_radius_at_depth(double depth) const override;
  /// Zero for a <= A: the punch face carries no force without an indentation, whose
  /// force 2 E* A d the radius alone does not fix.
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  std::optional<double> fixed_contact_radius() const override { return radius_; }
  double outer_radius() const override { return radius_; }
  /// Kendall's pull-off: F0 = sqrt(8 pi A^3 E* dgamma), a0 = A, d0 = sqrt(2 pi A dgamma/E*).
  std::optional<PullOffScales> pull_off_scales(double effective_modulus,
                                               double work_of_adhesion) const override;

 private:
  double radius_;  ///< A [m]
};

}  // namespace mdrsim
