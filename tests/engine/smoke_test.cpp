// Placeholder removed once real engine tests exist.
#include <gtest/gtest.h>

#include "tests/support/jkr_scenario.hpp"

TEST(Smoke, JkrFixedLoadRuns) {
  const mdrsim::test::JkrScenario s;
  const auto r = mdrsim::test::run_quietly(s.build());
  EXPECT_NEAR(r.critical.normal_force / s.scales().force, -1.0, 1e-3);
}
