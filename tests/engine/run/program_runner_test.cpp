// The program engine on scenes built in code: the reversible JKR cycle against its closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "controllers/builtin_controllers.hpp"
#include "detachment/mode_mixed_criterion.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "engine/run/run_scene.hpp"
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
  // 0.9355 F0 |d_c| (derived in tests/support/program_reference.cpp); O(1/N) at N = 4000.
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

}  // namespace
}  // namespace mdrsim
