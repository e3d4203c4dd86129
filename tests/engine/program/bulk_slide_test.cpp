// A friction ramp taken in bulk (slide_in_bulk in bulk_paths.hpp): where nobody observes single
// slips, a tangential ramp under fixed grips at a still normal load applies the friction row's
// events without the rest of the loop. Its result must be the loop's to the bit (the loop
// takes every event where slips are observed), and its events those the loop emits.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/observed_or_not.hpp"

namespace mdrsim {
namespace {

std::string scene_file(const std::string& name) {
  std::ifstream in(std::string(MDRSIM_SOURCE_DIR) + "/scenes/programs/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

using test::expect_same_state;

struct Pair {
  test::ObservedOrNot runs;
  std::int64_t friction_events = 0;  ///< slips and sticks the observer saw
};

Pair run_both(const std::string& text) {
  Pair p{test::run_observed_or_not(text)};
  for (const Event& e : p.runs.recorder.events()) {
    if (e.kind == EventKind::spring_slipped || e.kind == EventKind::spring_stuck) {
      ++p.friction_events;
    }
  }
  return p;
}

/// Every reported state, work and count to the bit, and a run with friction events in it (a
/// scene without any would show nothing of the bulk) unless `some_events` is false.
void expect_same_run(const Pair& p, bool some_events = true) {
  const RunResult& a = p.runs.bulk;
  const RunResult& b = p.runs.one_by_one;
  if (some_events) {
    EXPECT_GT(p.friction_events, 100);
  }
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.sliding, b.sliding);
  EXPECT_EQ(a.counts.events, b.counts.events);
  ASSERT_EQ(a.critical.has_value(), b.critical.has_value());
  if (a.critical) expect_same_state(*a.critical, *b.critical, "critical");
  ASSERT_EQ(a.peak.has_value(), b.peak.has_value());
  if (a.peak) expect_same_state(*a.peak, *b.peak, "peak");
  ASSERT_EQ(a.stages.size(), b.stages.size());
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    const std::string& name = a.stages[i].name;
    expect_same_state(a.stages[i].end, b.stages[i].end, name);
    EXPECT_EQ(a.stages[i].work.normal, b.stages[i].work.normal) << name;
    EXPECT_EQ(a.stages[i].work.tangential, b.stages[i].work.tangential) << name;
    EXPECT_EQ(a.stages[i].work.friction, b.stages[i].work.friction) << name;
  }
  ASSERT_EQ(a.jumps.size(), b.jumps.size());
  for (std::size_t i = 0; i < a.jumps.size(); ++i) {
    expect_same_state(a.jumps[i].critical, b.jumps[i].critical, "jump critical");
    expect_same_state(a.jumps[i].after, b.jumps[i].after, "jump after");
  }
}

// Cattaneo-Mindlin loading, Mindlin-Deresiewicz unloading and reloading under a held normal
// force: each reversal sticks every slider at once, then the springs slip one by one.
TEST(BulkSlide, FrettingLoopEqualsTheLoop) {
  expect_same_run(run_both(scene_file("fretting_parabola.toml")));
}

// The glue peels and breaks in the ramp (the loop's), and the ramp back slides in bulk. With
// rebinding a sliding spring may glue again, which only the loop follows: the ramp ends in full
// sliding there, and the ramp back, whose reversal sticks springs that then glue, is left out
// (the bulk does not stop for a glue a stick allows).
TEST(BulkSlide, AdhesionToFrictionEqualsTheLoop) {
  for (const char* name :
       {"adhesion_to_friction_chi_below.toml", "adhesion_to_friction_chi_above.toml"}) {
    SCOPED_TRACE(name);
    // Sheared back after the break: the glue is gone by then, and the reversal's sticks and
    // slips are the bulk's.
    std::string rebinding = scene_file(name);
    std::string text = rebinding;
    text.insert(text.find("[friction]"),
                "[[loading.stage]]\nname = \"back\"\ntangential = { by = -6.0e-5 }\n\n");
    expect_same_run(run_both(text));
    rebinding.insert(rebinding.find("[[loading.stage]]"), "[loading]\nrebinding = true\n");
    expect_same_run(run_both(rebinding), false);
  }
}

// A cone under fixed grips on both axes, sheared back and forth past full sliding between two
// presses (the normal moves in its own stages: those are the loop's), on an odd spring count.
TEST(BulkSlide, ConeShearedBackAndForthBetweenPressesEqualsTheLoop) {
  const std::string text = R"(
[material]
youngs_modulus = 2.0e6
poisson_ratio = 0.3
work_of_adhesion = 0.0
[profile]
type = "cone"
slope_angle_deg = 10.0
[[loading.stage]]
name = "press"
normal = { control = "fixed-grips", to = 2.0e-5 }
[[loading.stage]]
name = "forth"
tangential = { control = "fixed-grips", to = 3.0e-5 }
[[loading.stage]]
name = "back"
tangential = { to = -1.0e-5 }
[[loading.stage]]
name = "press-more"
normal = { to = 3.0e-5 }
[[loading.stage]]
name = "forth-again"
tangential = { to = 2.0e-5 }
[friction]
coefficient = 0.3
[discretization]
springs = 3001
)";
  expect_same_run(run_both(text));
}

}  // namespace
}  // namespace mdrsim
