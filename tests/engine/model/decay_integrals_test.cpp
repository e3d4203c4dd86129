// A Maxwell arm's integrals over a piece (decay_integrals) against Romberg quadrature in long
// double of their integrands, E = exp(-s/tau) and D = -expm1(-s/tau), at h/tau from 1e-12 to 10.
#include "engine/model/decay_integrals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace mdrsim {
namespace {

/// Romberg's extrapolation of the trapezoid rule over [0, h], to 20 halvings: the integrands are
/// entire, so it converges geometrically, to the long double's ~1e-19 well within them.
long double romberg(const std::function<long double(long double)>& f, long double h) {
  std::vector<long double> previous{0.5L * h * (f(0.0L) + f(h))};
  for (int level = 1; level <= 20; ++level) {
    const long double panels = std::ldexp(1.0L, level);
    const long double step = h / panels;
    long double midpoints = 0.0L;
    for (long double i = 1.0L; i < panels; i += 2.0L) midpoints += f(i * step);
    std::vector<long double> row{0.5L * previous[0] + step * midpoints};
    long double factor = 1.0L;
    for (int k = 1; k <= level; ++k) {
      factor *= 4.0L;
      row.push_back(row[k - 1] + (row[k - 1] - previous[k - 1]) / (factor - 1.0L));
    }
    const bool settled =
        level > 4 && std::fabs(row.back() - previous.back()) <= 1e-18L * std::fabs(row.back());
    previous = row;
    if (settled) break;
  }
  return previous.back();
}

TEST(DecayIntegrals, KeepTheirDigitsFromLongToVeryShortPieces) {
  // tau = 0.1 s; each integral within 1e-15 of the quadrature's (its own rounding is a few eps:
  // the series near h/tau = 1 alternates over terms 2x the sum). Differences of O(1) terms
  // left eps tau / h of the rise's integrals: 1e-4 of them at h/tau = 1e-12.
  const long double tau = 0.1L;
  // 2^-7 (0.0078125) parts the short pieces' polynomials from the series and closed forms.
  for (const double x : {1e-12, 1e-9, 1e-6, 1e-4, 1e-3, 0.0078, 0.0078125, 0.0079, 1e-2, 0.1, 0.5,
                         0.999, 1.0, 1.001, 3.0, 10.0}) {
    const double h = x * 0.1;
    const DecayIntegrals got = decay_integrals(h, 0.1);
    const auto e = [&](long double s) { return std::exp(-s / tau); };
    const auto d = [&](long double s) { return -std::expm1(-s / tau); };
    const long double hl = h;
    const long double want[] = {
        romberg(e, hl), romberg([&](long double s) { return e(s) * e(s); }, hl), romberg(d, hl),
        romberg([&](long double s) { return d(s) * e(s); }, hl),
        romberg([&](long double s) { return d(s) * d(s); }, hl)};
    const double have[] = {got.decay, got.decay_squared, got.rise, got.rise_decay,
                           got.rise_squared};
    const char* names[] = {"decay", "decay_squared", "rise", "rise_decay", "rise_squared"};
    for (int i = 0; i < 5; ++i) {
      const long double error = std::fabs((have[i] - want[i]) / want[i]);
      EXPECT_LT(error, 1e-15L) << names[i] << " at h/tau = " << x;
    }
  }
}

// 1 - exp(-x) by relaxed_part (a Taylor polynomial below 2^-7, expm1 above) against long
// double's expm1, within 2 ulp (the polynomial's Horner rounding and its truncation, below
// 2^-53 of the sum), across the boundary and from 1e-15 to 30.
TEST(DecayIntegrals, RelaxedPartToTwoUlpAcrossTheShortPiecesBoundary) {
  for (const double x : {1e-15, 1e-9, 1e-5, 1e-3, 0.004, 0.0078, 0.00781249, 0.0078125, 0.0079,
                         0.05, 0.7, 3.0, 30.0}) {
    const long double want = -std::expm1(-static_cast<long double>(x));
    const double have = relaxed_part(x);
    EXPECT_LE(std::fabs(have - want), 2.0L * std::numeric_limits<double>::epsilon() * want) << x;
  }
}

TEST(DecayIntegrals, AnArmsStressIntegralsAreItsPartsCombined) {
  // sigma = sigma0 E + c D: int sigma, int sigma^2 and int sigma E by the integrals above, at
  // h/tau = 1e-8 (where a fresh arm driven fast, sigma0 = 0, keeps only its rise).
  const DecayIntegrals i = decay_integrals(1e-9, 0.1);
  const ArmStressIntegrals a = arm_stress_integrals(i, 3.0, -2.0e4);
  EXPECT_DOUBLE_EQ(a.stress, 3.0 * i.decay - 2.0e4 * i.rise);
  EXPECT_DOUBLE_EQ(a.square,
                   9.0 * i.decay_squared - 12.0e4 * i.rise_decay + 4.0e8 * i.rise_squared);
  EXPECT_DOUBLE_EQ(a.with_decay, 3.0 * i.decay_squared - 2.0e4 * i.rise_decay);
  const ArmStressIntegrals fresh = arm_stress_integrals(i, 0.0, 5.0);
  EXPECT_DOUBLE_EQ(fresh.stress, 5.0 * 0.1 * 0.5e-16 * (1.0 - 1e-8 / 3.0));
}

}  // namespace
}  // namespace mdrsim
