// discretization.rtol's zoomed rows: the status they decide is the one the full rows decide.
#include "engine/accuracy/adaptive_resolution.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "engine/pull_off/pull_off.hpp"
#include "engine/run/run_scene.hpp"
#include "tests/support/constant_strength.hpp"

namespace mdrsim {
namespace {

const std::string kCone = "type = \"cone\"\nslope_angle_deg = 10.0\n";

std::string rtol_tail(double rtol) {
  return fmt::format("[solver]\nmethod = \"event\"\n[discretization]\nrtol = {}\n", rtol);
}

// A let-go stretch that stays finite as a -> 0 (the constant strength, e = 1 um) under fixed
// grips: d(a) = g(a) - e falls all the way to a -> 0 and F = E* (nf(a) - 2 a e) -> 0, a smooth
// peel (docs/continuum.md's table; the continuum route and a row of 2000 springs say so). The
// zoom follows it down to 1e-12 of the glued radius on rows of 512 springs. On the parabola
// g sinks there below the rounding of e (a^2/R < 1e-21 m below a ~ 1e-9 m): the rows' let-go
// values tie and their last springs go together at a held value that did not turn. On the
// cone g stays resolved (1e-12 of g(a_g) over 512 springs is 2e3 ulps of e), and each zoomed
// row's last spring carries E* e (A/512), about 1e-3 of the row's own largest force at its
// top A whatever the zoom, and 1e-11 of the run's force scale at the deepest zoom.
TEST(AdaptiveResolution, ConstantStrengthPeelsSmoothlyAtEveryRtol) {
  for (const std::string& profile : {test::kParabolaProfile, kCone}) {
    for (const double rtol : {1e-4, 1e-6, 1e-8}) {
      // The row under rtol, and rtol alone (the route the scene's plan picks).
      for (const std::string& tail :
           {rtol_tail(rtol), fmt::format("[discretization]\nrtol = {}\n", rtol)}) {
        SCOPED_TRACE(profile + tail);
        const RunResult r =
            run_scene(test::constant_strength_scene("fixed-grips", tail, profile), ObserverList{});
        EXPECT_EQ(r.status, RunStatus::no_instability);
        EXPECT_FALSE(r.critical);
        // Nothing to refine and no warning: a deepest zoom read as a jump refines rows of up
        // to 2^25 springs without meeting rtol.
        EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
      }
    }
    const RunResult continuum = run_scene(
        test::constant_strength_scene("fixed-grips", "[solver]\nmethod = \"continuum\"\n", profile),
        ObserverList{});
    EXPECT_EQ(continuum.status, RunStatus::no_instability);
  }
}

// One row of 512 springs, across the glued radius and zoomed to 1e-2 ... 1e-8 of it: the
// same smooth peel, the same status.
TEST(AdaptiveResolution, ZoomedRowsOfASmoothPeelSayNoInstability) {
  const Scene scene = test::constant_strength_scene("fixed-grips", rtol_tail(1e-6), kCone);
  for (const double share : {1.0, 1e-2, 1e-4, 1e-6, 1e-8}) {
    SCOPED_TRACE(share);
    const RunResult row = run_row(
        scene, {.springs = 512, .outer_radius = share * scene.glued_radius, .zoomed = share < 1.0},
        {});
    EXPECT_EQ(row.status, RunStatus::no_instability);
  }
}

// The same peel as a program (pressed to d = 1e-4 m, then retracted under fixed grips until
// separation): its rows span the largest contact and its status is the loss's on the run's
// force scale; rtol 1e-4 and 1e-6 and the continuum route say no-instability (1e-8 too, in 3 s
// of rows refined for the path's work).
TEST(AdaptiveResolution, ConstantStrengthProgramPeelsSmoothly) {
  const std::string stages =
      "[[loading.stage]]\nname = \"approach\"\nnormal = { control = \"fixed-grips\", to = 1e-4 }\n"
      "[[loading.stage]]\nname = \"retract\"\nnormal = { control = \"fixed-grips\", by = -1e-4 "
      "}\nuntil = \"separation\"\n";
  for (const std::string& profile : {test::kParabolaProfile, kCone}) {
    for (const std::string& tail :
         {rtol_tail(1e-4), rtol_tail(1e-6), std::string("[solver]\nmethod = \"continuum\"\n")}) {
      SCOPED_TRACE(profile + tail);
      const RunResult r =
          run_scene(test::constant_strength_text(stages + tail, profile), ObserverList{});
      EXPECT_EQ(r.status, RunStatus::no_instability);
      EXPECT_FALSE(r.critical);
      for (const auto& w : r.warnings) ADD_FAILURE() << w;
    }
  }
}

// A flat punch under the constant strength: every spring at the same let-go value d = -e, so
// the row's first let-go takes the whole contact at once, F = -2 E* A e. The control never
// fell: the continuum route's fold at the glued radius (its slope is not positive there), an
// instability on every route, not the tie of a falling branch.
TEST(AdaptiveResolution, FlatPunchUnderAConstantStrengthJumpsAtOnce) {
  const std::string punch = "type = \"flat_punch\"\nradius = 1e-3\n";
  for (const std::string& tail :
       {std::string("[solver]\nmethod = \"event\"\n[discretization]\nsprings = 2000\n"),
        rtol_tail(1e-6), std::string("[solver]\nmethod = \"continuum\"\n")}) {
    SCOPED_TRACE(tail);
    const RunResult r =
        run_scene(test::constant_strength_scene("fixed-grips", tail, punch), ObserverList{});
    EXPECT_EQ(r.status, RunStatus::instability);
    ASSERT_TRUE(r.critical);
    // F = -2 E* A e = -2e-3 N, to the row's own rounding.
    EXPECT_NEAR(r.critical->normal_force, -2.0 * 1e6 * 1e-3 * 1e-6, 1e-12);
  }
}

}  // namespace
}  // namespace mdrsim
