// The parabola's closed forms against the MDR transform and its inverse (paper eqs. 4-6).
#include "profiles/parabolic_profile.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

namespace {

using Quadrature = boost::math::quadrature::gauss_kronrod<double, 31>;

// Eq. 4 with r = x sin t, which removes the 1/sqrt(x^2 - r^2) singularity:
// g(x) = x * integral_0^{pi/2} f'(x sin t) dt.
template <class Slope>
double mdr_transform(Slope slope, double x) {
  return x * Quadrature::integrate([&](double t) { return slope(x * std::sin(t)); }, 0.0,
                                   std::numbers::pi / 2, 10, 1e-14);
}

// Eq. 5 with x = r sin t: f(r) = 2/pi * integral_0^{pi/2} g(r sin t) dt.
double inverse_transform(const mdrsim::Profile& p, double r) {
  return 2.0 / std::numbers::pi *
         Quadrature::integrate([&](double t) { return p.mdr_image(r * std::sin(t)); }, 0.0,
                               std::numbers::pi / 2, 10, 1e-14);
}

}  // namespace

TEST(ParabolicProfile, ImageIsTheMdrTransformOfTheShape) {
  const double radius = 0.02;
  const mdrsim::ParabolicProfile p(radius);
  for (const double x : {1e-5, 1e-4, 3e-3, 1e-2}) {
    EXPECT_NEAR(p.mdr_image(x), mdr_transform([&](double r) { return r / radius; }, x),
                1e-13 * p.mdr_image(x));
    EXPECT_NEAR(p.shape(x), inverse_transform(p, x), 1e-13 * p.shape(x));
  }
}

// The closed forms against the Profile defaults (root search, quadrature) they override.
TEST(ParabolicProfile, ClosedFormsMatchTheNumericalDefaults) {
  const mdrsim::ParabolicProfile p(0.01);
  for (const double a : {1e-5, 2e-4, 3e-3}) {
    EXPECT_NEAR(p.contact_radius_at_depth(p.mdr_image(a)), a, 1e-14 * a);
    EXPECT_NEAR(p.nonadhesive_force_per_modulus(a), p.Profile::nonadhesive_force_per_modulus(a),
                1e-12 * p.nonadhesive_force_per_modulus(a));
    EXPECT_NEAR(p.Profile::contact_radius_at_depth(p.mdr_image(a)), a, 1e-12 * a);
    EXPECT_NEAR(p.mdr_image_slope(a), p.Profile::mdr_image_slope(a), 1e-10 * p.mdr_image_slope(a));
  }
  EXPECT_NEAR(mdrsim::contact_radius_at_force(p, 1e-3, 1e6),
              std::cbrt(3.0 * 0.01 * 1e-3 / (4.0 * 1e6)), 1e-15);
  ASSERT_TRUE(p.jkr_scale_radius().has_value());
  EXPECT_EQ(*p.jkr_scale_radius(), 0.01);
}

TEST(ParabolicProfile, RejectsANonPositiveRadius) {
  EXPECT_THROW(mdrsim::ParabolicProfile(0.0), std::invalid_argument);
  EXPECT_THROW(mdrsim::ParabolicProfile(-1.0), std::invalid_argument);
}
