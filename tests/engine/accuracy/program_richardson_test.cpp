// Richardson on programs: the reported states located between springs and
// extrapolated across rows of N/2, N and 2N springs, against the continuum
// (engine/reference/program_reference), each estimate at least its error.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "engine/reference/program_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "tests/support/program_examples.hpp"

namespace mdrsim {
namespace {

namespace pr = program_reference;

const double kForce = test::kExampleForce;
const double kDepth = test::kExampleDepth;

/// scenes/programs/NAME.toml on `springs` springs, with `extrapolation`.
Scene example(const std::string& name, int springs, const char* extrapolation) {
  return test::program_example(
      name, "springs = " + std::to_string(springs) + "\nextrapolation = \"" + extrapolation + "\"");
}

/// |value - reference| in F0, checked against `tolerance` F0 and against the estimate.
double expect_within(const std::string& what, double value, std::optional<double> estimate,
                     double reference, double tolerance) {
  const double error = std::abs(value - reference) / kForce;
  EXPECT_LE(error, tolerance) << what << ": " << value / kForce << " F0 against "
                              << reference / kForce << " F0";
  EXPECT_TRUE(estimate) << what;
  if (estimate) {
    EXPECT_LE(error, *estimate / kForce)
        << what << ": the estimate " << *estimate / kForce << " F0 is below the error " << error;
  }
  return error;
}

// The bench's target 9 on the smallest rows: the jump in, the end of the approach and the
// fold within 1e-4 F0 from rows of 64, 128 and 256 springs.
TEST(ProgramRichardson, ReversibleCycleWithin1e4FromRowsOf64To256Springs) {
  const RunResult r = run_scene(example("jkr_cycle_reversible.toml", 128, "richardson"), {});
  EXPECT_EQ(r.accuracy.route, Accuracy::Route::richardson);
  EXPECT_EQ(r.accuracy.rows, (std::vector<std::int64_t>{64, 128, 256}));
  // Every state is located; the one warning is the shorthand's rule on springs at the
  // critical point (75 on the 256-spring row, below the 100 that rule asks for).
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].rfind("the critical point has only 75 springs in contact", 0), 0u)
      << r.warnings[0];
  ASSERT_EQ(r.jumps.size(), 2u);
  ASSERT_EQ(r.stages.size(), 2u);
  const pr::ReversibleCycle expected =
      pr::reversible_jkr_cycle(r.stages[0].end.indentation / kDepth);
  expect_within("jump-in after", r.jumps[0].after.normal_force, r.jumps[0].after_error_estimate,
                expected.jump_in_after.normal_force * kForce, 1e-4);
  expect_within("approach end", r.stages[0].end.normal_force,
                r.stages[0].normal_force_error_estimate,
                expected.approach_end.normal_force * kForce, 1e-4);
  expect_within("jump-out critical", r.jumps[1].critical.normal_force,
                r.jumps[1].critical_error_estimate, expected.retract_critical.normal_force * kForce,
                1e-4);
  ASSERT_TRUE(r.critical);
  EXPECT_EQ(r.critical->normal_force, r.jumps[1].critical.normal_force);
}

// Without the location between springs the rows' sawtooth would be extrapolated too: the
// extrapolated states are far closer than the finest row's own.
TEST(ProgramRichardson, ExtrapolationRemovesTheSawtoothOfTheFinestRow) {
  const RunResult extrapolated =
      run_scene(example("jkr_cycle_reversible.toml", 256, "richardson"), {});
  const RunResult finest = run_scene(example("jkr_cycle_reversible.toml", 512, "none"), {});
  ASSERT_EQ(extrapolated.jumps.size(), 2u);
  ASSERT_EQ(finest.jumps.size(), 2u);
  const auto error = [](double value, double reference) {
    return std::abs(value / kForce - reference);
  };
  const double after = -8.0 / 9.0;
  const double fold = pr::jkr_fold().normal_force;
  EXPECT_LT(error(extrapolated.jumps[0].after.normal_force, after),
            0.1 * error(finest.jumps[0].after.normal_force, after));
  EXPECT_LT(error(extrapolated.jumps[1].critical.normal_force, fold),
            0.1 * error(finest.jumps[1].critical.normal_force, fold));
}

TEST(ProgramRichardson, GlueOnTouchCycle) {
  const RunResult r = run_scene(example("jkr_cycle_glue_on_touch.toml", 512, "richardson"), {});
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
  ASSERT_EQ(r.stages.size(), 2u);
  ASSERT_TRUE(r.critical);
  const pr::GlueOnTouchCycle expected =
      pr::glue_on_touch_cycle(r.stages[0].end.indentation / kDepth);
  expect_within("load end", r.stages[0].end.normal_force, r.stages[0].normal_force_error_estimate,
                expected.load_end.normal_force * kForce, 1e-4);
  expect_within("pull-off", r.critical->normal_force, r.accuracy.critical_error_estimate,
                expected.retract_critical.normal_force * kForce, 1e-4);
}

// The critical points of the shear ramps and the inclined pull: folds located along lines in
// which the tangential displacement moves (scenes/programs/ comments).
TEST(ProgramRichardson, ShearRampsAndInclinedPull) {
  const auto cases = test::shear_and_inclined_examples();
  for (const auto& c : cases) {
    const RunResult r = run_scene(example(c.scene, 512, "richardson"), {});
    ASSERT_TRUE(r.critical) << c.scene;
    for (const std::string& w : r.warnings) ADD_FAILURE() << c.scene << ": " << w;
    expect_within(c.scene, r.critical->normal_force, r.accuracy.critical_error_estimate,
                  c.normal_force * kForce, 1e-4);
  }
}

// Springs pressed outside the glued ones (no rebinding on reload) are a second front that the
// rows do not locate: those states keep the finest row's value and plain estimate, and a
// warning says which.
TEST(ProgramRichardson, PressedSpringsFallBackToTheFinestRowWithAWarning) {
  const RunResult r = run_scene(example("reload_rebinding_false.toml", 512, "richardson"), {});
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.front().find("could not be located between springs"), std::string::npos)
      << r.warnings.front();
  const pr::ReloadProgram expected = pr::reload_program(12.0, 3.0, 6.0, false);
  ASSERT_GE(r.stages.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    expect_within(r.stages[i].name, r.stages[i].end.normal_force,
                  r.stages[i].normal_force_error_estimate, expected.stage_end_force[i] * kForce,
                  1e-2);
  }
}

/// |value - reference| [J] checked against the estimate; returns the error.
double expect_work_within(const std::string& what, double value, std::optional<AxisWork> estimate,
                          bool normal, double reference) {
  const double error = std::abs(value - reference);
  EXPECT_TRUE(estimate) << what;
  if (estimate) {
    const double bound = normal ? estimate->normal : estimate->tangential;
    EXPECT_LE(error, bound) << what << ": " << value << " J against " << reference
                            << " J, the estimate " << bound << " J";
  }
  return error;
}

// The reversible cycle's works on its Richardson rows (2000, 4000, 8000 springs) against
// program_reference's: the approach from the jump-in to d_max and the retract from there to the
// fold along eqs. 18-19 (jkr_branch_work; the jumps at fixed grips do no work), and the
// cycle's, each within its estimate.
TEST(ProgramRichardson, ReversibleCycleWorksWithinTheirEstimates) {
  const RunResult r = run_scene(example("jkr_cycle_reversible.toml", 4000, "richardson"), {});
  ASSERT_EQ(r.stages.size(), 2u);
  ASSERT_TRUE(r.work);
  const pr::ReversibleCycle c = pr::reversible_jkr_cycle(r.stages[0].end.indentation / kDepth);
  const double unit = kForce * kDepth;
  const double a_end = c.approach_end.contact_radius;
  expect_work_within("approach", r.stages[0].work.normal, r.stages[0].work_error_estimate, true,
                     pr::jkr_branch_work(c.jump_in_after.contact_radius, a_end) * unit);
  expect_work_within("retract", r.stages[1].work.normal, r.stages[1].work_error_estimate, true,
                     pr::jkr_branch_work(a_end, c.retract_critical.contact_radius) * unit);
  expect_work_within("cycle", r.work->normal, r.accuracy.work_error_estimate, true,
                     c.dissipated_work * unit);
}

// The shear ramp at a held F = -F0/2 (scenes/programs/shear_ramp_fixed_load.toml) on its
// Richardson rows, every work against the closed path, in F0 d0 (gamma = 1):
// - preload: glued on touch to a_p = 2 (Hertz), (6/5) a_p^5;
// - unload under the held force: at the fixed radius a_p (F = (a/2)(d - a^2)) from 3 a_p^2 down
//   to eq. 18's depth, a trapezoid, then along eqs. 18-19 to F (jkr_branch_work);
// - shear: the start lies on the let-go limit (e^2 = 16 a), so the contact peels at once along
//   eqs. 25-26 at the held F to eq. 29's critical point: the normal work F (d_c - d_s); with
//   S = 2 (a^3 - F)/a (eq. 26) and u^2 = 16 a - S^2 (eq. 25), F_x = a u/2 (eq. 27) does
//   int (a/4) d(u^2) = [2 a^2 - a S^2/4 + a^5/5 - F a^2 - F^2/a] from a_s to a_c (by parts).
// Each row's unload ends at the held force with its front on a spring, its shear at its last
// equilibrium before the flight: their depths sit a varying fraction of a spacing off the
// located ends, which Richardson kept as a sawtooth (the program's normal work 3.2e-13 J off
// with an estimate of 1.5e-14 J) until the works were carried to the located ends. The estimates
// of the works that move stay within 100 times their errors (found 17 and 25).
TEST(ProgramRichardson, ShearRampAtHeldForceWorksWithinTheirEstimates) {
  const RunResult r = run_scene(example("shear_ramp_fixed_load.toml", 4000, "richardson"), {});
  ASSERT_EQ(r.stages.size(), 3u);
  ASSERT_TRUE(r.work);
  const double ap = 2.0;
  const double f = -0.5;
  const pr::ShearRamp ramp = pr::shear_ramp_at_held_force(ap, f);
  ASSERT_EQ(ramp.first_let_go.tangential_displacement, 0.0);
  const pr::State glued = pr::jkr_state(ap);
  const double a_s = ramp.start.contact_radius;
  const double a_c = ramp.critical.contact_radius;
  const double preload = 1.2 * std::pow(ap, 5);
  const double unload =
      0.5 * (ap * ap * ap + glued.normal_force) * (glued.indentation - 3.0 * ap * ap) +
      pr::jkr_branch_work(ap, a_s);
  const double shear_normal = f * (ramp.critical.indentation - ramp.start.indentation);
  const auto primitive = [&](double a) {
    const double stretch = 2.0 * (a * a * a - f) / a;
    return 2.0 * a * a - 0.25 * a * stretch * stretch + 0.2 * std::pow(a, 5) - f * a * a -
           f * f / a;
  };
  const double shear_tangential = primitive(a_c) - primitive(a_s);
  const double unit = kForce * kDepth;
  expect_work_within("preload", r.stages[0].work.normal, r.stages[0].work_error_estimate, true,
                     preload * unit);
  const double unload_error = expect_work_within(
      "unload", r.stages[1].work.normal, r.stages[1].work_error_estimate, true, unload * unit);
  const double shear_error =
      expect_work_within("shear, normal", r.stages[2].work.normal, r.stages[2].work_error_estimate,
                         true, shear_normal * unit);
  expect_work_within("shear, tangential", r.stages[2].work.tangential,
                     r.stages[2].work_error_estimate, false, shear_tangential * unit);
  expect_work_within("program, normal", r.work->normal, r.accuracy.work_error_estimate, true,
                     (preload + unload + shear_normal) * unit);
  expect_work_within("program, tangential", r.work->tangential, r.accuracy.work_error_estimate,
                     false, shear_tangential * unit);
  ASSERT_TRUE(r.stages[1].work_error_estimate && r.stages[2].work_error_estimate);
  EXPECT_LE(r.stages[1].work_error_estimate->normal, 100.0 * unload_error);
  EXPECT_LE(r.stages[2].work_error_estimate->normal, 100.0 * shear_error);
}

}  // namespace
}  // namespace mdrsim
