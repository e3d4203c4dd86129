// The cone's closed forms: image, depth-radius relation and the non-adhesive force.
#include "profiles/cone_profile.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/base/angle_series.hpp"
#include "profiles/power_law_profile.hpp"

namespace mdrsim {

ConeProfile::ConeProfile(double slope_angle_deg) {
  if (!(slope_angle_deg > 0.0 && slope_angle_deg < 90.0)) {
    throw std::invalid_argument("the cone's slope angle must lie in (0, 90) degrees");
  }
  slope_ = std::tan(slope_angle_deg * std::numbers::pi / 180.0);
  image_slope_ = 0.5 * std::numbers::pi * slope_;
}

double ConeProfile::shape(double r) const { return r * slope_; }

double ConeProfile::mdr_image(double x) const { return image_slope_ * x; }

double ConeProfile::contact_radius_at_depth(double depth) const {
  return depth > 0.0 ? depth / image_slope_ : 0.0;
}

// 2 integral_0^a k (a - x) dx = k a^2 with k = (pi/2) tan(theta): the classical cone force
// F = (pi/2) E* a^2 tan(theta) (Sneddon).
double ConeProfile::nonadhesive_force_per_modulus(double a) const { return image_slope_ * a * a; }

// int_a^c k (x - a)/sqrt(c^2 - x^2) dx = k (s - a t) = k a (tan t - t), s = sqrt(c^2 - a^2);
// at a = 0 it is k c (a -> 0 with t -> pi/2). Its slope at fixed a is tan(t) int_a^c k x /
// sqrt(c^2 - x^2) dx = k s tan(t).
DugdaleGap ConeProfile::dugdale_gap(double a, double c, double t) const {
  return {.integral = a > 0.0 ? image_slope_ * a * tan_minus_angle(t) : image_slope_ * c,
          .angle_slope = image_slope_ * c * std::sin(t) * std::tan(t)};
}

// k = (pi/2) tan(theta): a0 = 9 pi dgamma/(2 E* k^2), F0 = E* k a0^2/3 = 27 pi^2 dgamma^2/(4 E*
// k^3), d0 = k a0/3, the critical indentation itself (positive: the cone jumps off pressed in).
std::optional<PullOffScales> ConeProfile::pull_off_scales(double effective_modulus,
                                                          double work_of_adhesion) const {
  return PowerLawProfile::pull_off_scales_of(
      image_slope_, 1.0, effective_modulus, work_of_adhesion,
      "cone: the fixed-load pull-off, F0 = 54 dgamma^2/(pi E* tan^3 theta), a0 = 18 dgamma/(pi "
      "E* tan^2 theta), d0 = 3 dgamma/(E* tan theta)");
}

}  // namespace mdrsim
