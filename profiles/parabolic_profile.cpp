// The parabolic indenter: closed forms of its MDR image, Hertz radius and Hertz force.
#include "profiles/parabolic_profile.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/base/angle_series.hpp"

namespace mdrsim {

ParabolicProfile::ParabolicProfile(double radius) : radius_(radius) {
  if (!(radius > 0.0) || !std::isfinite(radius)) {
    throw std::invalid_argument("the parabola's radius must be positive and finite");
  }
}

double ParabolicProfile::shape(double r) const { return r * r / (2.0 * radius_); }

double ParabolicProfile::mdr_image(double x) const { return x * x / radius_; }

double ParabolicProfile::contact_radius_at_depth(double depth) const {
  return depth > 0.0 ? std::sqrt(radius_ * depth) : 0.0;
}

// 2 * integral_0^a (a^2 - x^2)/R dx = 4 a^3 / (3 R), the Hertz force over E*.
double ParabolicProfile::nonadhesive_force_per_modulus(double a) const {
  return 4.0 * a * a * a / (3.0 * radius_);
}

// int_a^c (x^2 - a^2)/(R sqrt(c^2 - x^2)) dx = (a s - a^2 t + s^2 t) / (2R) with s = c sin(t) =
// sqrt(c^2 - a^2); a s - a^2 t = a^2 (tan t - t) cancels at small t and takes its series. Its
// slope at fixed a is tan(t) int_a^c 2 x^2/(R sqrt(c^2 - x^2)) dx = tan(t) c^2 (t + sin t cos t)/R.
DugdaleGap ParabolicProfile::dugdale_gap(double a, double c, double t) const {
  const double sin_t = std::sin(t), cos_t = std::cos(t);
  const double s = c * sin_t;
  return {.integral = (a * a * tan_minus_angle(t) + t * s * s) / (2.0 * radius_),
          .angle_slope = std::tan(t) * c * c * (t + sin_t * cos_t) / radius_};
}

}  // namespace mdrsim
