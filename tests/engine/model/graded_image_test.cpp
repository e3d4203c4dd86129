// The graded image's closed forms against its defining integral and the homogeneous images.
#include "engine/model/graded_image.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <numbers>

#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"

namespace mdrsim {
namespace {

/// g_k(x) = x^(1-k) int_0^x f'(r) (x^2 - r^2)^((k-1)/2) dr by tanh-sinh (the endpoint
/// singularity is its strength), for f = c r^n.
double image_by_quadrature(double c, double n, double k, double x) {
  boost::math::quadrature::tanh_sinh<double> rule;
  const auto integrand = [&](double r, double to_end) {
    // x^2 - r^2 = (x - r)(x + r), with x - r kept exact near x.
    const double gap = to_end > 0.0 ? to_end : x - r;
    return c * n * std::pow(r, n - 1.0) * std::pow(gap * (x + r), 0.5 * (k - 1.0));
  };
  return std::pow(x, 1.0 - k) * rule.integrate(integrand, 0.0, x, 1e-14);
}

TEST(GradedImage, MatchesItsDefiningIntegral) {
  // tanh-sinh to about 1e-13 on these endpoint singularities: 1e-11.
  for (double k : {0.0, 0.25, 0.5, 0.75}) {
    for (const auto& [c, n] :
         {std::pair{50.0, 2.0}, std::pair{0.7, 1.0}, std::pair{3.0, 1.5}, std::pair{0.02, 0.6}}) {
      const GradedImage g = GradedImage::of_power_law(c, n, k);
      for (double x : {1e-4, 3e-3}) {
        EXPECT_NEAR(g.image(x) / image_by_quadrature(c, n, k, x), 1.0, 1e-11)
            << "k = " << k << ", n = " << n << ", x = " << x;
      }
    }
  }
}

TEST(GradedImage, ParabolaIsXSquaredOverOnePlusKTimesR) {
  const double r = 0.01;
  for (double k : {0.25, 0.5, 0.75}) {
    const auto g = GradedImage::of_profile("parabolic", r, 0.0, k);
    ASSERT_TRUE(g);
    const double x = 2e-4;
    EXPECT_NEAR(g->image(x), x * x / ((1.0 + k) * r), 1e-15 * x * x / r);
  }
}

TEST(GradedImage, HomogeneousIsTheProfilesImage) {
  // k = 0: the profiles' own images, to rounding.
  const double x = 3e-4;
  EXPECT_NEAR(GradedImage::of_profile("parabolic", 0.01, 0.0, 0.0)->image(x),
              ParabolicProfile(0.01).mdr_image(x), 1e-15);
  EXPECT_NEAR(GradedImage::of_profile("cone", 20.0, 0.0, 0.0)->image(x),
              ConeProfile(20.0).mdr_image(x), 1e-17);
  EXPECT_NEAR(GradedImage::of_profile("power_law", 2.5, 1.5, 0.0)->image(x),
              PowerLawProfile(2.5, 1.5).mdr_image(x), 1e-17);
  EXPECT_FALSE(GradedImage::of_profile("sphere", 0.01, 0.0, 0.5));
}

TEST(GradedImage, WeightedIntegralsMatchQuadrature) {
  // (1 + k) int_0^a x^k (g(a) - g(x)) dx and (1 + k) int_0^a x^k (d - g)^2 dx by tanh-sinh:
  // 1e-12.
  boost::math::quadrature::tanh_sinh<double> rule;
  for (double k : {0.3, 0.8}) {
    const GradedImage g = GradedImage::of_power_law(4.0, 1.7, k);
    const double a = 2e-3, d = 0.4 * g.image(a);
    const double nf =
        (1.0 + k) *
        rule.integrate([&](double x) { return std::pow(x, k) * (g.image(a) - g.image(x)); }, 0.0, a,
                       1e-15);
    EXPECT_NEAR(g.nonadhesive_force_per_constant(a) / nf, 1.0, 1e-12);
    const double sq = (1.0 + k) * rule.integrate(
                                      [&](double x) {
                                        const double gap = d - g.image(x);
                                        return std::pow(x, k) * gap * gap;
                                      },
                                      0.0, a, 1e-15);
    EXPECT_NEAR(g.squared_gap_integral(a, d) / sq, 1.0, 1e-12);
    EXPECT_NEAR(g.image(g.radius_at_depth(1e-5)) / 1e-5, 1.0, 1e-14);
    EXPECT_NEAR(g.nonadhesive_force_per_constant(g.radius_at_force(3e-3, 2e7)) * 2e7 / 3e-3, 1.0,
                1e-14);
  }
}

}  // namespace
}  // namespace mdrsim
