// The warnings of a row that does not resolve its critical point: the rule at its edges, and
// programs giving it as the shorthand does.
#include "engine/run/resolution_warning.hpp"

#include <gtest/gtest.h>

#include <string>

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
// on 10, 1 on 2 and 3, with errors of 9 to 169 % (issue 19).
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

}  // namespace
}  // namespace mdrsim
