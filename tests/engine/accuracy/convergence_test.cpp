// Convergence of the critical force with springs.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "engine/reference/jkr_scenario.hpp"
#include "engine/reference/parabolic_reference.hpp"

namespace ref = mdrsim::parabolic_reference;
using mdrsim::test::JkrScenario;

namespace {

double critical_force_error(const std::string& normal, std::int64_t springs, double u = 0.0) {
  JkrScenario s;
  s.normal = normal;
  s.springs = springs;
  if (u > 0) s.tangential_displacement = u;
  const auto r = mdrsim::test::run_quietly(s.build());
  const double exact = normal == "fixed-load" ? ref::fixed_load_critical(u).normal_force
                                              : ref::fixed_grips_critical(u).normal_force;
  return std::abs(r.critical->normal_force / s.scales().force - exact);
}

}  // namespace

// Under fixed load the error is a smooth O(1/springs) term: the estimated order
// log10(e(N)/e(10 N)) over 100, 1000, 10000 springs is 1 (DiffEqDevTools' habit of asserting
// the order, not one error).
TEST(Convergence, FixedLoadErrorShrinksLikeOneOverSprings) {
  for (const double u : {0.0, 2.0}) {
    const double e100 = critical_force_error("fixed-load", 100, u);
    const double e1000 = critical_force_error("fixed-load", 1000, u);
    const double e10000 = critical_force_error("fixed-load", 10000, u);
    EXPECT_GE(std::log10(e100 / e1000), 0.95) << "u/d0 = " << u;
    EXPECT_GE(std::log10(e1000 / e10000), 0.95) << "u/d0 = " << u;
  }
}

// Doubling the springs halves the error: order from log2 of successive ratios.
TEST(Convergence, FixedLoadOrderFromSuccessiveDoublings) {
  std::vector<double> errors;
  for (const std::int64_t n : {1000, 2000, 4000, 8000, 16000}) {
    errors.push_back(critical_force_error("fixed-load", n));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 1.0, 0.05) << "doubling " << i;
  }
}

// Under fixed grips the fold is flat in d, so which spring is the last to hold is decided
// to within one spacing dx: the force error is a sawtooth bounded by |dF/da| dx plus the
// O(dx) bias, |dF/da| = 1.39 F0/a0 at the fold and dx = 2 a0/springs, so
// error * springs <= 3 at every resolution (it does not decrease monotonically).
TEST(Convergence, FixedGripsErrorIsBoundedByOneSpacing) {
  for (const std::int64_t n : {100, 300, 1000, 3000, 10000, 30000}) {
    EXPECT_LE(critical_force_error("fixed-grips", n) * static_cast<double>(n), 3.0) << n;
  }
  EXPECT_LT(critical_force_error("fixed-grips", 10000),
            critical_force_error("fixed-grips", 100) / 10);
}
