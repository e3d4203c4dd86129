// The tanh-sinh MDR transform (eqs. 4-5) against closed-form images and their round trip.
#include "profiles/mdr_transform.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

// Eq. 4 of the classical shapes, whose images are known in closed form (paper eq. 6 and
// Hess's power law): the quadrature must reach them to near rounding, including the
// singular slope of r^0.5 at the tip and the 1/sqrt singularity at r = x.
TEST(MdrTransform, ReachesClosedFormImages) {
  const double radius = 0.01;
  for (const double x : {1e-6, 1e-4, 3e-3}) {
    EXPECT_NEAR(mdrsim::mdr_transform([&](double r) { return r / radius; }, x), x * x / radius,
                1e-13 * x * x / radius);
    // Cone: g = (pi/2) tan(theta) x.
    EXPECT_NEAR(mdrsim::mdr_transform([](double) { return 0.3; }, x), 0.5 * kPi * 0.3 * x,
                1e-13 * x);
    // f = r^0.5: g = kappa(0.5) x^0.5 with kappa = sqrt(pi) Gamma(1.25)/Gamma(0.75).
    const double kappa = std::sqrt(kPi) * std::tgamma(1.25) / std::tgamma(0.75);
    EXPECT_NEAR(mdrsim::mdr_transform([](double r) { return 0.5 / std::sqrt(r); }, x),
                kappa * std::sqrt(x), 1e-12 * std::sqrt(x));
  }
}

// Eq. 5 inverts eq. 4: f -> g -> f for the sphere's exact image (paper eq. 5 applied to
// g = x artanh(x/R) must give back R - sqrt(R^2 - r^2)).
TEST(MdrTransform, InverseRecoversTheShape) {
  const double radius = 1e-3;
  for (const double r : {1e-5, 3e-4, 9e-4}) {
    const double f = radius - std::sqrt(radius * radius - r * r);
    EXPECT_NEAR(
        mdrsim::inverse_mdr_transform([&](double x) { return x * std::atanh(x / radius); }, r), f,
        1e-12 * f);
  }
  const auto slope = [](double r) { return 1.5 * std::sqrt(r); };  // f = r^1.5
  for (const double r : {1e-4, 0.2, 1.0}) {
    const double back =
        mdrsim::inverse_mdr_transform([&](double x) { return mdrsim::mdr_transform(slope, x); }, r);
    EXPECT_NEAR(back, std::pow(r, 1.5), 1e-11 * std::pow(r, 1.5));
  }
}

TEST(MdrTransform, IsZeroAtTheTip) {
  EXPECT_EQ(mdrsim::mdr_transform([](double) { return 1.0; }, 0.0), 0.0);
  EXPECT_EQ(mdrsim::inverse_mdr_transform([](double x) { return x; }, 0.0), 0.0);
}
