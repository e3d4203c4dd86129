// The JKR scales of paper eq. 17, including where a naive formula would underflow.
#include "engine/model/jkr_scales.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

TEST(JkrScales, Equation17) {
  const double r = 0.01, e = 1e6, w = 0.05, pi = std::numbers::pi;
  const auto s = mdrsim::JkrScales::of(r, e, w);
  ASSERT_TRUE(s.has_value());
  EXPECT_DOUBLE_EQ(s->force, 1.5 * pi * r * w);
  EXPECT_NEAR(s->radius, std::cbrt(9 * pi * r * r * w / (8 * e)), 1e-15 * s->radius);
  EXPECT_NEAR(s->depth, std::cbrt(3 * pi * pi * r * w * w / (64 * e * e)), 1e-15 * s->depth);
  // Consequences of eqs. 14 and 17 used by eqs. 18 and 27: d0 = a0^2/(3R), a0 d0 = 3 pi R w/(8 E*).
  EXPECT_NEAR(s->depth, s->radius * s->radius / (3 * r), 1e-14 * s->depth);
  EXPECT_NEAR(s->radius * s->depth, 3 * pi * r * w / (8 * e), 1e-14 * s->radius * s->depth);
}

// dgamma^2 = 1e-340 underflows to zero; the scales must still be positive and finite.
TEST(JkrScales, TinyAdhesionStaysFinite) {
  const auto s = mdrsim::JkrScales::of(0.01, 1e6, 1e-170);
  ASSERT_TRUE(s.has_value());
  EXPECT_GT(s->depth, 0.0);
  EXPECT_TRUE(std::isfinite(s->radius));
  EXPECT_FALSE(mdrsim::JkrScales::of(0.01, 1e6, 0.0).has_value());  // no adhesion, no scales
}
