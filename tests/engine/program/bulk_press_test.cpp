// The press taken in one pass (press_in_bulk in bulk_paths.hpp, ProgramRow::glue_through): a
// program gives the same result as when each spring's glue is an event of its own (which the
// loop does wherever single springs are observed), and the preload's work meets Hertz's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "tests/support/observed_or_not.hpp"

namespace mdrsim {
namespace {

constexpr const char* kHead = R"(
[material]
youngs_modulus = 1.0e6
poisson_ratio = 0.0
work_of_adhesion = 0.05
[profile]
type = "parabolic"
radius = 0.01
[detachment]
criterion = "mode-mixed"
)";

using test::expect_same_state;
using Pair = test::ObservedOrNot;

Pair run_both(const std::string& text) { return test::run_observed_or_not(text); }

/// Every state to the bit; each stage's work, summed per spring in closed form against the
/// loop's trapezoids, within rounding (1e-13 of the largest stage work).
void expect_same_run(const Pair& p) {
  const RunResult& a = p.bulk;
  const RunResult& b = p.one_by_one;
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.counts.events, b.counts.events);
  ASSERT_EQ(a.critical.has_value(), b.critical.has_value());
  if (a.critical) expect_same_state(*a.critical, *b.critical, "critical");
  ASSERT_EQ(a.stages.size(), b.stages.size());
  double scale = 0.0;
  for (const auto& s : b.stages) scale = std::max(scale, std::abs(s.work.normal));
  for (std::size_t i = 0; i < a.stages.size(); ++i) {
    expect_same_state(a.stages[i].end, b.stages[i].end, a.stages[i].name.c_str());
    EXPECT_NEAR(a.stages[i].work.normal, b.stages[i].work.normal, 1e-13 * scale)
        << a.stages[i].name;
    EXPECT_EQ(a.stages[i].work.tangential, b.stages[i].work.tangential) << a.stages[i].name;
  }
  ASSERT_EQ(a.jumps.size(), b.jumps.size());
  for (std::size_t i = 0; i < a.jumps.size(); ++i) {
    expect_same_state(a.jumps[i].critical, b.jumps[i].critical, "jump");
  }
}

// The paper's Fig. 2 path as a program: press to d, pull off until separation. The press's
// work is Hertz's, 8/15 E* a d^2 with a^2 = R d, to the row's O(1/N).
TEST(BulkPress, PaperPathEqualsOneGlueAtATimeAndHertzWork) {
  const double depth = 2.2614848269449475e-6;
  const std::string text =
      std::string(kHead) + "[discretization]\nsprings = 20000\n" +
      "[loading]\n[[loading.stage]]\nname = \"preload\"\nnormal = { control = \"fixed-grips\", "
      "to = 2.2614848269449475e-6 }\n[[loading.stage]]\nname = \"pull-off\"\nnormal = { by = "
      "-2.2614848269449475e-6 }\nuntil = \"separation\"\n";
  const Pair p = run_both(text);
  expect_same_run(p);
  const double radius = std::sqrt(0.01 * depth);
  const double hertz = 8.0 / 15.0 * 1e6 * radius * depth * depth;
  ASSERT_FALSE(p.bulk.stages.empty());
  EXPECT_NEAR(p.bulk.stages.front().work.normal / hertz, 1.0, 2e-4);
  EXPECT_EQ(p.bulk.stages.front().end.springs_in_contact, 20000);
}

// A press on a contact glued and sheared before it: the old springs keep their tangential
// offset (the trapezoid of their force), the new ones glue at the present u_x.
TEST(BulkPress, PressAfterAShearEqualsOneGlueAtATime) {
  const std::string text =
      std::string(kHead) + "[discretization]\nsprings = 4000\n" +
      "[loading]\n[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to "
      "= 1e-6 }\n[[loading.stage]]\nname = \"shear\"\ntangential = { control = \"fixed-grips\", "
      "to = 2e-7 }\n[[loading.stage]]\nname = \"press-more\"\nnormal = { to = 3e-6 }\n"
      "[[loading.stage]]\nname = \"pull-off\"\nnormal = { by = -3e-6 }\nuntil = \"separation\"\n";
  expect_same_run(run_both(text));
}

// A press again after a partial retract, with rebinding (springs that let go glue again) and
// without (they are pressed: the one-pass press does not apply, the loop takes every event).
TEST(BulkPress, PressAgainAfterARetractEqualsOneGlueAtATime) {
  for (const char* rebinding : {"true", "false"}) {
    const std::string text =
        std::string(kHead) + "[discretization]\nsprings = 4000\n" +
        "[loading]\nrebinding = " + rebinding +
        "\n[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to = "
        "2e-6 }\n[[loading.stage]]\nname = \"retract\"\nnormal = { to = -1e-6 }\n"
        "[[loading.stage]]\nname = \"press-again\"\nnormal = { to = 3e-6 }\n";
    SCOPED_TRACE(rebinding);
    expect_same_run(run_both(text));
  }
}

// A wavy sphere's image falls in places: where it does, the one-pass press stops and the loop
// takes the springs that glue together (a jump) one cascade at a time.
TEST(BulkPress, WavyProfileEqualsOneGlueAtATime) {
  const std::string text =
      "[material]\nyoungs_modulus = 1.0e6\npoisson_ratio = 0.0\nwork_of_adhesion = 0.05\n"
      "[profile]\ntype = \"wavy\"\nradius = 0.01\namplitude = 2e-7\nwavelength = 5e-5\n"
      "[discretization]\nsprings = 4000\n"
      "[loading]\n[[loading.stage]]\nname = \"press\"\nnormal = { control = \"fixed-grips\", to "
      "= 4e-6 }\n[[loading.stage]]\nname = \"pull-off\"\nnormal = { by = -4e-6 }\nuntil = "
      "\"separation\"\n";
  const Pair p = run_both(text);
  expect_same_run(p);
  EXPECT_FALSE(p.bulk.jumps.empty());  // the press glued springs together somewhere
}

}  // namespace
}  // namespace mdrsim
