// rtol on programs (issue 9, point 3): every stage end's and jump's forces within rtol of the
// continuum (tests/support/program_reference), and each error estimate at least the error.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "engine/run/run_scene.hpp"
#include "tests/support/program_examples.hpp"
#include "tests/support/program_reference.hpp"

namespace mdrsim {
namespace {

namespace pr = program_reference;

const double kForce = test::kExampleForce;
const double kDepth = test::kExampleDepth;

/// scenes/programs/NAME.toml with its springs replaced by rtol.
Scene scene_with_rtol(const std::string& name, double rtol) {
  return test::program_example(name, "rtol = " + std::to_string(rtol));
}

/// One checked force: the engine's value and estimate against the continuum's [N].
void expect_within(const char* what, double value, std::optional<double> estimate, double reference,
                   double rtol) {
  ASSERT_TRUE(estimate) << what;
  const double error = std::abs(value - reference);
  EXPECT_LE(error, rtol * std::abs(reference))
      << what << ": " << value / kForce << " F0 against " << reference / kForce << " F0";
  EXPECT_LE(error, *estimate) << what << ": the estimate " << *estimate / kForce
                              << " F0 is below the error " << error / kForce << " F0";
}

class ProgramRtol : public ::testing::TestWithParam<double> {};

TEST_P(ProgramRtol, ReversibleCycleJumpsAndStageEndsMeetRtol) {
  const double rtol = GetParam();
  const RunResult r = run_scene(scene_with_rtol("jkr_cycle_reversible.toml", rtol), {});
  EXPECT_TRUE(r.accuracy.rtol_met);
  ASSERT_EQ(r.jumps.size(), 2u);
  expect_within("jump-in after", r.jumps[0].after.normal_force, r.jumps[0].after_error_estimate,
                -8.0 / 9.0 * kForce, rtol);
  expect_within("jump-out critical", r.jumps[1].critical.normal_force,
                r.jumps[1].critical_error_estimate, pr::jkr_fold().normal_force * kForce, rtol);
  const double d_max = r.stages[0].end.indentation / kDepth;
  const double approach_end =
      pr::jkr_state(pr::jkr_radius_at_indentation(d_max)).normal_force * kForce;
  expect_within("approach end", r.stages[0].end.normal_force,
                r.stages[0].normal_force_error_estimate, approach_end, rtol);
}

TEST_P(ProgramRtol, ReloadStageEndsMeetRtolWithAndWithoutRebinding) {
  const double rtol = GetParam();
  for (const bool rebinding : {false, true}) {
    const RunResult r = run_scene(
        scene_with_rtol(rebinding ? "reload_rebinding_true.toml" : "reload_rebinding_false.toml",
                        rtol),
        {});
    EXPECT_TRUE(r.accuracy.rtol_met);
    ASSERT_GE(r.stages.size(), 4u);
    // The scenes' depths: d1 = 12 d0, d2 = 3 d0, d3 = 6 d0 (see their comments).
    const pr::ReloadProgram expected = pr::reload_program(12.0, 3.0, 6.0, rebinding);
    for (std::size_t i = 0; i < 4; ++i) {
      expect_within(r.stages[i].name.c_str(), r.stages[i].end.normal_force,
                    r.stages[i].normal_force_error_estimate, expected.stage_end_force[i] * kForce,
                    rtol);
    }
    ASSERT_TRUE(r.critical);
    expect_within("pull-off", r.critical->normal_force, r.accuracy.critical_error_estimate,
                  expected.pull_off_critical.normal_force * kForce, rtol);
  }
}

// The critical points of the shear ramps and the inclined pull, whose folds the paper's
// closed forms give.
TEST_P(ProgramRtol, ShearRampsAndInclinedPullCriticalPointsMeetRtol) {
  const double rtol = GetParam();
  const auto cases = test::shear_and_inclined_examples();
  for (const auto& c : cases) {
    const RunResult r = run_scene(scene_with_rtol(c.scene, rtol), {});
    EXPECT_TRUE(r.accuracy.rtol_met) << c.scene;
    ASSERT_TRUE(r.critical) << c.scene;
    expect_within(c.scene, r.critical->normal_force, r.accuracy.critical_error_estimate,
                  c.normal_force * kForce, rtol);
  }
}

INSTANTIATE_TEST_SUITE_P(Tolerances, ProgramRtol, ::testing::Values(1e-3, 1e-4),
                         [](const auto& info) {
                           return info.param == 1e-3 ? "rtol1e3" : "rtol1e4";
                         });

}  // namespace
}  // namespace mdrsim
