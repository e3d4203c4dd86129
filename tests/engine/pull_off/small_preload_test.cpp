// A preload too small to reach the equilibrium branch: below the fold radius the pull-off force
// depends on the preload, above it it does not.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"
#include "tests/support/pull_off_runs.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::RunResult;
using mdrsim::RunStatus;
using mdrsim::test::JkrScenario;
using mdrsim::test::run_quietly;
using mdrsim::test::scenario;

// The stable branch ends at the fold radius: a0 under fixed load (eq. 29 at u = 0), (1/9)^(1/3)
// a0 under fixed grips (eq. 31), in between for a compliant machine. Glued at a smaller
// radius, the contact never reaches it: its first let-go starts the final cascade, at the
// branch force of its own radius (eq. 19), F/F0 = a^3 - 2 a^(3/2). So below the fold radius
// the pull-off force depends on the preload (and is weaker than the plateau); above it, it
// does not. Checked along a curve of glued radii, 10^4 springs, 2e-3 as for Fig. 3a.
TEST(SmallPreload, PullOffDependsOnThePreloadBelowTheFoldRadius) {
  for (const char* normal : {"fixed-load", "fixed-grips", "compliant"}) {
    const auto fold = std::string(normal) == "fixed-load"    ? ref::fixed_load_critical(0.0)
                      : std::string(normal) == "fixed-grips" ? ref::fixed_grips_critical(0.0)
                                                             : ref::compliant_critical(1.0);
    std::vector<double> below;
    for (const double glued : {0.1, 0.2, 0.3, 0.4, 0.45, 0.6, 0.8, 0.95, 1.1, 1.5, 2.0, 3.0}) {
      JkrScenario s = scenario(normal, 10000);
      s.glued_radius = glued;
      const RunResult r = run_quietly(s.build());
      ASSERT_EQ(r.status, RunStatus::instability) << normal << " " << glued;
      const double got = r.critical->normal_force / s.scales().force;
      if (glued < fold.contact_radius) {
        EXPECT_EQ(r.critical->springs_in_contact, s.springs) << normal << " " << glued;
        EXPECT_NEAR(got, ref::normal_force(glued), 2e-3) << normal << " " << glued;
        below.push_back(got);
      } else {
        EXPECT_NEAR(got, fold.normal_force, 2e-3) << normal << " " << glued;
      }
    }
    // The dependence is real: each smaller preload gives a weaker pull-off, by more than the
    // tolerance, and all are weaker than the plateau.
    ASSERT_GE(below.size(), 2u) << normal;
    for (std::size_t i = 1; i < below.size(); ++i) EXPECT_LT(below[i], below[i - 1] - 4e-3);
    EXPECT_GT(below.back(), fold.normal_force);
  }
}
