// The power law's closed forms (Hess's MDR image of r^n).
#include "profiles/power_law_profile.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace mdrsim {

PowerLawProfile::PowerLawProfile(double coefficient, double exponent)
    : coefficient_(coefficient), exponent_(exponent) {
  if (!(coefficient > 0.0) || !std::isfinite(coefficient)) {
    throw std::invalid_argument("the power law's coefficient must be positive and finite");
  }
  if (!(exponent > 0.0) || !std::isfinite(exponent)) {
    throw std::invalid_argument("the power law's exponent must be positive and finite");
  }
  image_coefficient_ = image_factor(exponent) * coefficient;
  if (!std::isfinite(image_coefficient_)) {
    throw std::invalid_argument("the power law's coefficient overflows its MDR image");
  }
}

// Eq. 4 with f' = n c r^(n-1) and r = x s: g = n c x^n integral_0^1 s^(n-1)/sqrt(1 - s^2) ds
// = n c x^n B(n/2, 1/2)/2 = c x^n sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2). Log-gammas keep
// the ratio finite for large n (it grows like sqrt(pi n/2)).
double PowerLawProfile::image_factor(double n) {
  return std::sqrt(std::numbers::pi) *
         std::exp(std::lgamma(0.5 * n + 1.0) - std::lgamma(0.5 * n + 0.5));
}

double PowerLawProfile::shape(double r) const { return coefficient_ * std::pow(r, exponent_); }

double PowerLawProfile::mdr_image(double x) const {
  return image_coefficient_ * std::pow(x, exponent_);
}

double PowerLawProfile::mdr_image_slope(double x) const {
  return image_coefficient_ * exponent_ * std::pow(x, exponent_ - 1.0);
}

double PowerLawProfile::contact_radius_at_depth(double depth) const {
  return depth > 0.0 ? std::pow(depth / image_coefficient_, 1.0 / exponent_) : 0.0;
}

// 2 integral_0^a k (a^n - x^n) dx = 2 k a^(n+1) n/(n + 1), k = kappa(n) c.
double PowerLawProfile::nonadhesive_force_per_modulus(double a) const {
  return 2.0 * image_coefficient_ * std::pow(a, exponent_ + 1.0) * exponent_ / (exponent_ + 1.0);
}

}  // namespace mdrsim
