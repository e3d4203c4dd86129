// The closing events of a run (emit_closing_events, pull_off.hpp): where the run ended.
#include <gtest/gtest.h>

#include "engine/events/event_recorder.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

// A run stopped at solver.max_steps has no critical point: its `finished` event (the last
// line of the log) carries the state where it stopped, the pull-off stage's end, not the
// undeformed start (all zeros, as the log printed before).
TEST(ClosingEvents, StepLimitFinishesWhereTheRunStopped) {
  test::JkrScenario s;
  s.springs = 1000;
  s.method = "stepping";
  s.solver_extra = "max_steps = 20";
  const Scene scene = s.build();
  EventRecorder recorder;
  ObserverList observers;
  observers.add(recorder);
  const RunResult r = run_scene(scene, observers);
  ASSERT_EQ(r.status, RunStatus::step_limit);
  ASSERT_FALSE(r.critical);
  ASSERT_FALSE(r.stages.empty());
  ASSERT_FALSE(recorder.events().empty());
  const Event& last = recorder.events().back();
  EXPECT_EQ(last.kind, EventKind::finished);
  EXPECT_EQ(last.status, RunStatus::step_limit);
  // Twenty steps of 1e-3 of the control's scale leave the glued contact in place, the held
  // force 2 % below the preload's.
  EXPECT_EQ(last.state.springs_in_contact, 1000);
  EXPECT_LT(last.state.normal_force, r.stages.front().end.normal_force);
  EXPECT_EQ(last.state.indentation, r.stages.back().end.indentation);
  EXPECT_EQ(last.state.normal_force, r.stages.back().end.normal_force);
}

}  // namespace
}  // namespace mdrsim
