// The wavy profile: its shape and its MDR image through the ripple integrals.
#include "profiles/wavy_profile.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "engine/base/angle_series.hpp"
#include "profiles/wavy_gap.hpp"
#include "profiles/wavy_image.hpp"

namespace mdrsim {

WavyProfile::WavyProfile(double radius, double amplitude, double wavelength)
    : radius_(radius), amplitude_(amplitude), wavenumber_(2.0 * std::numbers::pi / wavelength) {
  if (!(radius > 0.0) || !(amplitude > 0.0) || !(wavelength > 0.0) || !std::isfinite(wavenumber_)) {
    throw std::invalid_argument("wavy: radius, amplitude and wavelength must be positive");
  }
}

double WavyProfile::shape(double radius) const {
  return radius * radius / (2.0 * radius_) + amplitude_ * (1.0 - std::cos(wavenumber_ * radius));
}

double WavyProfile::mdr_image(double x) const {
  // Term by term: the parabola's x^2/R and the ripple's A k x I(k x).
  const double z = wavenumber_ * x;
  return x * x / radius_ + amplitude_ * z * ripple_integrals(z).value;
}

double WavyProfile::mdr_image_slope(double x) const {
  // d/dx [A z I(z)] = A k (I(z) + z I'(z)).
  const double z = wavenumber_ * x;
  const RippleIntegrals ripple = ripple_integrals(z);
  return 2.0 * x / radius_ + amplitude_ * wavenumber_ * (ripple.value + z * ripple.slope);
}

double WavyProfile::nonadhesive_force_per_modulus(double contact_radius) const {
  // The parabola's 2 a^3/(3R) and the ripple's A a Z I(Z) - (A/k) int_0^Z z I(z) dz; the
  // ripple's two terms do not cancel where Z is small (Z^2 - Z^2/3).
  const double a = contact_radius;
  const double z = wavenumber_ * a;
  const RippleIntegrals ripple = ripple_integrals(z);
  const double ripple_part = amplitude_ * a * (z * ripple.value - ripple.slope_deficit);
  return 2.0 * (2.0 * a * a * a / (3.0 * radius_) + ripple_part);
}

DugdaleGap WavyProfile::dugdale_gap(double a, double c, double t) const {
  if (wavenumber_ * a > std::numbers::pi * kMaxWavyGapHalfWaves) {
    return dugdale_gap_quadrature(*this, a, c, t);
  }
  // The parabola's part as ParabolicProfile::dugdale_gap has it.
  const double sin_t = std::sin(t), cos_t = std::cos(t);
  const double s = c * sin_t;
  const DugdaleGap ripple = wavy_ripple_gap(amplitude_, wavenumber_, a, c, t);
  return {.integral = (a * a * tan_minus_angle(t) + t * s * s) / (2.0 * radius_) + ripple.integral,
          .angle_slope = std::tan(t) * c * c * (t + sin_t * cos_t) / radius_ + ripple.angle_slope};
}

}  // namespace mdrsim
