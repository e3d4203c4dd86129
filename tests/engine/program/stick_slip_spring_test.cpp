// One spring that sticks and slips: event times, the slide following the limit, a glued limit.
#include "engine/program/stick_slip_spring.hpp"

#include <gtest/gtest.h>

namespace {

using mdrsim::FrictionEventKind;
using mdrsim::LinearMotion;
using mdrsim::SlipLimit;
using mdrsim::SpringGeometry;
using mdrsim::StickSlipSpring;

// kz = 2, kx = 1, g = 0 and mu = 0.5 throughout: at d = 1 the spring is pressed with f_z = 2
// and its limit is mu f_z = 1. Every event time below is the root of a linear function,
// derived by hand in the comment beside it; the tolerance is rounding (1e-15 of t ~ 1).
const SpringGeometry kSpring{2.0, 1.0, 0.0};
const SlipLimit kFriction{0.5, 0.0};
constexpr double kRounding = 1e-14;

TEST(StickSlipSpring, SticksUntilItsForceReachesTheLimit) {
  const StickSlipSpring state{0.0, 0};
  // f_x = kx u = t reaches the limit 1 at t = 1, along +x.
  const LinearMotion forward{0.0, 1.0, 0.0, 0.0, 1.0};
  const auto slip = mdrsim::next_friction_event(state, kFriction, kSpring, forward, 3.0);
  ASSERT_TRUE(slip);
  EXPECT_EQ(slip->kind, FrictionEventKind::slip);
  EXPECT_EQ(slip->direction, 1);
  EXPECT_NEAR(slip->at, 1.0, kRounding);
  EXPECT_FALSE(mdrsim::next_friction_event(state, kFriction, kSpring, forward, 0.99));
  // f_x = -2 t reaches -1 at t = 0.5, along -x.
  const LinearMotion backward{0.0, 1.0, 0.0, 0.0, -2.0};
  const auto back = mdrsim::next_friction_event(state, kFriction, kSpring, backward, 3.0);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->direction, -1);
  EXPECT_NEAR(back->at, 0.5, kRounding);
}

TEST(StickSlipSpring, SlipsWhereAFallingLimitMeetsTheForce) {
  // From t0 = 0.4, s = t - t0: d = 0.8 - s/2, so the limit is 0.5 x 2 d = 0.8 - s/2; u = 0.2 + s/2
  // with offset 0, so f_x = 0.2 + s/2. They meet at s = 0.6, t = 1.
  const StickSlipSpring state{0.0, 0};
  const LinearMotion motion{0.4, 0.8, 0.2, -0.5, 0.5};
  const auto slip = mdrsim::next_friction_event(state, kFriction, kSpring, motion, 2.0);
  ASSERT_TRUE(slip);
  EXPECT_EQ(slip->kind, FrictionEventKind::slip);
  EXPECT_NEAR(slip->at, 1.0, kRounding);
}

TEST(StickSlipSpring, OnItsLimitMovingOutwardsItSlipsAtOnce) {
  const StickSlipSpring state{-1.0, 0};  // f_x = kx (0 - (-1)) = 1 = limit at d = 1
  const LinearMotion motion{0.3, 1.0, 0.0, 0.0, 1.0};
  const auto slip = mdrsim::next_friction_event(state, kFriction, kSpring, motion, 1.0);
  ASSERT_TRUE(slip);
  EXPECT_EQ(slip->at, 0.3);
  // Moving back it stays stuck: the other side of the limit is 2 away, at t = 0.3 + 2.
  const LinearMotion back{0.3, 1.0, 0.0, 0.0, -1.0};
  EXPECT_FALSE(mdrsim::next_friction_event(state, kFriction, kSpring, back, 2.29));
  const auto far = mdrsim::next_friction_event(state, kFriction, kSpring, back, 3.0);
  ASSERT_TRUE(far);
  EXPECT_NEAR(far->at, 2.3, kRounding);
  EXPECT_EQ(far->direction, -1);
}

TEST(StickSlipSpring, ASlidingSpringSticksWhenItsMotionReverses) {
  const StickSlipSpring state{-1.0, 1};  // sliding along +x at f_x = limit = 1, u = 0
  const LinearMotion back{0.0, 1.0, 0.0, 0.0, -0.1};
  const auto stick = mdrsim::next_friction_event(state, kFriction, kSpring, back, 1.0);
  ASSERT_TRUE(stick);
  EXPECT_EQ(stick->kind, FrictionEventKind::stick);
  EXPECT_EQ(stick->at, 0.0);
  StickSlipSpring stuck = state;
  mdrsim::apply_friction_event(stuck, *stick);
  EXPECT_EQ(stuck.sliding, 0);
  EXPECT_EQ(stuck.offset, -1.0);  // it keeps its slip: the Mindlin-Deresiewicz memory
  // Forward it slides on and dissipates the limit times the slip: 1 x 2 over t in [0, 2].
  const LinearMotion forward{0.0, 1.0, 0.0, 0.0, 1.0};
  EXPECT_FALSE(mdrsim::next_friction_event(state, kFriction, kSpring, forward, 2.0));
  StickSlipSpring sliding = state;
  EXPECT_NEAR(mdrsim::advance_spring(sliding, kFriction, kSpring, forward, 2.0), 2.0, kRounding);
  EXPECT_NEAR(sliding.offset, 1.0, kRounding);
}

TEST(StickSlipSpring, SlidingFollowsAChangingNormalLoadWithoutEvents) {
  // d = 1 + t/4: limit L = 1 + t/4, L' = 1/4; u = 1 + t: the slip velocity u' - L'/kx = 3/4 > 0,
  // so it slides on, f_x = L, with no event. Offset at t = 2: u - L/kx = 3 - 1.5 = 1.5.
  // Dissipated: int L (3/4) dt over [0, 2] = (3/4)(2 + 1/2) = 1.875.
  const StickSlipSpring start{0.0, 1};
  const LinearMotion pressing{0.0, 1.0, 1.0, 0.25, 1.0};
  EXPECT_FALSE(mdrsim::next_friction_event(start, kFriction, kSpring, pressing, 2.0));
  StickSlipSpring state = start;
  EXPECT_NEAR(mdrsim::advance_spring(state, kFriction, kSpring, pressing, 2.0), 1.875, kRounding);
  EXPECT_NEAR(state.offset, 1.5, kRounding);
  EXPECT_NEAR(mdrsim::spring_tangential_force(state, kFriction, kSpring, 1.5, 3.0), 1.5, kRounding);
  // Unloading with u held: L' = -1/4, slip velocity +1/4: it slides forward as the limit falls.
  const LinearMotion unloading{0.0, 1.0, 1.0, -0.25, 0.0};
  EXPECT_FALSE(mdrsim::next_friction_event(start, kFriction, kSpring, unloading, 2.0));
  // Pressing faster than it is sheared: u' = 0.2 < L'/kx = 0.25 reverses the slip: it sticks.
  const LinearMotion slow{0.0, 1.0, 1.0, 0.25, 0.2};
  const auto stick = mdrsim::next_friction_event(start, kFriction, kSpring, slow, 2.0);
  ASSERT_TRUE(stick);
  EXPECT_EQ(stick->kind, FrictionEventKind::stick);
}

TEST(StickSlipSpring, AGluedSpringSlipsAtItsAdhesiveLimitInTension) {
  // Glued "coulomb": limit 0.5 max(f_z, 0) + 0.3. d = 0.5 - t: f_z = 2 (0.5 - t) changes sign at
  // t = 0.5; the limit is 0.8 - t before, 0.3 after.
  const SlipLimit glued{0.5, 0.3};
  const StickSlipSpring state{0.0, 0};
  // f_x = 0.5 held: meets 0.8 - t at t = 0.3, before the crossing.
  const LinearMotion held{0.0, 0.5, 0.5, -1.0, 0.0};
  const auto early = mdrsim::next_friction_event(state, glued, kSpring, held, 2.0);
  ASSERT_TRUE(early);
  EXPECT_NEAR(early->at, 0.3, kRounding);
  // f_x = 0.2 + 0.1 t: 0.8 - t = 0.2 + 0.1 t at t = 0.545 > 0.5, so not before the crossing;
  // after it 0.3 = 0.2 + 0.1 t at t = 1.
  const LinearMotion ramp{0.0, 0.5, 0.2, -1.0, 0.1};
  const auto late = mdrsim::next_friction_event(state, glued, kSpring, ramp, 2.0);
  ASSERT_TRUE(late);
  EXPECT_EQ(late->kind, FrictionEventKind::slip);
  EXPECT_NEAR(late->at, 1.0, kRounding);
  // In tension the limit is tau_0 dx alone.
  EXPECT_EQ(mdrsim::slip_limit(glued, kSpring, 0.2 - 1.0), 0.3);
}

TEST(StickSlipSpring, GluedCoulombSlideHasAKinkWhereTheNormalForceChangesSign) {
  // Sliding along +x with u = 1 + 2t and d = 0.5 - t: limit 0.8 - t until t = 0.5, then 0.3.
  // Offset u - L: 0.2 at t = 0, 2 - 0.3 = 1.7 at 0.5, 3 - 0.3 = 2.7 at 1. Dissipated: mean limit
  // 0.55 over the slip 1.5, then 0.3 over 1.0: 1.125.
  const SlipLimit glued{0.5, 0.3};
  const StickSlipSpring start{0.2, 1};
  const LinearMotion motion{0.0, 0.5, 1.0, -1.0, 2.0};
  const auto kink = mdrsim::next_friction_event(start, glued, kSpring, motion, 1.0);
  ASSERT_TRUE(kink);
  EXPECT_EQ(kink->kind, FrictionEventKind::limit_kink);
  EXPECT_NEAR(kink->at, 0.5, kRounding);
  EXPECT_FALSE(mdrsim::next_friction_event(start, glued, kSpring, motion.from(kink->at), 1.0));
  StickSlipSpring state = start;
  EXPECT_NEAR(mdrsim::advance_spring(state, glued, kSpring, motion, 1.0), 1.125, kRounding);
  EXPECT_NEAR(state.offset, 2.7, kRounding);
}

TEST(StickSlipSpring, SlipsToItsLimitAtOnceWhenItsGlueLetsGo) {
  // Stretch 2 with limit 1: the offset moves by 1 to u - L/kx = 1; dissipated 1 x 1.
  StickSlipSpring state{0.0, 0};
  EXPECT_DOUBLE_EQ(mdrsim::slip_to_limit(state, kFriction, kSpring, 1.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(state.offset, 1.0);
  EXPECT_EQ(state.sliding, 1);
  StickSlipSpring within{0.0, 0};
  EXPECT_EQ(mdrsim::slip_to_limit(within, kFriction, kSpring, 1.0, -0.5), 0.0);
  EXPECT_EQ(within.sliding, 0);
}

}  // namespace
