// The program engine on scenes built in code: the reversible JKR cycle against its closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "controllers/builtin_controllers.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "engine/output/result_json.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"
#include "profiles/parabolic_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kRadius = 0.01;
constexpr double kModulus = 1e6;
constexpr double kWork = 0.05;

StageAxis fixed_grips(StageAxis::Motion motion, double value) {
  return {.control = "fixed-grips",
          .controller = std::make_shared<FixedGripsController>(),
          .motion = motion,
          .value = value};
}

Scene cycle_scene(double approach_work, double depth, std::int64_t springs) {
  Scene scene;
  scene.material = {kModulus, kModulus, kWork, approach_work};
  scene.profile_name = "parabolic";
  scene.profile = std::make_unique<ParabolicProfile>(kRadius);
  scene.criterion_name = "mode-mixed";
  scene.criterion = std::make_unique<ModeMixedCriterion>(scene.material);
  scene.springs = springs;
  Program program;
  program.stages.push_back(
      {.name = "approach", .normal = fixed_grips(StageAxis::Motion::to, depth)});
  program.stages.push_back({.name = "retract",
                            .normal = fixed_grips(StageAxis::Motion::by, -depth),
                            .until_separation = true});
  scene.program = std::move(program);
  return scene;
}

struct Scales {
  double force, depth;
};
Scales jkr_scales() {
  const double pi = std::numbers::pi;
  return {1.5 * pi * kRadius * kWork,
          std::cbrt(3.0 * pi * pi * kRadius * kWork * kWork / (64.0 * kModulus * kModulus))};
}

TEST(ProgramRunner, ReversibleJkrCycleJumpsInAtMinusEightNinthsAndOutAtMinusFiveNinths) {
  const Scene scene = cycle_scene(kWork, 2e-5, 4000);
  const RunResult r = run_scene(scene, {});
  const Scales s = jkr_scales();
  ASSERT_FALSE(r.jumps.empty());
  EXPECT_TRUE(r.jumps.front().inward);
  EXPECT_NEAR(r.jumps.front().after.normal_force / s.force, -8.0 / 9.0, 5e-3);
  ASSERT_TRUE(r.critical);
  EXPECT_NEAR(r.critical->normal_force / s.force, -5.0 / 9.0, 5e-3);
  ASSERT_TRUE(r.work);
  // The fixed-grips fold of eq. 18: d_c = -3^(2/3) d0 (paper eq. 21 at u = 0).
  EXPECT_NEAR(r.critical->indentation / s.depth, -std::cbrt(9.0), 2e-3);
  // The cycle's dissipation, the area between the JKR branch and F = 0 from d_c to 0:
  // 0.9355 F0 |d_c| (derived in engine/reference/program_reference.cpp); O(1/N) at N = 4000.
  EXPECT_NEAR(r.work->normal / (s.force * std::abs(r.critical->indentation)), 0.9355, 2e-3);
}

StageAxis axis(const char* control, StageAxis::Motion motion, double value) {
  StageAxis a{.control = control, .motion = motion, .value = value};
  if (std::string(control) == "fixed-load") {
    a.controller = std::make_shared<FixedLoadController>();
  } else {
    a.controller = std::make_shared<FixedGripsController>();
  }
  return a;
}

TEST(ProgramRunner, ShearRampAtHeldForceEndsOnTheFixedLoadCriticalCurve) {
  Scene scene = cycle_scene(0.0, 2e-5, 4000);
  const Scales s = jkr_scales();
  using M = StageAxis::Motion;
  scene.program->stages[1] = {.name = "unload",
                              .normal = axis("fixed-load", M::to, -0.5 * s.force)};
  scene.program->stages.push_back(
      {.name = "shear", .tangential = axis("fixed-grips", M::by, 1e-6), .until_separation = true});
  const RunResult r = run_scene(scene, {});
  ASSERT_TRUE(r.critical) << to_string(r.status);
  const double u = r.critical->tangential_displacement / s.depth;
  const auto expected = parabolic_reference::fixed_load_critical(u);
  EXPECT_EQ(r.status, RunStatus::instability);
  EXPECT_EQ(r.jumps.size(), 1u);
  EXPECT_NEAR(r.critical->normal_force / s.force, expected.normal_force, 5e-3);
}

TEST(ProgramRunner, GlueOnTouchCycle) {
  const Scene scene = cycle_scene(0.0, 2e-5, 4000);
  const RunResult r = run_scene(scene, {});
  const Scales s = jkr_scales();
  ASSERT_TRUE(r.critical);
  std::printf("status %s F/F0 %.6g d/d0 %.6g work %.6g J = %.6g F0 d_max, jumps %zu\n",
              to_string(r.status), r.critical->normal_force / s.force,
              r.critical->indentation / s.depth, r.work->normal, r.work->normal / (s.force * 2e-5),
              r.jumps.size());
  EXPECT_NEAR(r.critical->normal_force / s.force, -5.0 / 9.0, 5e-3);
}

TEST(ProgramRunner, FixedLoadReversibleCycle) {
  Scene scene = cycle_scene(kWork, 2e-5, 4000);
  const Scales s = jkr_scales();
  using M = StageAxis::Motion;
  scene.program->stages[0] = {.name = "approach", .normal = axis("fixed-load", M::to, s.force)};
  scene.program->stages[1] = {.name = "retract",
                              .normal = axis("fixed-load", M::by, -2.0 * s.force),
                              .until_separation = true};
  const RunResult r = run_scene(scene, {});
  ASSERT_TRUE(r.critical) << to_string(r.status);
  // Reversible under fixed load: the jump-in at F = 0 and the pull-off at -F0 (eq. 19's minimum).
  ASSERT_EQ(r.jumps.size(), 2u);
  EXPECT_TRUE(r.jumps[0].inward);
  EXPECT_NEAR(r.critical->normal_force / s.force, -1.0, 5e-3);
}

// The stepping method on a program: the paper's increments on the stage parameter, halved where
// a step would move more than one spring. Its critical point converges to the event method's
// as the increment shrinks: within one step's change of d of it.
TEST(ProgramRunner, SteppingFindsTheEventMethodsCriticalPointWithinOneIncrement) {
  Scene scene = cycle_scene(kWork, 2e-5, 2000);
  const RunResult exact = run_scene(scene, {});
  scene.solver.method = SolverMethod::stepping;
  scene.solver.step = 1e-4;  // of the stage parameter: 2e-9 m of d per step
  const RunResult stepped = run_scene(scene, {});
  ASSERT_TRUE(exact.critical && stepped.critical);
  EXPECT_EQ(stepped.status, exact.status);
  EXPECT_GT(stepped.counts.steps, 0);
  EXPECT_GT(stepped.counts.halvings, 0);  // the jump-in and the jump-out are halved into
  EXPECT_EQ(stepped.jumps.size(), exact.jumps.size());
  EXPECT_NEAR(stepped.critical->indentation, exact.critical->indentation, 2e-9);
  EXPECT_NEAR(stepped.critical->normal_force / exact.critical->normal_force, 1.0, 1e-3);
  // A step moves the indenter past each spring's threshold by up to one increment before the
  // spring changes: the work differs by O(increment), 1.5e-3 here, and halves with it.
  const auto work_error = [&](double step) {
    scene.solver.step = step;
    return std::abs(run_scene(scene, {}).work->normal / exact.work->normal - 1.0);
  };
  EXPECT_LT(work_error(1e-4), 3e-3);
  EXPECT_LT(work_error(2.5e-5), 0.5 * work_error(1e-4));
}

TEST(ProgramRunner, SteppingStopsAtMaxStepsWithAWarning) {
  Scene scene = cycle_scene(kWork, 2e-5, 200);
  scene.solver.method = SolverMethod::stepping;
  scene.solver.step = 1e-4;
  scene.solver.max_steps = 100;
  const RunResult r = run_scene(scene, {});
  EXPECT_EQ(r.status, RunStatus::step_limit);
  EXPECT_FALSE(r.critical);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("solver.max_steps = 100"), std::string::npos) << r.warnings[0];
}

// The impossible at run time: a fixed load that pulls before anything
// is in contact ends the program at once with a status and a warning, never a hang.
TEST(ProgramRunner, AFixedLoadPullingOnNothingEndsTheProgramWithAWarning) {
  Scene scene = cycle_scene(kWork, 2e-5, 100);
  scene.program->stages = {
      {.name = "pull", .normal = axis("fixed-load", StageAxis::Motion::to, -1e-3)}};
  const RunResult r = run_scene(scene, {});
  EXPECT_EQ(r.status, RunStatus::no_instability);
  EXPECT_FALSE(r.critical);
  EXPECT_EQ(r.counts.events, 0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("nothing holds it"), std::string::npos) << r.warnings[0];
}

// A program that stops in a stage reports the controllers of that stage, not of its last.
TEST(ProgramRunner, AProgramStoppedEarlyReportsTheControlsOfItsLastStageRun) {
  Scene scene = cycle_scene(kWork, 2e-5, 100);
  scene.program->stages = {
      {.name = "pull", .normal = axis("fixed-load", StageAxis::Motion::to, -1e-3)},
      {.name = "press", .normal = axis("fixed-grips", StageAxis::Motion::to, 1e-6)}};
  const RunResult r = run_scene(scene, {});
  ASSERT_EQ(r.stages.size(), 1u);
  EXPECT_EQ(final_controls(scene, r.stages.size()).first, "fixed-load");
  EXPECT_EQ(final_controls(scene).first, "fixed-grips");
  EXPECT_EQ(result_to_json(scene, r)["control"]["normal"], "fixed-load");
}

// A jump changes the row: a change located at t that rounding leaves just short of its
// condition must not flip back at the same t (reload_rebinding_false once reported 363 empty
// "jumps" of a touch and a lift at one t).
TEST(ProgramRunner, EveryJumpOfTheExampleScenesChangesTheRow) {
  int scenes = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(MDRSIM_SOURCE_DIR) + "/scenes/programs")) {
    if (entry.path().extension() != ".toml") continue;
    ++scenes;
    const Scene scene = SceneDocument::from_file(entry.path()).build(Registries::builtin());
    const RunResult r = run_scene(scene, {});
    for (const JumpRecord& jump : r.jumps) {
      EXPECT_TRUE(jump.springs != 0 || jump.glued_springs != 0)
          << entry.path().filename() << ": a jump in stage " << jump.stage << " changes nothing";
    }
  }
  EXPECT_GE(scenes, 7);
}

}  // namespace
}  // namespace mdrsim

namespace mdrsim {
namespace {

// docs/programs.md "How it runs": spring N sits at a_max and is in contact when the indenter
// reaches it, whatever the rounding. The approach to 3 d0 reaches a_max at its very end.
TEST(ProgramRunner, TheApproachEndsWithEveryOneOfItsSprings) {
  const double depth = 3.0 * jkr_scales().depth;
  for (const std::int64_t springs : {1000, 4000, 12345}) {
    const RunResult r = run_scene(cycle_scene(kWork, depth, springs), {});
    ASSERT_GE(r.stages.size(), 1u);
    EXPECT_EQ(r.stages[0].end.springs_in_contact, springs);
  }
}

// Pressed springs carry no tension: once a shear of 4 d0 has broken the glue of the parabola
// glued at 2 a0 (the paper's Fig. 3a, fixed grips), the pull-off lifts them one by one and
// no state is tensile; the last ones sit near the apex at forces of rounding (-2.6e-24 N on
// 1e5 springs, which the zero scale tells from a peak). The glue's jump is the
// instability, at a compressive force (Fig. 3a's positive branch, as the shorthand says),
// not a state of rounding.
TEST(ProgramRunner, NoPeakAndNoCriticalPointFromRounding) {
  const std::string text = R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[[loading.stage]]
name = "preload"
normal = { control = "fixed-grips", to = 2.713782e-5 }
[[loading.stage]]
name = "tangential"
tangential = { control = "fixed-grips", to = 9.04594e-6 }
[[loading.stage]]
name = "pull-off"
normal = { control = "fixed-grips", by = -1.0e-5 }
until = "separation"
[discretization]
springs = 100000
)";
  const RunResult r =
      run_scene(SceneDocument::from_text(text, "sheared.toml").build(Registries::builtin()), {});
  EXPECT_EQ(r.status, RunStatus::instability);
  ASSERT_TRUE(r.critical);
  // F0 = 3/2 pi R dgamma = 2.36e-3 N: the critical force is of its order, far above rounding.
  EXPECT_GT(r.critical->normal_force, 1e-4);
  EXPECT_FALSE(r.peak);
}

}  // namespace
}  // namespace mdrsim
