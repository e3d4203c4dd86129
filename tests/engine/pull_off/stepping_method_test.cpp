// The stepping method at the fold: its halving ends, and its critical point lies within the
// finest step of the event method's, whatever the step and the halvings, even below the
// resolution of the control value.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "engine/events/event_recorder.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "tests/support/pull_off_runs.hpp"

using mdrsim::Event;
using mdrsim::EventKind;
using mdrsim::RunResult;
using mdrsim::RunStatus;
using mdrsim::Scene;
using mdrsim::test::force_per_control;
using mdrsim::test::JkrScenario;
using mdrsim::test::rounding;
using mdrsim::test::run_quietly;
using mdrsim::test::run_tracked;
using mdrsim::test::scenario;
using mdrsim::test::TrackedRun;

namespace {

std::string fmt_step(double step, int max_halvings) {
  return fmt::format("step = {:.17g}\nmax_halvings = {}", step, max_halvings);
}

}  // namespace

/// The equilibrium of the exact path (the event method's) at control value `control`: springs
/// whose let-go control is >= it are gone; with n springs attached the force is linear in the
/// control, so it follows from the next spring's let-go state by one product.
struct PathState {
  std::int64_t springs;
  double normal_force;
};

PathState exact_path_at(const Scene& scene, const std::vector<Event>& events, double control) {
  std::int64_t springs = scene.springs;
  for (const Event& e : events) {
    if (e.kind != EventKind::spring_detached || e.state.normal_control < control) continue;
    springs = std::min(springs, e.spring - 1);
  }
  for (const Event& e : events) {
    if (e.kind == EventKind::spring_detached && e.spring == springs) {
      return {springs, e.state.normal_force +
                           force_per_control(scene, springs) * (control - e.state.normal_control)};
    }
  }
  return {springs, 0.0};
}

// At the fold every step, however small, detaches the boundary spring and the cascade behind
// it; the method halves max_halvings times and then accepts the step with its cascade, so a
// run always ends. Its critical point is the state before that step. The state at a control
// value does not depend on how the control got there (springs only let go, in order), so:
// - the stepping critical state is the exact path's equilibrium at the same control value c_s
//   (same springs, same force up to rounding: 1e-9 F0);
// - the event method's critical control c_e and c_s obey c_e <= c_s <= c_e + finest step: the
//   step before c_s kept the contact, the one after emptied it (tolerance: rounding of the
//   control values, 8 eps);
// - with the same springs as the event critical point the forces differ by dF/dw times the
//   finest step at most. With coarse steps the stepping may stop a few springs earlier (the
//   fixed-grips fold is flat, docs/accuracy.md); its force then differs by the sawtooth, not a
//   defect: the point is still an exact equilibrium within one finest step of the fold.
// All of this holds for any base step, also for max_halvings = 0 (no halving at all, every
// step accepted with what it detaches).
class FoldUnderStepping
    : public ::testing::TestWithParam<std::tuple<std::string, double, int, double>> {};

TEST_P(FoldUnderStepping, HalvingEndsAndTheCriticalPointIsWithinTheFinestStep) {
  const auto& [normal, step_fraction, max_halvings, u] = GetParam();
  JkrScenario s = scenario(normal, 2000);
  if (u > 0.0) s.tangential_displacement = u;
  const Scene event_scene = s.build();
  mdrsim::EventRecorder recorder;
  mdrsim::ObserverList observers;
  observers.add(recorder);
  const RunResult event = mdrsim::run_pull_off(event_scene, observers);
  ASSERT_EQ(event.status, RunStatus::instability);

  const double step = step_fraction * std::abs(recorder.events().front().state.normal_control);
  s.method = "stepping";
  s.solver_extra = fmt_step(step, max_halvings);
  const Scene scene = s.build();
  const TrackedRun stepping = run_tracked(scene);
  ASSERT_EQ(stepping.result.status, RunStatus::instability);
  // Halving ends: never more than max_halvings in a row, and the run-ending step needed all.
  EXPECT_LE(stepping.result.counts.halvings,
            static_cast<std::int64_t>(max_halvings) * stepping.result.counts.steps);
  EXPECT_EQ(stepping.tracker.halvings_before_last_step(), max_halvings);

  ASSERT_TRUE(stepping.result.critical.has_value());
  const auto& got = *stepping.result.critical;
  const PathState exact = exact_path_at(event_scene, recorder.events(), got.normal_control);
  EXPECT_EQ(got.springs_in_contact, exact.springs);
  EXPECT_NEAR(got.normal_force, exact.normal_force, 1e-9 * s.scales().force);

  const double finest = std::ldexp(step, -max_halvings);
  const double above = got.normal_control - event.critical->normal_control;
  const double slack = rounding(event.critical->normal_control);
  EXPECT_GE(above, -slack);
  EXPECT_LE(above, finest * (1.0 + 1e-9) + slack);
  EXPECT_GE(got.springs_in_contact, event.critical->springs_in_contact);
  if (got.springs_in_contact == event.critical->springs_in_contact) {
    EXPECT_NEAR(got.normal_force, event.critical->normal_force,
                force_per_control(scene, got.springs_in_contact) * finest * (1.0 + 1e-9) + 1e-15);
  }
}

INSTANTIATE_TEST_SUITE_P(
    StepsAndHalvings, FoldUnderStepping,
    ::testing::Combine(::testing::Values("fixed-load", "fixed-grips", "compliant"),
                       ::testing::Values(1e-1, 1e-3, 1e-5), ::testing::Values(0, 1, 8, 30),
                       ::testing::Values(0.0, 3.0)));

// At the default step (1e-3 of the preload control) and max_halvings 30, the stepping stops at
// the event method's critical spring: the finest step, 1e-3 * 2^-30 of the preload control, is
// far below the let-go spacing of neighbouring springs at the fold.
TEST(FoldUnderSteppingDefaults, StopsAtTheSameSpringAsTheEventMethod) {
  for (const char* normal : {"fixed-load", "fixed-grips", "compliant"}) {
    JkrScenario s = scenario(normal, 2000);
    const RunResult event = run_quietly(s.build());
    s.method = "stepping";
    const RunResult stepping = run_quietly(s.build());
    EXPECT_EQ(stepping.critical->springs_in_contact, event.critical->springs_in_contact) << normal;
  }
}

// The same at max_halvings = 45 and 60 (allowed: 0..60). With the default step (1e-3 of the
// preload value) the halved step falls below the control value's resolution near 47 halvings:
// a trial that cannot move the control must not be taken (it would detach nothing, be
// accepted, and the base step would cross the fold again forever, ending only at max_steps
// with step-limit, about 10 min at the default 1e8). Expected: instability at the fold, the
// halving ending where a further halving could not move the control, so the critical point is
// the event method's to rounding (1e-12 of the control). max_steps = 1e5 keeps a regression
// quick.
TEST(FoldUnderSteppingBelowTheControlResolution, HalvingEndsAtTheFold) {
  for (const char* normal : {"fixed-load", "fixed-grips"}) {
    for (const int max_halvings : {45, 60}) {
      JkrScenario s = scenario(normal, 2000);
      const TrackedRun event = run_tracked(s.build());
      s.method = "stepping";
      s.solver_extra = "max_halvings = " + std::to_string(max_halvings) + "\nmax_steps = 100000";
      const RunResult r = run_quietly(s.build());
      ASSERT_EQ(r.status, RunStatus::instability) << normal << " " << max_halvings;
      EXPECT_EQ(r.critical->springs_in_contact, event.result.critical->springs_in_contact);
      EXPECT_NEAR(r.critical->normal_control, event.result.critical->normal_control,
                  1e-12 * std::abs(event.result.critical->normal_control));
    }
  }
}

// A base step below the resolution of the control value (1e-30 N against a preload of about
// 0.02 N) moves it by one ulp per step, since a step never rounds to no movement: reaching the
// fold would take some 10^16 steps, so the run ends at max_steps with status step-limit and
// no critical point (docs: none was found), with a warning. That is the documented outcome of
// an exhausted step budget, not a hang.
TEST(EdgeCases, SteppingBelowTheControlResolutionEndsAtTheStepLimit) {
  JkrScenario s = scenario("fixed-load", 200);
  s.method = "stepping";
  s.solver_extra = "step = 1e-30\nmax_steps = 1000";
  const RunResult r = run_quietly(s.build());
  EXPECT_EQ(r.status, RunStatus::step_limit);
  EXPECT_EQ(r.counts.steps, 1000);
  EXPECT_FALSE(r.critical.has_value());
  EXPECT_EQ(r.counts.events, 0);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            "the stepping method reached solver.max_steps = 1000 before the contact was lost: "
            "there is no critical point");
}
