// The paper's closed forms checked against each other and against classical JKR values.
#include "engine/reference/parabolic_reference.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ref = mdrsim::parabolic_reference;

// JKR: a = 1, F = -1, d = -1 under fixed load (paper eq. 17 defines the scales this way).
TEST(ParabolicReference, FixedLoadJkrPointIsTheUnitScale) {
  const auto c = ref::fixed_load_critical(0.0);
  EXPECT_NEAR(c.contact_radius, 1.0, 1e-13);
  EXPECT_NEAR(c.normal_force, -1.0, 1e-13);
  EXPECT_NEAR(c.indentation, -1.0, 1e-13);
}

// Fixed grips: a^3 = 1/9 (eq. 31 at u = 0), F = -5/9 (eq. 33), d = 3 a^2 - 4 sqrt(a).
TEST(ParabolicReference, FixedGripsJkrPointIsMinusFiveNinths) {
  const auto c = ref::fixed_grips_critical(0.0);
  EXPECT_NEAR(c.contact_radius, std::cbrt(1.0 / 9.0), 1e-13);
  EXPECT_NEAR(c.normal_force, -5.0 / 9.0, 1e-13);
  EXPECT_NEAR(c.indentation, 3.0 * std::cbrt(1.0 / 81.0) - 4.0 * std::pow(1.0 / 9.0, 1.0 / 6.0),
              1e-13);
}

// Eqs. 18-19 are eqs. 25-26 at u = 0.
TEST(ParabolicReference, BranchWithoutTangentialLoadIsJkr) {
  for (const double a : {0.1, 0.5, 1.0, 2.0, 3.5}) {
    EXPECT_NEAR(ref::indentation(a), 3.0 * a * a - 4.0 * std::sqrt(a), 1e-13);
    EXPECT_NEAR(ref::normal_force(a), a * a * a - 2.0 * std::pow(a, 1.5), 1e-13);
  }
}

// The folds are where the branch's slopes vanish, checked by finite differences.
TEST(ParabolicReference, FoldsAreStationaryPointsOfTheBranch) {
  for (const double gamma : {1.0, 0.82352941176470584}) {
    for (const double u : {0.0, 1.0, 2.5, 4.0}) {
      const double h = 1e-6;
      const double afg = ref::fixed_grips_critical(u, gamma).contact_radius;
      EXPECT_NEAR(
          (ref::indentation(afg + h, u, gamma) - ref::indentation(afg - h, u, gamma)) / (2 * h),
          0.0, 1e-7);
      const double afl = ref::fixed_load_critical(u, gamma).contact_radius;
      EXPECT_NEAR(
          (ref::normal_force(afl + h, u, gamma) - ref::normal_force(afl - h, u, gamma)) / (2 * h),
          0.0, 1e-7);
    }
  }
}

// Eq. 34 follows from eqs. 32-33: the critical point lies on the master curve.
TEST(ParabolicReference, FixedGripsCriticalPointsLieOnTheMasterCurve) {
  for (const double gamma : {1.0, 0.82352941176470584}) {
    for (const double u : {0.0, 0.7, 2.0, 4.0}) {
      const auto c = ref::fixed_grips_critical(u, gamma);
      EXPECT_NEAR(c.normal_force, ref::fixed_grips_master_curve(c.tangential_force, gamma), 1e-12);
      EXPECT_NEAR(c.normal_force, std::pow(c.contact_radius, 3) - 2.0 / 3.0, 1e-12);  // eq. 33
    }
  }
}

// Fig. 3b: the fixed-load curve lies below the fixed-grips one, by 4/9 at F_x = 0, and
// the gap closes as the tangential load grows.
TEST(ParabolicReference, FixedLoadCurveApproachesFixedGripsCurve) {
  EXPECT_NEAR(ref::fixed_grips_critical(0).normal_force - ref::fixed_load_critical(0).normal_force,
              4.0 / 9.0, 1e-12);
  double gap = 1.0;
  for (const double u : {0.0, 1.0, 2.0, 3.0, 4.0, 6.0}) {
    const double next =
        ref::fixed_grips_critical(u).normal_force - ref::fixed_load_critical(u).normal_force;
    EXPECT_GT(next, 0.0);
    EXPECT_LT(next, gap);
    gap = next;
  }
}

// A compliant machine lies between its two limits and tends to them.
TEST(ParabolicReference, CompliantFoldTendsToItsLimits) {
  const double fg = ref::fixed_grips_critical(0.0).normal_force;
  const double fl = ref::fixed_load_critical(0.0).normal_force;
  EXPECT_NEAR(ref::compliant_critical(1e9).normal_force, fg, 1e-7);
  EXPECT_NEAR(ref::compliant_critical(1e-9).normal_force, fl, 1e-7);
  const double mid = ref::compliant_critical(1.0).normal_force;
  EXPECT_GT(mid, fl);
  EXPECT_LT(mid, fg);
}
