// The rate-law retraction's own solution (tests/support/rate_law_front) against its limits:
// the JKR start, JKR's fixed-grips path as beta -> 0, its growth with beta, its convergence in
// rtol and its energy balance. The engine's tests compare against it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tests/support/rate_law_front.hpp"

namespace mdrsim::test {
namespace {

constexpr double kPi = std::numbers::pi;

// U = int_0^alpha (delta - s^2)^2 ds and the adhesion energy -pi alpha^2, in dgamma L^2.
double stored_energy(const RateLawState& s) {
  const double a = s.alpha;
  const double d = s.delta;
  return d * d * a - 2.0 * d * a * a * a / 3.0 + std::pow(a, 5) / 5.0;
}
double adhesion_energy(const RateLawState& s) { return -kPi * s.alpha * s.alpha; }

TEST(RateLawReference, StartsAtJkrsZeroForceState) {
  const RateLawRetraction r = rate_law_retraction(1.0, 1.0, 1e-10);
  // F = 0 on the JKR branch: 4 E* a^3 / (3R) = sqrt(8 pi a^3 dgamma E*), a^3 = 9 pi dgamma R^2 /
  // (2 E*); rounding only.
  EXPECT_NEAR(r.start.force, 0.0, 1e-14);
  const double e = r.start.delta - r.start.alpha * r.start.alpha;
  EXPECT_NEAR(e * e / (2.0 * kPi * r.start.alpha), 1.0, 1e-14);
  EXPECT_NEAR(std::pow(r.start.alpha, 3), 4.5 * kPi, 1e-12);
}

TEST(RateLawReference, SlowLimitIsJkrsFixedGripsPath) {
  // The front lags JKR's branch by G / dgamma - 1 = (|da/dt| / v*)^n ~ beta^n: the peak and the
  // indentation where the contact is lost approach JKR's (-3 pi / 2 at a0; the pull-off at
  // d'(a) = 0, a_c^3 = pi R^2 dgamma / (8 E*)), the peak at the order n in beta.
  for (const double n : {1.0, 0.5}) {
    double previous_peak_error = 0.0;
    double previous_lost_error = 0.0;
    for (const double beta : {1e-3, 1e-4, 1e-5}) {
      const RateLawRetraction r = rate_law_retraction(beta, n, 1e-10);
      const double peak_error = r.peak.force - jkr_fixed_grips_peak_force();
      const double lost_error = std::abs(r.lost.delta - jkr_fixed_grips_pull_off_indentation());
      EXPECT_LT(peak_error, 0.0) << "beta " << beta << " n " << n;  // more tension than JKR's
      if (previous_peak_error != 0.0) {
        // The order from successive errors over a decade: n, within 0.1.
        EXPECT_NEAR(std::log10(previous_peak_error / peak_error), n, 0.1) << beta << " " << n;
        // The pull-off indentation: a slow passage through the fold at d'(a) = 0, where
        // G / dgamma - 1 ~ x^2 - c beta tau (x = a - a_c) and dx/dtau = -(G / dgamma - 1)^(1/n):
        // x^2 ~ beta tau and x / tau ~ x^(2/n) give the lag x ~ beta^(n/(n+2)) and the
        // indentation's beta^(2n/(n+2)) (2/3 for n = 1, the classic delay past a saddle-node).
        EXPECT_NEAR(std::log10(previous_lost_error / lost_error), 2.0 * n / (n + 2.0), 0.03)
            << beta << " " << n;
      }
      previous_peak_error = peak_error;
      previous_lost_error = lost_error;
    }
    // At beta = 1e-5 both within 1e-3 relative (n = 1) / 1e-2 (n = 1/2: the lag ~ beta^(1/2)).
    EXPECT_LT(std::abs(previous_peak_error), (n == 1.0 ? 1e-3 : 1e-2) * 1.5 * kPi);
  }
}

TEST(RateLawReference, PeakTensionGrowsWithBeta) {
  double previous = 0.0;
  for (const double beta : {1e-3, 1e-2, 1e-1, 1.0, 10.0, 100.0, 1000.0}) {
    const RateLawRetraction r = rate_law_retraction(beta, 0.5, 1e-10);
    EXPECT_LT(r.peak.force, previous) << beta;
    EXPECT_LT(r.peak.force, jkr_fixed_grips_peak_force()) << beta;
    previous = r.peak.force;
  }
}

TEST(RateLawReference, ConvergedToItsTolerance) {
  // rtol 1e-10 against 1e-13: the peak, the time and indentation of the lost contact and the
  // dissipation agree to 1e-9 (ten times the tolerance asked for the accumulated error).
  for (const double beta : {1e-2, 1.0, 100.0}) {
    for (const double n : {1.0, 0.5, 0.3}) {
      const RateLawRetraction coarse = rate_law_retraction(beta, n, 1e-10);
      const RateLawRetraction fine = rate_law_retraction(beta, n, 1e-13);
      EXPECT_NEAR(coarse.peak.force / fine.peak.force, 1.0, 1e-9) << beta << " " << n;
      EXPECT_NEAR(coarse.lost.tau / fine.lost.tau, 1.0, 1e-9) << beta << " " << n;
      EXPECT_NEAR(coarse.lost.dissipated / fine.lost.dissipated, 1.0, 1e-9) << beta << " " << n;
    }
  }
}

TEST(RateLawReference, EnergyBalanceCloses) {
  // Machine work = stored energy change + adhesion energy change + dissipation at the front, at
  // the peak and at the loss of contact; to 1e-9 of the initial stored energy (integrated at
  // rtol 1e-10).
  for (const double beta : {1e-2, 1.0, 100.0}) {
    const RateLawRetraction r = rate_law_retraction(beta, 0.5, 1e-10);
    const double scale = stored_energy(r.start);
    for (const RateLawState& s : {r.peak, r.lost}) {
      const double balance = s.machine_work - (stored_energy(s) - stored_energy(r.start)) -
                             (adhesion_energy(s) - adhesion_energy(r.start)) - s.dissipated;
      EXPECT_NEAR(balance / scale, 0.0, 1e-9) << beta;
    }
    EXPECT_GT(r.lost.dissipated, 0.0);
  }
}

}  // namespace
}  // namespace mdrsim::test
