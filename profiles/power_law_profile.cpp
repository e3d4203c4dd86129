// The power law's closed forms (Hess's MDR image of r^n).
#include "profiles/power_law_profile.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

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

// int_0^a (d - k x^n)^2 dx = d^2 a - 2 d k a^(n+1)/(n+1) + k^2 a^(2n+1)/(2n+1), from g(a) =
// k a^n: each term a few ulps off, so their magnitudes' sum bounds the rounding.
std::optional<ExactIntegral> PowerLawProfile::squared_gap_integral(double a, double d) const {
  if (!(a > 0.0)) return ExactIntegral{0.0, 0.0};
  const double edge = mdr_image(a);
  const double square = d * d * a;
  const double cross = 2.0 * d * edge * a / (exponent_ + 1.0);
  const double image = edge * edge * a / (2.0 * exponent_ + 1.0);
  return ExactIntegral{square - cross + image,
                       std::abs(square) + std::abs(cross) + std::abs(image)};
}

// JKR in MDR (paper eqs. 14-15 for any image): the boundary spring lets go at the stretch
// dl(a) = sqrt(w a), w = 2 pi dgamma/E*, so along the pull-off branch d = k a^n - sqrt(w a) and
// F = 2 E* (a d - integral_0^a k x^n dx) = 2 E* k n a^(n+1)/(n+1) - 2 E* sqrt(w) a^(3/2).
// Under fixed load the contact jumps off at the minimum of F(a): dF/da = 0 gives
// 2 k n a^(n-1/2) = 3 sqrt(w), a minimum for n > 1/2. There sqrt(w a) = (2 k n/3) a^n, so
// F0 = -F = 2 E* k n (2n - 1) a0^(n+1)/(3(n + 1)) and d = k a0^n (3 - 2n)/3. d0 = k a0^n/3
// equals |d| for the cone (n = 1) and the parabola (n = 2, k = 1/R: eq. 17); at n = 3/2 the
// critical d is 0, so |d| cannot be the scale. Logarithms keep extreme values in range.
std::optional<PullOffScales> PowerLawProfile::pull_off_scales_of(double k, double n,
                                                                 double effective_modulus,
                                                                 double work_of_adhesion,
                                                                 std::string basis) {
  if (!(n > 0.5) || !(work_of_adhesion > 0.0) || !(effective_modulus > 0.0) || !(k > 0.0)) {
    return std::nullopt;
  }
  const double log_w =
      std::log(2.0 * std::numbers::pi) + std::log(work_of_adhesion) - std::log(effective_modulus);
  const double log_a0 =
      (std::log(1.5) + 0.5 * log_w - std::log(k) - std::log(n)) * 2.0 / (2.0 * n - 1.0);
  const double scales[] = {std::exp(std::log(2.0 * n * (2.0 * n - 1.0) / (3.0 * (n + 1.0))) +
                                    std::log(effective_modulus) + std::log(k) + (n + 1.0) * log_a0),
                           std::exp(log_a0), std::exp(std::log(k) + n * log_a0 - std::log(3.0))};
  for (const double s : scales) {
    if (!(s > 0.0) || !std::isfinite(s)) return std::nullopt;
  }
  return PullOffScales{scales[0], scales[1], scales[2], std::move(basis)};
}

std::optional<PullOffScales> PowerLawProfile::pull_off_scales(double effective_modulus,
                                                              double work_of_adhesion) const {
  return pull_off_scales_of(
      image_coefficient_, exponent_, effective_modulus, work_of_adhesion,
      "power_law: the fixed-load pull-off of g = k x^n, k = kappa(n) c: a0 = (3 sqrt(2 pi "
      "dgamma/E*)/(2 k n))^(2/(2n-1)), F0 = 2 E* k n (2n-1) a0^(n+1)/(3(n+1)), d0 = k a0^n/3");
}

}  // namespace mdrsim
