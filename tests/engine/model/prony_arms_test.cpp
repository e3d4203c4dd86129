// One spring's Maxwell arms against closed forms, and its let-go under unloading against Ting's
// condition from the independent reference (tests/support/lee_radok).
#include "engine/model/prony_arms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "tests/support/lee_radok.hpp"

namespace mdrsim {
namespace {

constexpr PronyTerm kArm{9.0e6, 0.1};

// From rest at a constant rate: sigma = E r tau (1 - exp(-t / tau)); held: sigma0 exp(-t / tau);
// two steps compose to one (the update is the exact flow). 1e-15 relative: a few roundings
// (1 - exp(-t / tau) by expm1 in the expected value too: the difference loses digits at t << tau).
TEST(PronyArms, ExactUpdate) {
  const double rate = 2e-4;
  for (const double t : {1e-9, 1e-3, 0.1, 1.0, 30.0}) {
    const double expected = kArm.modulus * rate * kArm.time * -std::expm1(-t / kArm.time);
    EXPECT_NEAR(maxwell_arm_after(0.0, kArm, rate, t), expected, 1e-15 * expected) << t;
    EXPECT_NEAR(maxwell_arm_after(5.0, kArm, 0.0, t), 5.0 * std::exp(-t / kArm.time), 1e-15 * 5.0)
        << t;
  }
  const double once = maxwell_arm_after(3.0, kArm, -rate, 0.37);
  const double twice =
      maxwell_arm_after(maxwell_arm_after(3.0, kArm, -rate, 0.12), kArm, -rate, 0.25);
  EXPECT_NEAR(once, twice, 1e-14 * std::abs(once));
}

// The line load as an exponential sum equals the updated spring at every s.
TEST(PronyArms, LineLoadOverAMotion) {
  const std::vector<PronyTerm> terms{kArm, {2.0e6, 3.0}};
  std::vector<double> stresses{120.0, -40.0};
  const double relaxed = 1.0e6, stretch = 3e-5, rate = -1e-4;
  const ExponentialSum load = line_load_over(relaxed, terms, stretch, stresses, rate);
  for (const double s : {0.0, 0.05, 0.3, 2.0}) {
    std::vector<double> after = stresses;
    advance_arms(after, terms, rate, s);
    const double expected = relaxed * (stretch + rate * s) + after[0] + after[1];
    EXPECT_NEAR(load.at(s), expected, 1e-12 * std::abs(expected)) << s;
  }
}

// A spring of the MDR row under a parabola pressed at V to t_m and withdrawn: touched at t_in =
// x^2 / (R V), its load falls to zero at the t where Ting's psi(t - t_in) = 2 psi(t - t_m), that
// is where the reference's matching time is t_in. The let-go found by the root of the spring's
// own exponential sum agrees to 1e-12 relative (both roots to a few ulps; Ting's through
// psi's differences, which lose about 1e-13 near separation).
TEST(PronyArms, LetGoMeetsTingsCondition) {
  const test::StandardLinearSolid solid{1.0e6, kArm.modulus, kArm.time};
  const test::ParabolaRamp ramp{0.01, 1.0e-4, 0.2};
  const std::vector<PronyTerm> terms{kArm};
  for (const double entry : {0.0, 0.02, 0.1, 0.15, 0.19}) {
    std::vector<double> stresses{0.0};
    const double pressed = ramp.turn_time - entry;
    advance_arms(stresses, terms, ramp.speed, pressed);
    const ExponentialSum load =
        line_load_over(solid.relaxed_modulus, terms, ramp.speed * pressed, stresses, -ramp.speed);
    const auto s = first_crossing(load, 0.0, 10.0 * ramp.turn_time);
    ASSERT_TRUE(s.has_value()) << entry;
    const double let_go = ramp.turn_time + *s;
    EXPECT_NEAR(test::ting_matching_time(solid, ramp, let_go), entry, 1e-12 * ramp.turn_time)
        << entry;
  }
  // The first spring (touched at 0) leaves last, when the contact is lost.
  std::vector<double> stresses{0.0};
  advance_arms(stresses, terms, ramp.speed, ramp.turn_time);
  const auto s = first_crossing(line_load_over(solid.relaxed_modulus, terms,
                                               ramp.speed * ramp.turn_time, stresses, -ramp.speed),
                                0.0, 10.0 * ramp.turn_time);
  ASSERT_TRUE(s.has_value());
  const double separation = test::ting_separation_time(solid, ramp);
  EXPECT_NEAR(ramp.turn_time + *s, separation, 1e-13 * separation);
}

}  // namespace
}  // namespace mdrsim
