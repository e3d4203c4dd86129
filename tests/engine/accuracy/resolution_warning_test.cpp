// The warnings of a row that does not resolve its critical point: the rule at its edges, and
// programs giving it as the shorthand does.
#include "engine/accuracy/resolution_warning.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/run/run_scene.hpp"
#include "tests/support/program_examples.hpp"

namespace mdrsim {
namespace {

const ResolvedRow kRow{1000, 1e-3, "largest", "more springs"};

RunResult with_critical(std::int64_t springs_in_contact) {
  RunResult r;
  r.critical = ContactSnapshot{};
  r.critical->springs_in_contact = springs_in_contact;
  return r;
}

TEST(ResolutionWarning, BelowOneHundredSpringsAtTheCriticalPoint) {
  EXPECT_TRUE(unresolved_critical(with_critical(99), kRow));
  EXPECT_FALSE(unresolved_critical(with_critical(100), kRow));
  EXPECT_FALSE(unresolved_critical(RunResult{}, kRow));  // no critical point
  // A row of 50 springs all in contact at its critical point resolves what it can.
  EXPECT_FALSE(unresolved_critical(with_critical(50), {50, 1e-3, "glued", "x"}));
}

bool has_warning(const RunResult& r, const std::string& start) {
  for (const std::string& w : r.warnings) {
    if (w.rfind(start, 0) == 0) return true;
  }
  return false;
}

// The reversible cycle's fold is at 0.292 of a_max (a_c/a_max = 9^(-1/3)/1.6465): 3 springs
// on 10, 1 on 2 and 3, with errors of 9 to 169 %.
TEST(ResolutionWarning, ProgramsWarnAsTheShorthandDoes) {
  for (const int springs : {2, 3, 10}) {
    const RunResult r = run_scene(
        test::program_example("jkr_cycle_reversible.toml", "springs = " + std::to_string(springs)),
        {});
    ASSERT_TRUE(r.critical) << springs;
    EXPECT_TRUE(has_warning(r, "the critical point has only")) << springs;
  }
  const RunResult fine =
      run_scene(test::program_example("jkr_cycle_reversible.toml", "springs = 4000"), {});
  EXPECT_TRUE(fine.warnings.empty());  // 1168 springs at the fold
}

// One spring sits at a_max, where the adhesive front glues it short of touch; the first
// spring needs touch, so the row never touches: the run says so.
TEST(ResolutionWarning, AProgramRowThatNeverTouchedSaysSo) {
  const RunResult r =
      run_scene(test::program_example("jkr_cycle_reversible.toml", "springs = 1"), {});
  EXPECT_EQ(r.status, RunStatus::completed);
  EXPECT_TRUE(has_warning(r, "no spring of the row (1 springs")) << r.warnings.size();
}

// A 30 degree cone glued on touch to a = 1e-4 m, pulled through a spring of 50 N/m: the
// contact's stiffness 2 E* a falls to k near a = 2.5e-5 m and the fold's force is -2.6e-8 N
// (rows of 16384 and 65536 springs: -2.610e-8 and -2.570e-8 N, converging as 1/N). On 512
// springs the row ends in a smooth peel: it says the fold below its last spring is unresolved,
// as the shorthand's row does.
TEST(ResolutionWarning, AProgramsSmoothPeelSaysAFoldBelowItIsUnresolved) {
  const auto cone = [](int springs) {
    return run_scene(test::build_scene_text(fmt::format(
                         "[material]\neffective_modulus = 1e6\nwork_of_adhesion = 0.05\n"
                         "[profile]\ntype = \"cone\"\nslope_angle_deg = 30\n[loading]\n"
                         "[[loading.stage]]\nnormal = {{ control = \"fixed-grips\", to = "
                         "9.0690e-5 }}\n[[loading.stage]]\nnormal = {{ control = \"compliant\", "
                         "stiffness = 50.0, by = -1e-4 }}\nuntil = \"separation\"\n"
                         "[discretization]\nsprings = {}\n",
                         springs)),
                     {});
  };
  const RunResult coarse = cone(512);
  EXPECT_EQ(coarse.status, RunStatus::no_instability);
  EXPECT_TRUE(has_warning(coarse, "the contact peeled off down to its last spring"));
  const RunResult fine = cone(16384);
  ASSERT_EQ(fine.status, RunStatus::instability);
  EXPECT_FALSE(has_warning(fine, "the contact peeled off down to its last spring"));
  // Without adhesion nothing folds: a smooth peel is all there is.
  EXPECT_FALSE(unresolved_smooth_peel(coarse, kRow, false));
}

}  // namespace
}  // namespace mdrsim
