// The walk down the continuum branch on a profile with two folds: a partial jump that lands on
// the tip's branch, checked against the independent continuum reference.
#include "engine/continuum/continuum_pull_off.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "controllers/builtin_controllers.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "engine/reference/continuum_reference.hpp"
#include "tests/support/stepped_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kRadius = 0.01;  // R [m]

using test::SteppedProfile;

// With A = 6 um the parabola's fold sits above d = 0: its jump lands on the tip's branch where
// d falls back to the fold's value, and the pull-off ends at the tip's fold (the reference's
// own test checks this against a brute-force scan). The folds agree to 1e-9 of the depth
// scale A (the reference refines to a few ulps, this walk's difference quotient to ~1e-12).
TEST(ContinuumPullOff, PartialJumpLandsOnTheTipsBranch) {
  const Material m = Material::from_youngs_modulus(1e6, 0.0, 0.05);
  const SteppedProfile profile(6e-6, 1e-5, kRadius);
  const ModeMixedCriterion criterion(m);
  ContinuumBranch branch(profile, criterion, m, FixedGripsController().constraint(),
                         FixedGripsController().constraint(), 0.0);
  const ContinuumPullOff p = continuum_pull_off(branch, 3e-4);
  const test::ContinuumCritical c =
      test::ContinuumReference(profile,
                               test::ContinuumMaterial::from_youngs_modulus(1e6, 0.0, 0.05), {}, {},
                               test::NormalControl::fixed_grips())
          .pull_off(3e-4);
  ASSERT_EQ(c.partial_jumps.size(), 1u);
  ASSERT_EQ(p.partial_jumps.size(), 1u);
  EXPECT_EQ(p.end, ContinuumPullOff::End::fold);
  const auto& want = c.partial_jumps.front();
  const auto& got = p.partial_jumps.front();
  EXPECT_NEAR(got.from.indentation, want.from.indentation, 1e-9 * 6e-6);
  EXPECT_NEAR(got.to.contact_radius, want.to.contact_radius, 1e-9 * want.to.contact_radius);
  EXPECT_NEAR(p.critical.indentation, c.point.indentation, 1e-9 * 6e-6);
  EXPECT_NEAR(p.critical.normal_force, c.point.normal_force, 1e-9 * std::abs(c.point.normal_force));
  ASSERT_TRUE(p.peak);
  EXPECT_NEAR(p.peak->normal_force, c.peak_adhesive_force, 1e-9 * std::abs(c.peak_adhesive_force));
  // Two stable stretches: a_g to the parabola's fold, the landing to the tip's fold.
  ASSERT_EQ(p.segments.size(), 2u);
  EXPECT_EQ(p.segments[1].first, got.to.contact_radius);
}

}  // namespace
}  // namespace mdrsim
