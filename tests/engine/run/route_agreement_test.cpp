// The two routes of one scene agree: the continuum route (its default rtol 1e-10) and the spring
// row at rtol 1e-8 (method = "event", Richardson and zoomed rows as rtol picks them), on the
// fixed-seed random set of shorthand scenes (engine/reference/random_scenes: every profile but
// the table, every criterion, control and tangential load, drawn numbers). Neither run is the
// other's reference, and both share no code with engine/reference/continuum_reference, against
// which each is held elsewhere (RtolGuarantee, RunContinuum.RandomSetAgreesWithTheReference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/random_scenes.hpp"
#include "engine/run/run_scene.hpp"

namespace mdrsim {
namespace {

RunResult run_text(const std::string& text) {
  return run_scene(test::build_scene_text(text), ObserverList{});
}

// 1e-8 relative, on the critical force and on the peak adhesive force: the row's rtol. Every
// scene of the set must meet it on the row (a row that runs out of springs says so, and would
// fail here: the set is within the row's reach at 1e-8, 120 of 120 measured).
TEST(RouteAgreement, ContinuumAndRowAtRtol1e8AgreeOnTheRandomSet) {
  const std::vector<test::RandomScene> scenes = test::random_scenes(20240611, 120);
  ASSERT_EQ(scenes.size(), 120u);
  double worst = 0.0;
  double worst_peak = 0.0;
  std::string worst_name;
  for (const test::RandomScene& s : scenes) {
    SCOPED_TRACE(s.name);
    const RunResult route =
        run_text(s.toml_without_discretization + "[solver]\nmethod = \"continuum\"\n");
    const RunResult row = run_text(s.toml_without_discretization +
                                   "[solver]\nmethod = \"event\"\n[discretization]\nrtol = 1e-8\n");
    ASSERT_EQ(route.accuracy.route, Accuracy::Route::continuum);
    ASSERT_NE(row.accuracy.route, Accuracy::Route::continuum);
    EXPECT_TRUE(route.accuracy.rtol_met);
    EXPECT_TRUE(row.accuracy.rtol_met) << (row.warnings.empty() ? "" : row.warnings.front());
    EXPECT_EQ(route.status, row.status);
    ASSERT_TRUE(route.critical && row.critical);
    const double f = route.critical->normal_force;
    const double difference = std::abs(row.critical->normal_force - f) / std::abs(f);
    EXPECT_LE(difference, 1e-8) << "row " << row.critical->normal_force << " N, route " << f;
    if (difference > worst) {
      worst = difference;
      worst_name = s.name;
    }
    ASSERT_EQ(route.peak.has_value(), row.peak.has_value());
    if (route.peak) {
      const double p = route.peak->normal_force;
      const double peak_difference = std::abs(row.peak->normal_force - p) / std::abs(p);
      EXPECT_LE(peak_difference, 1e-8) << "row " << row.peak->normal_force << " N, route " << p;
      worst_peak = std::max(worst_peak, peak_difference);
    }
  }
  std::printf("%zu scenes: critical force within %.2g (worst %s), peak within %.2g\n",
              scenes.size(), worst, worst_name.c_str(), worst_peak);
}

}  // namespace
}  // namespace mdrsim
