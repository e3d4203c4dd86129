// Maugis' parabola (maugis_reference) against its known limits and a 40-digit evaluation.
#include "engine/reference/maugis_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace mdrsim::maugis_reference {
namespace {

constexpr double kPi = std::numbers::pi;

// The opening condition solved at 40 digits (mpmath bisection in t = arctan sqrt(m^2 - 1)), one
// point each where t is large (lambda = 0.3), moderate (1), small (50) and where its series
// carries the sums (1e4, t = 1e-4). Tolerance 1e-12: a few ulps of P, D and C, times the
// condition of the root in t.
TEST(MaugisReference, ContactBranchMatchesAFortyDigitEvaluation) {
  struct Point {
    double lambda, a, c, d, p;
  };
  for (const Point& q :
       {Point{1.0, 1.0, 1.4159617835336622, -0.33662777827242357, -1.5796270206018335},
        Point{0.3, 0.5, 2.03580728506845, -0.53938064855305623, -1.8155450993492582},
        Point{50.0, 1.2, 1.2002998640868709, -0.34856084537355276, -1.491945860237247},
        Point{1e4, 0.8, 0.80000000749999999, -0.82059348438588624, -1.2407121922175146}}) {
    SCOPED_TRACE(q.lambda);
    const MaugisState s = contact_branch(q.lambda, q.a);
    EXPECT_NEAR(s.cohesive_radius, q.c, 1e-12);
    EXPECT_NEAR(s.indentation, q.d, 1e-12);
    EXPECT_NEAR(s.force, q.p, 1e-12);
  }
}

// lambda -> infinity is JKR: P = A^3 - sqrt(6 A^3), D = A^2 - (2/3) sqrt(6 A) in Maugis' units;
// the difference falls like lambda^-2 (4.9e-5 at 100, 4.9e-9 at 1e4), so 1e-9 at 1e5.
TEST(MaugisReference, LargeLambdaIsJkr) {
  for (const double a : {0.6, 1.0, 1.5}) {
    const MaugisState s = contact_branch(1e5, a);
    EXPECT_NEAR(s.force, a * a * a - std::sqrt(6.0 * a * a * a), 1e-9);
    EXPECT_NEAR(s.indentation, a * a - 2.0 / 3.0 * std::sqrt(6.0 * a), 1e-9);
  }
  EXPECT_NEAR(fixed_load_pull_off(1e4).force, -1.5, 1e-6);
  const MaugisState grips = fixed_grips_jump(1e4);
  EXPECT_NEAR(grips.force, -5.0 / 6.0, 1e-6);
  EXPECT_NEAR(grips.contact_radius, std::cbrt(1.0 / 6.0), 1e-6);
}

// lambda -> 0 is DMT: the fixed-load pull-off tends to -2 (-1.99999995 at lambda = 1e-5); under
// fixed grips the contact closes and the zone's disk folds at C = 8 lambda / (3 pi), in closed
// form.
TEST(MaugisReference, SmallLambdaIsDmt) {
  EXPECT_NEAR(fixed_load_pull_off(1e-5).force, -2.0, 1e-6);
  for (const double lambda : {0.01, 0.3, 0.9}) {
    const MaugisState grips = fixed_grips_jump(lambda);
    const double c = 8.0 * lambda / (3.0 * kPi);
    EXPECT_EQ(grips.contact_radius, 0.0);
    EXPECT_NEAR(grips.force, -0.5 * kPi * lambda * c * c, 1e-15);
  }
}

// The transition: -1.6007 at lambda = 1 (Maugis' curve). Under fixed grips the contact closes
// before D folds where C0 reaches the no-contact branch's fold 8 lambda/(3 pi): substituted into
// C0's equation, lambda^3 = 9 pi / (16 (pi - 1)), 0.9379475. Just above it the contact branch's
// fold sits just above A = 0 and loses the contact at once; just
// below, the no-contact branch carries the fold: the two forces meet there (C0 = 8 lambda/(3 pi)).
TEST(MaugisReference, TheTransition) {
  EXPECT_NEAR(fixed_load_pull_off(1.0).force, -1.6007, 1e-4);
  const double threshold = grips_threshold();
  EXPECT_NEAR(threshold, 0.93794746, 1e-8);
  EXPECT_NEAR(closing_cohesive_radius(threshold), 8.0 * threshold / (3.0 * kPi), 1e-12);
  EXPECT_EQ(fixed_grips_jump(threshold * (1.0 - 1e-4)).contact_radius, 0.0);
  const MaugisState above = fixed_grips_jump(threshold * (1.0 + 1e-4));
  EXPECT_GT(above.contact_radius, 0.0);
  EXPECT_LT(above.contact_radius, 1e-2);
  EXPECT_NEAR(above.force, fixed_grips_jump(threshold * (1.0 - 1e-4)).force, 1e-3);
  // D at the fold lies below D at the closing point: the fold is real, not a rounding tie.
  EXPECT_LT(above.indentation, contact_branch(threshold * (1.0 + 1e-4), 1e-6).indentation);
}

// As A -> 0 the contact branch runs onto the no-contact branch at C0, the difference falling like
// A (9e-10 in P at A = 1e-6, lambda = 0.5); much closer to A = 0, t = arccos(A/C) sits within a
// few ulps of pi/2 and m = C/A loses its digits, so the reference is used down to A ~ 1e-6.
TEST(MaugisReference, TheBranchesMeetWhereTheContactCloses) {
  for (const double lambda : {0.1, 0.5, 2.0}) {
    SCOPED_TRACE(lambda);
    const MaugisState closing = contact_branch(lambda, 1e-6);
    const MaugisState disk = no_contact_branch(lambda, closing_cohesive_radius(lambda));
    EXPECT_NEAR(closing.cohesive_radius, disk.cohesive_radius, 1e-7);
    EXPECT_NEAR(closing.indentation, disk.indentation, 1e-7);
    EXPECT_NEAR(closing.force, disk.force, 1e-7);
  }
}

}  // namespace
}  // namespace mdrsim::maugis_reference
