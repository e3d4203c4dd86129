// bracketed_minimum finds a minimum at any scale of its variable, metres or nanometres.
#include "engine/base/bracketed_minimum.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mdrsim {
namespace {

// A parabola's minimum at x0 inside [x0 / 3, 2 x0], from 1 m down to 1e-12 m: the place to
// 1e-7 relative (26 bits: half a double's digits; the place of a smooth minimum is known to
// no more), the value to 1e-13 of its curvature's scale. Boost's rule alone, over x itself,
// stops at once below about 1e-7 m (its absolute 2^-27 in x) and returns the bracket's end.
TEST(BracketedMinimum, FindsAMinimumAtEveryScale) {
  for (const double x0 : {1.0, 1e-3, 1e-6, 1.27e-8, 1e-12}) {
    SCOPED_TRACE(x0);
    const auto f = [x0](double x) { return (x - x0) * (x - x0) / (x0 * x0) - 1.0; };
    const Minimum m = bracketed_minimum(f, x0 / 3.0, 2.0 * x0, 26);
    EXPECT_NEAR(m.at / x0, 1.0, 1e-7);
    EXPECT_NEAR(m.value, -1.0, 1e-13);
    EXPECT_EQ(m.value, f(m.at));
  }
}

// An end of the bracket is the minimum where the function falls towards it.
TEST(BracketedMinimum, AnEndWhereTheFunctionFallsTowardsIt) {
  const Minimum m = bracketed_minimum([](double x) { return x; }, 2e-9, 5e-9, 26);
  EXPECT_NEAR(m.at, 2e-9, 1e-9 * 1e-6);
}

}  // namespace
}  // namespace mdrsim
