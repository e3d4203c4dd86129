// Approach and retract fitted together: a synthetic JKR loop (the approach forming its contact
// with a smaller work of adhesion than the retract peels it with) recovered, and the hysteresis
// energy against the loop's closed-form area.
#include "engine/fit/combined_fit.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "engine/fit/prepared_curve.hpp"
#include "engine/fit/tip_shape.hpp"

namespace mdrsim::fit {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 5e-6;  // [m]
constexpr double kModulus = 1e6;  // [Pa]
constexpr double kNu = 0.5;
constexpr double kWork = 0.02;       // [J/m^2] retract
constexpr double kApproach = 0.006;  // [J/m^2] approach: 0.3 of the retract's
constexpr double kContact = 3e-6;    // [m]

/// JKR 1971 for the paraboloid at contact radius a: delta = a^2/R - sqrt(2 pi a w / E*),
/// F = 4 E* a^3 / (3 R) - sqrt(8 pi w E* a^3).
double jkr_depth(double e, double w, double a) {
  return a * a / kRadius - std::sqrt(2 * kPi * a * w / e);
}
double jkr_force(double e, double w, double a) {
  return 4 * e * a * a * a / (3 * kRadius) - std::sqrt(8 * kPi * w * e * a * a * a);
}
/// The integral of F d(delta) along the branch from radius 0 to a: with k = sqrt(2 pi w / E*)
/// and s = sqrt(8 pi w E*), F delta'(a) = 8 E* a^4 / (3 R^2) - (2 E* k / (3 R) + 2 s / R)
/// a^(5/2) + 2 pi w a (s k = 4 pi w), whose primitive this is.
double jkr_work(double e, double w, double a) {
  const double k = std::sqrt(2 * kPi * w / e), s = std::sqrt(8 * kPi * w * e);
  return 8 * e * std::pow(a, 5) / (15 * kRadius * kRadius) -
         (2 * e * k / (3 * kRadius) + 2 * s / kRadius) * 2.0 / 7.0 * std::pow(a, 3.5) +
         kPi * w * a * a;
}
/// The stable branch's radius at depth d, by bisection above the fixed-grips end
/// a*^3 = pi w R^2 / (8 E*).
double jkr_radius(double e, double w, double d) {
  double lo = std::cbrt(kPi * w * kRadius * kRadius / (8 * e)), hi = 2 * lo;
  while (jkr_depth(e, w, hi) < d) hi *= 2;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (jkr_depth(e, w, mid) < d ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Loop {
  PreparedSegment approach, retract;
  double depth = 0;       // [m] the largest indentation
  double hysteresis = 0;  // [J] the closed-form area of the noise-free loop
};

/// 2000 samples each way between half the largest indentation above contact and the largest
/// indentation (where the retract's force is six of its pull-off forces), a tilted baseline
/// and Gaussian noise of `noise` x the largest force. The approach joins its branch (w_a) at
/// depth 0 (the snap-in at fixed depth: no area); the retract leaves its branch (w) at the
/// radius half way between the fixed-load pull-off, a^3 = 9 pi w R^2 / (8 E*), and the
/// fixed-grips end, a^3 = pi w R^2 / (8 E*).
Loop loop(unsigned seed, double noise) {
  const double e = kModulus / (1 - kNu * kNu);
  const double pull = 1.5 * kPi * kWork * kRadius;
  const double a_load = std::cbrt(9 * kPi * kWork * kRadius * kRadius / (8 * e));
  const double a_end = std::cbrt(kPi * kWork * kRadius * kRadius / (8 * e));
  const double a_leave = 0.5 * (a_load + a_end);
  const double leave_depth = jkr_depth(e, kWork, a_leave);
  Loop out;
  double lo = 0, hi = 1e-9;
  while (jkr_force(e, kWork, jkr_radius(e, kWork, hi)) < 6 * pull) hi *= 2;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (jkr_force(e, kWork, jkr_radius(e, kWork, mid)) < 6 * pull ? lo : hi) = mid;
  }
  out.depth = 0.5 * (lo + hi);
  const double peak = 6 * pull;
  const double offset = 0.1 * peak, slope = 0.05 * peak / out.depth;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gauss(0.0, noise * peak);
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    const double in = out.depth * (1.5 * t - 0.5);
    const double back = out.depth * (1 - 1.5 * t);
    double fa = offset + slope * -in, fr = offset + slope * -back;
    if (in > 0) fa += jkr_force(e, kApproach, jkr_radius(e, kApproach, in));
    if (back > leave_depth) fr += jkr_force(e, kWork, jkr_radius(e, kWork, back));
    out.approach.tip_position.push_back(kContact - in);
    out.approach.force.push_back(fa + gauss(random));
    out.retract.tip_position.push_back(kContact - back);
    out.retract.force.push_back(fr + gauss(random));
  }
  // The loop: in along the approach's branch from depth 0 to the deepest, out along the
  // retract's from there to where it leaves.
  const double a_zero = std::cbrt(std::pow(std::sqrt(2 * kPi * kApproach / e) * kRadius, 2));
  out.hysteresis =
      jkr_work(e, kApproach, jkr_radius(e, kApproach, out.depth)) - jkr_work(e, kApproach, a_zero) -
      (jkr_work(e, kWork, jkr_radius(e, kWork, out.depth)) - jkr_work(e, kWork, a_leave));
  return out;
}

CombinedFitOptions jkr_options() {
  CombinedFitOptions options;
  options.model = AdhesionModel::jkr;
  options.tip = parse_tip("parabolic:radius=5e-6");
  options.poisson_ratio = kNu;
  return options;
}

// 20 seeds: E within 2 %, both works of adhesion within 3 % (the tolerances), the
// contact point within 1 % of the largest indentation. The noise is 0.5 % of the largest force:
// the approach's adhesion is 0.3 of the retract's, and at the 1 % of the one-segment tests the
// standard error of w_a alone is 1.8 % (its worst of 20 seeds 5.8 %, 3.2 of them), which no
// fit can bring under 3 %.
TEST(CombinedFit, RecoversJkrApproachAndRetractWorks) {
  double worst_e = 0, worst_w = 0, worst_wa = 0, worst_c = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const Loop s = loop(seed, 0.005);
    const CombinedFit fit = fit_combined(s.approach, s.retract, jkr_options());
    ASSERT_EQ(fit.status, FitStatus::fitted) << "seed " << seed << ": " << fit.message;
    worst_e = std::max(worst_e, std::abs(fit.youngs_modulus.value / kModulus - 1));
    worst_w = std::max(worst_w, std::abs(fit.work_of_adhesion.value / kWork - 1));
    worst_wa = std::max(worst_wa, std::abs(fit.approach_work_of_adhesion.value / kApproach - 1));
    worst_c = std::max(worst_c, std::abs(fit.contact_point.value - kContact) / s.depth);
    EXPECT_GT(fit.approach_work_of_adhesion.standard_error, 0.0);
    // Honest errors: each within 4 standard errors (a normal deviate passes 4 sigma once in
    // 16000; 60 draws here).
    EXPECT_LT(std::abs(fit.youngs_modulus.value - kModulus), 4 * fit.youngs_modulus.standard_error);
    EXPECT_LT(std::abs(fit.work_of_adhesion.value - kWork),
              4 * fit.work_of_adhesion.standard_error);
    EXPECT_LT(std::abs(fit.approach_work_of_adhesion.value - kApproach),
              4 * fit.approach_work_of_adhesion.standard_error);
  }
  std::printf(
      "both segments, jkr parabolic: worst |dE|/E = %.3f %%, |dw|/w = %.3f %%, |dw_a|/w_a = "
      "%.3f %%, |dc|/depth = %.3f %%\n",
      100 * worst_e, 100 * worst_w, 100 * worst_wa, 100 * worst_c);
  EXPECT_LT(worst_e, 0.02);
  EXPECT_LT(worst_w, 0.03);
  EXPECT_LT(worst_wa, 0.03);
  EXPECT_LT(worst_c, 0.01);
}

// Hertz on both segments has one modulus: a noise-free Hertz loop (w = 0 both ways) gives it.
TEST(CombinedFit, HertzHasOneModulusForBoth) {
  const double e = kModulus / (1 - kNu * kNu);
  Loop s;
  for (int i = 0; i < 1000; ++i) {
    const double d = 1e-7 * (1.5 * i / 999.0 - 0.5);
    const double f = d > 0 ? 4.0 / 3.0 * e * std::sqrt(kRadius) * std::pow(d, 1.5) : 0.0;
    s.approach.tip_position.push_back(kContact - d);
    s.approach.force.push_back(f);
    s.retract.tip_position.insert(s.retract.tip_position.begin(), kContact - d);
    s.retract.force.insert(s.retract.force.begin(), f);
  }
  CombinedFitOptions options;
  options.adhesive = false;
  options.tip = parse_tip("parabolic:radius=5e-6");
  options.poisson_ratio = kNu;
  const CombinedFit fit = fit_combined(s.approach, s.retract, options);
  ASSERT_EQ(fit.status, FitStatus::fitted) << fit.message;
  // Noise-free: the minimum is the truth to the minimiser's tolerance.
  EXPECT_NEAR(fit.youngs_modulus.value, kModulus, 1e-6 * kModulus);
  EXPECT_NEAR(fit.contact_point.value, kContact, 1e-12);
  EXPECT_EQ(fit.points, 2000U);
  EXPECT_EQ(fit.approach_work_of_adhesion.value, 0.0);
}

// The trapezoid on the noise-free loop against its closed-form area: 2000 samples over 1.5
// depths leave the trapezoid's error (the square of the step against the curvature) and the
// snap-off's half step below 0.5 %. With 1 % noise and the baseline estimated from the
// approach, within 3 %: the noise's sum over 4000 samples is ~ sqrt(4000) x 0.01 x peak x step.
TEST(CombinedFit, HysteresisEnergyIsTheLoopsArea) {
  const Loop clean = loop(1, 0.0);
  ASSERT_GT(clean.hysteresis, 0.0);
  const double pull = 1.5 * kPi * kWork * kRadius;
  const double slope = 0.05 * 6 * pull / clean.depth;
  const double offset = 0.1 * 6 * pull;
  const double exact = hysteresis_energy(clean.approach, clean.retract, kContact, offset, slope);
  std::printf("hysteresis: closed form %.6e J, trapezoid %.6e J (%.4f %%)\n", clean.hysteresis,
              exact, 100 * (exact / clean.hysteresis - 1));
  EXPECT_NEAR(exact, clean.hysteresis, 5e-3 * clean.hysteresis);
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Loop noisy = loop(seed, 0.01);
    const FirstGuess guess = first_guess(noisy.approach, parse_tip("parabolic:radius=5e-6"), kNu);
    const double energy = hysteresis_energy(noisy.approach, noisy.retract, guess.contact_point,
                                            guess.baseline_offset, guess.baseline_slope);
    std::printf("hysteresis with 1 %% noise, seed %u: %.4f %%\n", seed,
                100 * (energy / clean.hysteresis - 1));
    EXPECT_NEAR(energy, clean.hysteresis, 3e-2 * clean.hysteresis) << "seed " << seed;
  }
}

}  // namespace
}  // namespace mdrsim::fit
