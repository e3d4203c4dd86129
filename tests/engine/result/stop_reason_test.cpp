// How a run stopped (stop_reason.hpp): each reason a step-limit can have, provoked by a small
// scene, in the result, the JSON, the summary and the sweep row; none beside another status.
#include "engine/result/stop_reason.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "engine/output/result_json.hpp"
#include "engine/output/run_summary.hpp"
#include "engine/output/sweep_csv.hpp"
#include "engine/program/program_runner.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "engine/sweep/sweep_grid.hpp"
#include "engine/sweep/vary_spec.hpp"

namespace mdrsim {
namespace {

/// A JKR approach-retract cycle of a parabola under fixed grips (R = 1 cm, E* = 1 MPa,
/// dgamma = 0.05 J/m^2, to 3 d0 and back until separation), with `solver` as its [solver].
std::string cycle(std::string_view solver) {
  return std::string(
             "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
             "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
             "[[loading.stage]]\nname = \"approach\"\n"
             "normal = { control = \"fixed-grips\", to = 6.78e-6 }\n"
             "[[loading.stage]]\nname = \"retract\"\nnormal = { by = -1.0e-6 }\n"
             "until = \"separation\"\n[discretization]\nsprings = 200\n[solver]\n") +
         std::string(solver);
}

RunResult run(const Scene& scene) { return run_scene(scene, ObserverList{}); }

/// The run's status and reason, as the JSON writes them.
void expect_stop(const Scene& scene, const RunResult& r, StopReason reason) {
  EXPECT_EQ(r.status, RunStatus::step_limit);
  ASSERT_TRUE(r.stop_reason.has_value());
  EXPECT_EQ(*r.stop_reason, reason) << to_string(*r.stop_reason);
  const auto j = result_to_json(scene, r);
  EXPECT_EQ(j["status"], "step-limit");
  EXPECT_EQ(j["stop_reason"], to_string(reason));
}

TEST(StopReason, NamesAreKebabCase) {
  EXPECT_STREQ(to_string(StopReason::outgrew_row), "outgrew-row");
  EXPECT_STREQ(to_string(StopReason::max_steps), "max-steps");
  EXPECT_STREQ(to_string(StopReason::max_events), "max-events");
  EXPECT_STREQ(to_string(StopReason::max_events_per_spring), "max-events-per-spring");
  EXPECT_STREQ(to_string(StopReason::overflow), "overflow");
  EXPECT_STREQ(to_string(StopReason::unending_cascade), "unending-cascade");
  EXPECT_STREQ(to_string(StopReason::no_end), "no-end");
}

TEST(StopReason, PullOffAtMaxSteps) {
  test::JkrScenario s;
  s.springs = 200;
  s.method = "stepping";
  s.solver_extra = "max_steps = 5";
  const Scene scene = s.build();
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::max_steps);
  EXPECT_EQ(r.counts.steps, 5);
}

TEST(StopReason, PullOffAtMaxEvents) {
  test::JkrScenario s;
  s.springs = 200;
  s.solver_extra = "max_events = 10";
  const Scene scene = s.build();
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::max_events);
  EXPECT_EQ(r.counts.events, 10);
  EXPECT_FALSE(r.critical);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "the row reached solver.max_events = 10 before the contact was lost: there is no "
            "critical point");
}

TEST(StopReason, ProgramAtMaxSteps) {
  const Scene scene = test::build_scene_text(cycle("method = \"stepping\"\nmax_steps = 5\n"));
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::max_steps);
  EXPECT_FALSE(r.critical);
}

TEST(StopReason, ProgramAtMaxEvents) {
  const Scene scene = test::build_scene_text(cycle("method = \"event\"\nmax_events = 10\n"));
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::max_events);
  // The loop looks at its limits between cascades: it stops at the first one past the limit.
  EXPECT_GE(r.counts.events, 10);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.back(),
            "the row reached solver.max_events = 10 in stage 'approach' before the program's "
            "end: the program stops here");
}

// A fixed-load shear ramp to 2e13 N with rebinding slips without end
// (tests/fuzz/regressions/program_stick_slip_under_a_huge_tangential_load.toml): the stage stops
// at its events-per-spring limit, here 2 instead of 64, so that it stops early.
TEST(StopReason, ProgramAtMaxEventsPerSpring) {
  const Scene scene = test::build_scene_text(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.05\n"
      "approach_work_of_adhesion = 0.02\n[profile]\ntype = \"parabolic\"\nradius = 6.01\n"
      "[loading]\nrebinding = true\n"
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-load\", to = 0.01 }\n"
      "[[loading.stage]]\nname = \"shear\"\n"
      "tangential = { control = \"fixed-load\", by = 2e13 }\n"
      "[[loading.stage]]\nname = \"unload\"\nnormal = { to = -0.001 }\n"
      "[discretization]\nsprings = 500\n[solver]\nmax_events_per_spring = 2\n");
  EXPECT_EQ(scene.solver.max_events_per_spring, 2);
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::max_events_per_spring);
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_EQ(r.stages.back().name, "shear");
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.back().rfind(
                "stage 'shear' changed its spring row more than solver.max_events_per_spring = 2 "
                "times per spring (",
                0),
            0u)
      << r.warnings.back();
}

// Without adhesion and friction, a tangential ramp moves nothing on a pressed contact: a stage
// until separation has no end.
TEST(StopReason, ProgramWithNoEnd) {
  const Scene scene = test::build_scene_text(
      "[material]\neffective_modulus = 1.0e6\nwork_of_adhesion = 0.0\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = 1e-5 }\n"
      "[[loading.stage]]\nname = \"shear\"\n"
      "tangential = { control = \"fixed-grips\", by = 1e-6 }\nuntil = \"separation\"\n"
      "[discretization]\nsprings = 100\n");
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::no_end);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(r.warnings.back(),
            "stage 'shear' runs until separation, but nothing on its path can part the contact "
            "(100 springs in contact): the program stops here");
}

// tests/fuzz/regressions/program_values_beyond_a_double.toml.
TEST(StopReason, ProgramBeyondADouble) {
  const Scene scene = test::build_scene_text(
      "[material]\neffective_modulus = 1.0e300\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"parabolic\"\nradius = 0.01\n"
      "[[loading.stage]]\nnormal = { to = 1e200 }\n"
      "[[loading.stage]]\nnormal = { by = -1e200 }\nuntil = \"separation\"\n"
      "[discretization]\nsprings = 100\n");
  const RunResult r = run(scene);
  expect_stop(scene, r, StopReason::overflow);
  EXPECT_FALSE(r.critical);
}

// run_scene frames a program's rows on the largest contact its pilot finds, so that they do not
// outgrow; a row of its own whose end comes first does, here in the cascade of the reversible
// JKR jump-in at d = 0 (dgamma_a = dgamma: out to 1.2114 a0 = 3.16e-4 m, about 210 springs).
TEST(StopReason, ProgramRowOutgrowsItsEnd) {
  std::string text = cycle("method = \"event\"\n");
  text.insert(text.find("[profile]"), "approach_work_of_adhesion = 0.05\n");
  const Scene scene = test::build_scene_text(text);
  const double radius = 1.5e-4;
  const ProgramRowSpec spec{.reference_radius = radius,
                            .reference_springs = 100,
                            .reference_image = scene.profile->mdr_image(radius),
                            .max_springs = 100};
  const RunResult r = run_program_row(scene, spec, ObserverList{});
  expect_stop(scene, r, StopReason::outgrew_row);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_EQ(
      r.warnings.back().rfind("stage 'approach': the contact outgrew the row of 100 springs", 0),
      0u)
      << r.warnings.back();
}

TEST(StopReason, OnlyAStepLimitHasOne) {
  const Scene scene = test::build_scene_text(cycle("method = \"event\"\n"));
  const RunResult r = run(scene);
  EXPECT_EQ(r.status, RunStatus::instability);
  EXPECT_FALSE(r.stop_reason);
  EXPECT_FALSE(result_to_json(scene, r).contains("stop_reason"));
  test::JkrScenario s;
  s.springs = 200;
  const Scene shorthand = s.build();
  const RunResult pulled = run(shorthand);
  EXPECT_EQ(pulled.status, RunStatus::instability);
  EXPECT_FALSE(pulled.stop_reason);
  EXPECT_FALSE(result_to_json(shorthand, pulled).contains("stop_reason"));
}

/// What print_summary writes.
std::string summary(const Scene& scene, const RunResult& r) {
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&text, &size);
  cli::print_summary(out, scene, r);
  std::fclose(out);
  std::string s(text, size);
  std::free(text);
  return s;
}

TEST(StopReason, TheSummaryAndTheSweepRowNameIt) {
  test::JkrScenario s;
  s.springs = 200;
  s.method = "stepping";
  s.solver_extra = "max_steps = 5";
  const Scene scene = s.build();
  const RunResult r = run(scene);
  EXPECT_EQ(
      summary(scene, r).rfind("status: step-limit, stop reason max-steps (normal fixed-load", 0),
      0u)
      << summary(scene, r);
  const cli::SweepGrid grid({cli::parse_vary("material.poisson_ratio=0")});
  EXPECT_EQ(cli::csv_header(grid, {}).rfind("status,stop_reason,material.poisson_ratio,", 0), 0u);
  EXPECT_EQ(cli::csv_row(grid.values(0), scene, r, {}).rfind("step-limit,max-steps,0,", 0), 0u);
  // Another status leaves the column empty.
  s.method = "event";
  s.solver_extra = "";
  const Scene plain = s.build();
  const RunResult instability = run(plain);
  EXPECT_EQ(summary(plain, instability).rfind("status: instability (normal fixed-load", 0), 0u);
  EXPECT_EQ(cli::csv_row(grid.values(0), plain, instability, {}).rfind("instability,,0,", 0), 0u);
}

}  // namespace
}  // namespace mdrsim
