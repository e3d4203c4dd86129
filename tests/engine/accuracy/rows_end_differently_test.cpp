// The warning of rows that end differently (program_resolution.cpp) says where they part,
// in one short phrase, instead of listing every jump of every row.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

// A stick-slip program (207 jumps at 1000 springs) whose rows of 250, 500 and 1000 springs
// end with different jumps: listing them would take 6 KB, three lists of "pull:out" most of
// them alike. A phrase naming the rows and the first item apart fits in 400 characters.
TEST(RowsEndDifferently, WarningNamesWhereTheRowsPart) {
  std::ifstream in(
      std::string(MDRSIM_SOURCE_DIR) +
      "/tests/fuzz/regressions/program_stick_slip_until_separation_under_compression.toml");
  std::ostringstream text;
  text << in.rdbuf();
  const Scene scene =
      test::build_scene_text(text.str() + "extrapolation = \"richardson\"\n");  // [discretization]
  const RunResult r = run_scene(scene, {});
  bool found = false;
  for (const std::string& w : r.warnings) {
    if (w.find("end differently") == std::string::npos) continue;
    found = true;
    EXPECT_LT(w.size(), 400u) << w;
    EXPECT_NE(w.find("first apart between"), std::string::npos) << w;
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace mdrsim
