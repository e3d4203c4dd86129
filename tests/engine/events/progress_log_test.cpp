// The interrupt check of a run's progress path (Python's Ctrl-C): called every 65536 events or
// so on this thread only, and a check that throws stops the run.
#include "engine/events/progress_log.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <thread>

#include "engine/run/run_scene.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim::test {
namespace {

int checks = 0;  // NOLINT: the check is a plain function pointer
int stop_after = 0;

void counting_check() {
  if (++checks == stop_after) throw std::runtime_error("interrupted");
}

Scene scene_of(const std::string& file, const std::string& springs) {
  SceneDocument document = SceneDocument::from_file(std::string(MDRSIM_SOURCE_DIR) + file);
  document.set_value("discretization.springs", springs);
  // One row, so that the events are the springs' (the Fig. 2 scenes extrapolate three rows).
  document.set_value("discretization.extrapolation", "\"none\"");
  return document.build(Registries::builtin());
}

struct Installed {
  explicit Installed(int after) {
    checks = 0;
    stop_after = after;
    interrupt_check = &counting_check;
  }
  ~Installed() { interrupt_check = nullptr; }
};

TEST(InterruptCheck, CalledEvery65536EventsOfAPullOff) {
  // 400,000 springs, one event each (fixed load, event method): 6 checks of 65536.
  const Scene scene = scene_of("/scenes/fig2_fixed_load.toml", "400000");
  const Installed installed(0);
  const RunResult result = run_scene(scene, {});
  EXPECT_EQ(result.status, RunStatus::instability);
  EXPECT_GE(checks, 3);
  EXPECT_LE(checks, 400000 / 65536 + 1);
}

TEST(InterruptCheck, AThrowStopsAPullOffAndAProgram) {
  for (const char* file :
       {"/scenes/fig2_fixed_load.toml", "/scenes/programs/jkr_cycle_glue_on_touch.toml"}) {
    const Scene scene = scene_of(file, "1000000");
    const Installed installed(2);
    EXPECT_THROW(run_scene(scene, {}), std::runtime_error) << file;
    EXPECT_EQ(checks, 2) << file;
  }
}

TEST(InterruptCheck, OnlyOnTheThreadThatInstalledIt) {
  const Scene scene = scene_of("/scenes/fig2_fixed_load.toml", "400000");
  const Installed installed(1);
  std::thread other([&] { EXPECT_EQ(run_scene(scene, {}).status, RunStatus::instability); });
  other.join();
  EXPECT_EQ(checks, 0);
}

}  // namespace
}  // namespace mdrsim::test
