// A Maxwell arm's integrals over a piece, accurate for short pieces.
#include "engine/model/decay_integrals.hpp"

#include <array>
#include <cmath>
#include <cstddef>

namespace mdrsim {
namespace {

/// Below it the rise's integrals are summed from their series: at x < 1 the terms fall at least
/// as 2^n / n!, 24 of them reach below 1e-17 of the first.
constexpr double kSeriesBelow = 1.0;
constexpr int kSeriesTerms = 26;
/// A term below this share of the sum changes none of its bits.
constexpr double kLastBit = 0x1p-54;

/// 1 / n for the series' terms: a product where a division per term would stall each step.
constexpr std::array<double, kSeriesTerms> kInverses = [] {
  std::array<double, kSeriesTerms> inverses{};
  for (int n = 1; n < kSeriesTerms; ++n) inverses[static_cast<std::size_t>(n)] = 1.0 / n;
  return inverses;
}();

/// x - 1 + exp(-x) = sum_{n >= 2} (-x)^n / n!.
double rise_series(double x) {
  double term = x * x / 2.0;  // (-x)^2 / 2!
  double sum = term;
  for (int n = 3; n < kSeriesTerms; ++n) {
    term *= -x * kInverses[static_cast<std::size_t>(n)];
    sum += term;
    // The terms fall from here on (n > x): one below the sum's last bit ends it.
    if (std::abs(term) <= kLastBit * std::abs(sum)) break;
  }
  return sum;
}

/// x - 2 (1 - exp(-x)) + (1 - exp(-2x)) / 2 = sum_{n >= 3} (-1)^(n+1) (2^(n-1) - 2) x^n / n!.
double rise_squared_series(double x) {
  double power = x * x / 2.0;  // x^n / n! at n = 2
  double two = 2.0;            // 2^(n-1) at n = 2
  double sum = 0.0;
  for (int n = 3; n < kSeriesTerms; ++n) {
    power *= x * kInverses[static_cast<std::size_t>(n)];
    two *= 2.0;
    const double term = (two - 2.0) * power;
    sum += (n % 2 == 1) ? term : -term;
    if (term <= kLastBit * std::abs(sum)) break;
  }
  return sum;
}

}  // namespace

double relaxed_part_long(double x) { return -std::expm1(-x); }

DecayIntegrals decay_integrals(double h, double tau) {
  return decay_integrals(h, tau, relaxed_part(h / tau));
}

DecayIntegrals decay_integrals_long(double h, double tau, double fall) {
  const double x = h / tau;
  DecayIntegrals i{};
  i.decay = tau * fall;
  // 1 - exp(-2x) = (1 - exp(-x)) (1 + exp(-x)): from `fall` to a few eps, with no second call.
  const double fall_twice = fall * (2.0 - fall);
  i.decay_squared = fall_twice * tau * 0.5;
  i.rise_decay = tau * fall * fall * 0.5;
  if (x < kSeriesBelow) {
    i.rise = tau * rise_series(x);
    i.rise_squared = tau * rise_squared_series(x);
  } else {
    i.rise = tau * (x - fall);
    i.rise_squared = tau * (x - 2.0 * fall + fall_twice * 0.5);
  }
  return i;
}

ArmStressIntegrals arm_stress_integrals(const DecayIntegrals& i, double sigma0, double steady) {
  return {sigma0 * i.decay + steady * i.rise,
          sigma0 * sigma0 * i.decay_squared + 2.0 * sigma0 * steady * i.rise_decay +
              steady * steady * i.rise_squared,
          sigma0 * i.decay_squared + steady * i.rise_decay};
}

}  // namespace mdrsim
