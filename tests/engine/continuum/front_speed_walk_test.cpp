// The rate-law front's walk on the continuum branch of a parabola under fixed grips, from JKR's
// zero-force state, against the independent solution of tests/support/rate_law_front: the peak
// tension, the loss of contact, the dissipation and the energy balance.
#include "engine/continuum/front_speed_walk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "controllers/builtin_controllers.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "profiles/parabolic_profile.hpp"
#include "tests/support/rate_law_front.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.01;      // R [m]
constexpr double kWork = 0.05;        // dgamma [J/m^2]
constexpr double kFrontSpeed = 1e-6;  // v* [m/s]

struct FrontSpeedCase {
  Material material = Material::from_youngs_modulus(1e6, 0.5, kWork);
  ParabolicProfile profile{kRadius};
  ModeMixedCriterion criterion{material};
  ContinuumBranch branch{profile,
                         criterion,
                         material,
                         FixedGripsController().constraint(),
                         FixedGripsController().constraint(),
                         0.0};
  test::RateLawScales scales =
      test::rate_law_scales(material.effective_modulus, kRadius, kWork, kFrontSpeed);

  /// JKR's zero-force state, retracted at beta (the grips' speed V = beta v* / (E* R /
  /// dgamma)^(1/3)) until the contact is lost.
  FrontSpeedStart start(double beta) const {
    const double a0 = std::cbrt(4.5 * kPi * kWork * kRadius * kRadius / material.effective_modulus);
    const double e0 = std::sqrt(2.0 * kPi * a0 * kWork / material.effective_modulus);
    const double speed =
        beta * kFrontSpeed / std::cbrt(material.effective_modulus * kRadius / kWork);
    return {a0, a0 * a0 / kRadius - e0, 0.0, -speed, std::numeric_limits<double>::infinity()};
  }
};

// The peak tension, the time and indentation of the lost contact and the dissipation agree with
// the reference to 1e-8 (the walk asks rtol 1e-10 of its steps, the reference integrates its
// own dimensionless ODE at 1e-10: each within about 1e-9, compared at 1e-8).
TEST(FrontSpeedWalk, PeakAndLossAgreeWithTheReference) {
  const FrontSpeedCase c;
  for (const double n : {1.0, 0.5}) {
    for (const double beta : {1e-2, 0.1, 1.0, 10.0, 100.0}) {
      const FrontSpeedWalk w = walk_front_speed(c.branch, {kFrontSpeed, n}, c.start(beta), 1e-10);
      const test::RateLawRetraction r = test::rate_law_retraction(beta, n, 1e-10);
      ASSERT_TRUE(w.peak) << beta;
      ASSERT_TRUE(w.lost) << beta;
      const double peak = r.peak.force * c.scales.force;
      EXPECT_NEAR(w.peak->normal_force / peak, 1.0, 1e-8) << "beta " << beta << " n " << n;
      EXPECT_NEAR(w.peak_time / (r.peak.tau * c.scales.time), 1.0, 1e-6) << beta << " " << n;
      EXPECT_NEAR(w.end_time / (r.lost.tau * c.scales.time), 1.0, 1e-8) << beta << " " << n;
      EXPECT_NEAR(w.end.indentation / (r.lost.delta * c.scales.indentation), 1.0, 1e-8)
          << beta << " " << n;
      EXPECT_NEAR(w.dissipated / (r.lost.dissipated * c.scales.energy), 1.0, 1e-8)
          << beta << " " << n;
      EXPECT_NEAR(w.machine_work / (r.lost.machine_work * c.scales.energy), 1.0, 1e-8)
          << beta << " " << n;
      // The walk's own estimate is honest: within it of the reference (to 1e-9 of the peak).
      EXPECT_LE(std::abs(w.peak->normal_force - peak), w.peak_error + 1e-9 * std::abs(peak));
    }
  }
}

// Machine work = stored energy change + adhesion energy change + dissipation at the front, the
// stored energy E* int_0^a (d - x^2 / R)^2 dx in closed form: to 1e-9 of the stored energy at
// the start (the walk's tolerance 1e-12 per step, summed).
TEST(FrontSpeedWalk, EnergyBalanceCloses) {
  const FrontSpeedCase c;
  const double modulus = c.material.effective_modulus;
  const auto stored = [&](double a, double d) {
    return modulus * (d * d * a - 2.0 * d * a * a * a / (3.0 * kRadius) +
                      std::pow(a, 5) / (5.0 * kRadius * kRadius));
  };
  for (const double beta : {0.1, 10.0}) {
    const FrontSpeedStart s = c.start(beta);
    const FrontSpeedWalk w = walk_front_speed(c.branch, {kFrontSpeed, 0.5}, s, 1e-10);
    const double stored_change =
        stored(w.end.contact_radius, w.end.indentation) - stored(s.radius, s.indentation);
    const double surface_change =
        -kPi * kWork * (w.end.contact_radius * w.end.contact_radius - s.radius * s.radius);
    const double balance = w.machine_work - stored_change - surface_change - w.dissipated;
    EXPECT_NEAR(balance / stored(s.radius, s.indentation), 0.0, 1e-9) << beta;
  }
}

// A stage that ends while the front runs stops at its end time, with the contact kept; a hold
// (no grip motion) from a state above the threshold lets the front recede towards G = dgamma.
TEST(FrontSpeedWalk, EndsAtTheStagesEndAndRecedesInAHold) {
  const FrontSpeedCase c;
  FrontSpeedStart s = c.start(1.0);
  const FrontSpeedWalk full = walk_front_speed(c.branch, {kFrontSpeed, 1.0}, s, 1e-10);
  s.end_time = 0.5 * full.end_time;
  const FrontSpeedWalk half = walk_front_speed(c.branch, {kFrontSpeed, 1.0}, s, 1e-10);
  EXPECT_FALSE(half.lost);
  EXPECT_EQ(half.end_time, s.end_time);
  EXPECT_NEAR(half.end.indentation, s.indentation + s.rate * s.end_time,
              1e-12 * std::abs(s.indentation));
  EXPECT_GT(half.end.contact_radius, 0.0);

  // The hold: from there, the grips at rest for a long time; G / dgamma falls to 1.
  const FrontSpeedStart hold{half.end.contact_radius, half.end.indentation, half.end_time, 0.0,
                             half.end_time + 1e4 * c.scales.time};
  const FrontSpeedWalk held = walk_front_speed(c.branch, {kFrontSpeed, 1.0}, hold, 1e-10);
  EXPECT_FALSE(held.lost);
  EXPECT_LT(held.end.contact_radius, hold.radius);
  const double e = held.end.stretch;
  const double ratio =
      c.material.effective_modulus * e * e / (2.0 * kPi * held.end.contact_radius * kWork);
  EXPECT_NEAR(ratio, 1.0, 1e-3);  // n = 1: G - dgamma decays exponentially in t v* / L
  EXPECT_EQ(held.machine_work, 0.0);
}

}  // namespace
}  // namespace mdrsim
