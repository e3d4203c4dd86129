// The power law's closed forms (Hess's MDR image of r^n).
#include "profiles/power_law_profile.hpp"

#include <algorithm>
#include <boost/math/special_functions/beta.hpp>
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
  // cos^n(psi) = sum_j p_j psi^(2j) by J.C.P. Miller's recurrence for a power of the series
  // cos = sum_j (-1)^j psi^(2j)/(2j)!; then H(t) = sum_j p_j t^(2j+1)/(2j+1) and, as
  // t cos^n t = sum_j p_j t^(2j+1), G(t) = -sum_j p_j (2j/(2j+1)) t^(2j+1) without its j = 0
  // terms that cancel.
  std::array<double, kZoneSeriesTerms> cosine{}, power{};
  cosine[0] = power[0] = 1.0;
  for (int j = 1; j < kZoneSeriesTerms; ++j) {
    cosine[j] = -cosine[j - 1] / ((2.0 * j - 1.0) * (2.0 * j));
  }
  for (int k = 1; k < kZoneSeriesTerms; ++k) {
    double sum = 0.0;
    for (int j = 1; j <= k; ++j) sum += ((exponent + 1.0) * j - k) * cosine[j] * power[k - j];
    power[k] = sum / k;
  }
  for (int j = 0; j < kZoneSeriesTerms; ++j) {
    cosine_power_integral_[j] = power[j] / (2.0 * j + 1.0);
    cosine_power_excess_[j] = -power[j] * (2.0 * j) / (2.0 * j + 1.0);
  }
  // About t = pi/2, w = pi/2 - t: cos^n t = sin^n w = w^n (sin w/w)^n, the same recurrence on
  // sin w/w = sum_j (-1)^j w^(2j)/(2j+1)!, and int_t^(pi/2) cos^n = sum_j q_j w^(n+2j+1)/(n+2j+1).
  std::array<double, kZoneSeriesTerms> sinc{};
  sinc[0] = sine_power_[0] = 1.0;
  for (int j = 1; j < kZoneSeriesTerms; ++j) {
    sinc[j] = -sinc[j - 1] / ((2.0 * j) * (2.0 * j + 1.0));
  }
  for (int k = 1; k < kZoneSeriesTerms; ++k) {
    double sum = 0.0;
    for (int j = 1; j <= k; ++j) sum += ((exponent + 1.0) * j - k) * sinc[j] * sine_power_[k - j];
    sine_power_[k] = sum / k;
  }
  for (int j = 0; j < kZoneSeriesTerms; ++j) {
    sine_power_integral_[j] = sine_power_[j] / (exponent + 2.0 * j + 1.0);
  }
  // Each series converges geometrically, its terms falling like (t/(pi/2))^(2j) and (w/pi)^(2j)
  // (cos^n's zero at pi/2, sin^n's at pi): t, w <= 0.75 and 1.5 keep 40 terms below 1e-25. The
  // terms alternate like those of exp(-n t^2/2) and exp(-n w^2/6), whose magnitudes sum to e^2
  // times their sum where n t^2 = 2 and n w^2 = 6: about 7 ulps at most. Both ranges cover
  // (0, pi/2) for n up to about 6; beyond, the incomplete beta function takes the gap.
  thin_zone_angle_ = std::min(0.75, std::sqrt(2.0 / exponent));
  wide_zone_width_ = std::min(1.5, std::sqrt(6.0 / exponent));
  // The terms each bin of angles needs: one past the last whose magnitude at the bin's top
  // exceeds 2^-56 of its series' sum there (the terms fall geometrically beyond it).
  const auto terms_needed = [](const auto& series, double x) {
    int needed = 1;
    for (const auto* coefficients : series) {
      double sum = 0.0, power = 1.0;
      for (int j = 0; j < kZoneSeriesTerms; ++j, power *= x * x) sum += (*coefficients)[j] * power;
      power = 1.0;
      for (int j = 0; j < kZoneSeriesTerms; ++j, power *= x * x) {
        if (std::abs((*coefficients)[j] * power) > 0x1p-56 * std::abs(sum)) needed = j + 1;
      }
    }
    return needed;
  };
  const std::array thin = {&cosine_power_integral_, &cosine_power_excess_};
  const std::array wide = {&sine_power_, &sine_power_integral_};
  for (int b = 0; b < kZoneBins; ++b) {
    thin_zone_terms_[b] = terms_needed(thin, thin_zone_angle_ * (b + 1) / kZoneBins);
    wide_zone_terms_[b] = terms_needed(wide, wide_zone_width_ * (b + 1) / kZoneBins);
  }
  half_beta_ = 0.5 * boost::math::beta(0.5, 0.5 * (exponent + 1.0));
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

// J = int_a^c k (x^n - a^n)/sqrt(c^2 - x^2) dx = k c^n int_0^t (cos^n psi - cos^n t) dpsi in
// x = c cos(psi), a = c cos(t): k c^n (H - t cos^n t), and dJ/dt at fixed a = tan(t) int_a^c
// x g'(x)/sqrt(c^2 - x^2) dx = k n c^n tan(t) H. H = int_0^t cos^n = int_0^(sin^2 t) (1 -
// v)^((n-1)/2) v^(-1/2) dv/2 = (B/2) I_(sin^2 t)(1/2, (n+1)/2). H - t cos^n t loses 3/(n t^2)
// of its digits (H ~ t, G ~ n t^3/3): where the zone is thin the series in t give both without
// that loss; where it is wide, H(pi/2) less the series in w = pi/2 - t (about ten ulps lost
// where t = 0.75 and n is 1/2). The incomplete beta function, ten times dearer than a series,
// takes only the angles that neither series covers (n > 6).
DugdaleGap PowerLawProfile::dugdale_gap(double /*a*/, double c, double t) const {
  const double n = exponent_;
  const double scale = image_coefficient_ * std::pow(c, n);
  double integral = 0.0, excess = 0.0;
  // pi/2 - t in two parts, so that w keeps its digits where t is close to pi/2.
  constexpr double kHalfPiHigh = 1.5707963267948966;
  constexpr double kHalfPiLow = 6.123233995736766e-17;
  const double w = (kHalfPiHigh - t) + kHalfPiLow;
  if (t <= thin_zone_angle_) {
    const double t2 = t * t;
    const int terms = thin_zone_terms_[std::min(
        kZoneBins - 1, static_cast<int>(t * (kZoneBins / thin_zone_angle_)))];
    for (int j = terms - 1; j >= 0; --j) {
      integral = integral * t2 + cosine_power_integral_[j];
      excess = excess * t2 + cosine_power_excess_[j];
    }
    integral *= t;
    excess *= t;
  } else if (w <= wide_zone_width_) {
    const double w2 = w * w;
    double power = 0.0, tail = 0.0;
    const int terms = wide_zone_terms_[std::min(
        kZoneBins - 1, static_cast<int>(w * (kZoneBins / wide_zone_width_)))];
    for (int j = terms - 1; j >= 0; --j) {
      power = power * w2 + sine_power_[j];
      tail = tail * w2 + sine_power_integral_[j];
    }
    const double w_n = std::pow(w, n);
    integral = half_beta_ - w_n * w * tail;
    excess = integral - t * w_n * power;
  } else {
    const double sin_t = std::sin(t);
    // In double: Boost's default promotes to long double, 10 times slower (1-6 us a call).
    const auto in_double =
        boost::math::policies::make_policy(boost::math::policies::promote_double<false>());
    integral = half_beta_ * boost::math::ibeta(0.5, 0.5 * (n + 1.0), sin_t * sin_t, in_double);
    excess = integral - t * std::pow(std::cos(t), n);
  }
  return {.integral = scale * excess, .angle_slope = n * scale * std::tan(t) * integral};
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
