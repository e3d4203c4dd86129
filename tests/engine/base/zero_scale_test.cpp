// What is zero in a run: the scale from the scene's sizes, against its closed form.
#include "engine/base/zero_scale.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace mdrsim {
namespace {

// E* = 1 MPa, a = 0.1 mm, g(a) = 1 um, dgamma = 0.05 J/m^2: the Hess length 2 pi dgamma/E*
// = 0.314 um is below g(a), so D = 1 um and the force scale is E* a D = 1e-4 N.
TEST(ZeroScale, IsTheFlatPunchScaleTimesTheRoundingShare) {
  const ZeroScale z = zero_scale(1e6, 1e-4, 1e-6, 0.05);
  // Products of exact decimal factors: equal to 1 ulp.
  EXPECT_DOUBLE_EQ(z.force, kRoundingShare * 1e-4);
  EXPECT_DOUBLE_EQ(z.displacement, kRoundingShare * 1e-6);
  EXPECT_DOUBLE_EQ(z.work, kRoundingShare * 1e-10);
  EXPECT_TRUE(z.zero_force(-2.2e-22));   // a critical point of rounding seen on a run
  EXPECT_FALSE(z.zero_force(-3.6e-12));  // far above the rounding share: a force
}

TEST(ZeroScale, TakesTheHessLengthAndTheHeldForceWhereLarger) {
  const double hess = 2.0 * std::numbers::pi * 0.05 / 1e6;
  // A flat punch's image is 0 at its radius: the depth is the Hess length.
  const ZeroScale z = zero_scale(1e6, 1e-4, 0.0, 0.05);
  EXPECT_DOUBLE_EQ(z.displacement, kRoundingShare * hess);
  EXPECT_DOUBLE_EQ(z.force, kRoundingShare * 1e6 * 1e-4 * hess);
  // A held load of 1 N is far above E* a D = 3.1e-5 N: it sets the force scale.
  EXPECT_DOUBLE_EQ(zero_scale(1e6, 1e-4, 0.0, 0.05, -1.0).force, kRoundingShare);
}

TEST(ZeroScale, NothingIsZeroButZeroWithoutAnyScale) {
  const ZeroScale z = zero_scale(1e6, 1e-4, 0.0, 0.0);  // no image, no adhesion
  EXPECT_EQ(z.force, 0.0);
  EXPECT_TRUE(z.zero_force(0.0));
  EXPECT_FALSE(z.zero_force(1e-300));
}

}  // namespace
}  // namespace mdrsim
