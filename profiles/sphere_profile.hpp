// The exact spherical cap f(r) = R - sqrt(R^2 - r^2) and its MDR image g(x) = x artanh(x/R).
#pragma once

#include "profiles/profile.hpp"

namespace mdrsim {

/// A rigid sphere of radius R. Its tip is the parabola r^2/(2R), so the JKR scales of that
/// parabola apply (dimensionless output); it departs from the parabola as a/R grows, and
/// ends at r = R, where its image diverges.
class SphereProfile final : public Profile {
 public:
  explicit SphereProfile(double radius);

  /// R - sqrt(R^2 - r^2) for r <= R; +infinity beyond (nothing outside the sphere touches).
  double shape(double radius) const override;
  /// Eq. 4 with f' = r/sqrt(R^2 - r^2): g = (x/2) ln((R + x)/(R - x)) = x artanh(x/R), x < R.
  double mdr_image(double x) const override;
  bool always_one_disk() const override { return true; }
  double mdr_image_slope(double x) const override;
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  /// Where c <= R/2, by the image's series x^2 sum_k (x/R)^(2k)/((2k+1) R), each term a power
  /// law's J in closed form (relative accuracy a few ulps); beyond, dugdale_gap_quadrature.
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  double outer_radius() const override { return radius_; }
  std::optional<double> jkr_scale_radius() const override { return radius_; }

 private:
  double radius_;  ///< R [m]
};

}  // namespace mdrsim
