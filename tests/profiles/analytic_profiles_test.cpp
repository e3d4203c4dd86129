// Sphere, cone, flat punch and power law: closed forms against eq. 4 and the numerical defaults.
#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "profiles/cone_profile.hpp"
#include "profiles/flat_punch_profile.hpp"
#include "profiles/mdr_transform.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/sphere_profile.hpp"

namespace {

constexpr double kPi = std::numbers::pi;

/// The slope of f by a central difference (for eq. 4 from the shape alone, independent of the
/// closed forms under test); h scaled to r keeps its error near 1e-10 relative.
template <class P>
double shape_slope(const P& p, double r) {
  const double h = 1e-5 * r;
  return (p.shape(r + h) - p.shape(r - h)) / (2.0 * h);
}

}  // namespace

// g(x) = x artanh(x/R) against eq. 4 of f' = r/sqrt(R^2 - r^2), by tanh-sinh quadrature;
// up to x = 0.999 R, where f' grows to 22.
TEST(SphereProfile, ImageIsTheMdrTransformOfTheCap) {
  const double radius = 1e-3;
  const mdrsim::SphereProfile p(radius);
  for (const double x : {1e-6, 1e-4, 5e-4, 9e-4, 9.99e-4}) {
    const double g = mdrsim::mdr_transform(
        [&](double r) { return r / std::sqrt((radius - r) * (radius + r)); }, x);
    EXPECT_NEAR(p.mdr_image(x), g, 1e-12 * g) << "x = " << x;
    EXPECT_NEAR(p.shape(x),
                mdrsim::inverse_mdr_transform([&](double s) { return p.mdr_image(s); }, x),
                1e-12 * p.shape(x));
  }
}

// Small x/R: g = x^2/R + x^4/(3 R^3) + O(x^6), so the sphere tends to its tip parabola with
// a relative departure (x/R)^2/3.
TEST(SphereProfile, TendsToItsTipParabola) {
  const double radius = 0.01;
  const mdrsim::SphereProfile p(radius);
  for (const double x : {1e-6, 1e-5, 1e-4, 1e-3}) {
    const double t = x / radius;
    EXPECT_NEAR(p.mdr_image(x) / (x * x / radius) - 1.0, t * t / 3.0, 1e-15 + t * t * t * t);
    EXPECT_NEAR(p.shape(x) / (x * x / (2.0 * radius)) - 1.0, t * t / 4.0, 1e-15 + t * t * t * t);
  }
  ASSERT_TRUE(p.jkr_scale_radius().has_value());
  EXPECT_EQ(*p.jkr_scale_radius(), radius);
}

// The Hertz force of the exact sphere, (a^2 + R^2) artanh(a/R) - a R over E*, on both sides
// of the series switch at a/R = 0.1, against Gauss-Kronrod of 2 integral (g(a) - g); the
// slope against a difference; the depth inversion against the root-search default.
TEST(SphereProfile, ClosedFormsMatchTheNumericalDefaults) {
  const double radius = 1e-3;
  const mdrsim::SphereProfile p(radius);
  for (const double a : {1e-7, 5e-5, 9.99e-5, 1.001e-4, 5e-4, 9e-4}) {
    const double force = p.nonadhesive_force_per_modulus(a);
    EXPECT_NEAR(force, p.Profile::nonadhesive_force_per_modulus(a), 1e-12 * force) << a;
    // The default's fourth-order difference (step 1e-3 a) errs by (step/(R - a))^4: 1e-8 at
    // a = 0.9 R.
    EXPECT_NEAR(p.mdr_image_slope(a), p.Profile::mdr_image_slope(a),
                (a < 6e-4 ? 1e-9 : 2e-8) * p.mdr_image_slope(a));
    EXPECT_NEAR(p.contact_radius_at_depth(p.mdr_image(a)), a, 1e-13 * a);
  }
  // Small a: the Hertz force 4 a^3/(3R) (1 + 2/5 t^2 + 9/35 t^4 + ...), t = a/R, from the
  // terms k = 2, 3 of the series.
  const double a = 1e-6;
  EXPECT_NEAR(p.nonadhesive_force_per_modulus(a),
              4.0 * a * a * a / (3.0 * radius) * (1.0 + 0.4e-6 + 9.0 / 35.0 * 1e-12),
              1e-15 * 4.0 * a * a * a / (3.0 * radius));
}

// The image diverges at the sphere's edge: any depth is reached inside it, and beyond it
// nothing touches.
TEST(SphereProfile, EndsAtItsRadius) {
  const mdrsim::SphereProfile p(1e-3);
  EXPECT_EQ(p.outer_radius(), 1e-3);
  EXPECT_EQ(p.mdr_image(1e-3), std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.shape(1.1e-3), std::numeric_limits<double>::infinity());
  // Three radii deep (a = 0.995 R): g' a/g = 33 amplifies the root's rounding.
  const double deep = p.contact_radius_at_depth(3e-3);
  EXPECT_LT(deep, 1e-3);
  EXPECT_NEAR(p.mdr_image(deep), 3e-3, 1e-13 * 3e-3);
  // A force of 1 N on E* = 1 MPa needs a/R = 0.98: reached although g diverges at the edge.
  const double a = mdrsim::contact_radius_at_force(p, 1.0, 1e6);
  EXPECT_LT(a, 1e-3);
  EXPECT_NEAR(1e6 * p.nonadhesive_force_per_modulus(a), 1.0, 1e-12);
  EXPECT_THROW(mdrsim::SphereProfile(0.0), std::invalid_argument);
}

TEST(ConeProfile, ClosedFormsAreTheClassicalCone) {
  const mdrsim::ConeProfile p(30.0);
  const double slope = std::tan(kPi / 6.0);
  for (const double x : {1e-6, 1e-3}) {
    const double g = mdrsim::mdr_transform([&](double r) { return shape_slope(p, r); }, x);
    EXPECT_NEAR(p.mdr_image(x), g, 1e-9 * g);
    EXPECT_NEAR(p.mdr_image(x), 0.5 * kPi * slope * x, 1e-15 * x);
    // Sneddon: F = (pi/2) E* a^2 tan(theta), and the depth d = (pi/2) a tan(theta).
    EXPECT_NEAR(p.nonadhesive_force_per_modulus(x), 0.5 * kPi * x * x * slope, 1e-15 * x * x);
    EXPECT_NEAR(p.nonadhesive_force_per_modulus(x), p.Profile::nonadhesive_force_per_modulus(x),
                1e-13 * x * x);
    EXPECT_NEAR(p.contact_radius_at_depth(p.mdr_image(x)), x, 1e-15 * x);
    EXPECT_NEAR(p.mdr_image_slope(x), p.Profile::mdr_image_slope(x), 1e-10);
  }
  EXPECT_FALSE(p.jkr_scale_radius().has_value());
  EXPECT_THROW(mdrsim::ConeProfile(0.0), std::invalid_argument);
  EXPECT_THROW(mdrsim::ConeProfile(90.0), std::invalid_argument);
}

// The flat punch: zero image on its face, a wall beyond, and a contact radius fixed at A.
TEST(FlatPunchProfile, FaceIsFlatAndTheContactRadiusFixed) {
  const double radius = 1e-4;
  const mdrsim::FlatPunchProfile p(radius);
  EXPECT_EQ(p.mdr_image(0.5 * radius), 0.0);
  EXPECT_EQ(p.mdr_image(radius), 0.0);
  EXPECT_EQ(p.mdr_image_slope(radius), 0.0);
  EXPECT_EQ(p.mdr_image(1.0001 * radius), std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.shape(2.0 * radius), std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.contact_radius_at_depth(1e-9), radius);
  EXPECT_EQ(p.contact_radius_at_depth(0.0), 0.0);
  EXPECT_EQ(p.nonadhesive_force_per_modulus(radius), 0.0);
  ASSERT_TRUE(p.fixed_contact_radius().has_value());
  EXPECT_EQ(*p.fixed_contact_radius(), radius);
  EXPECT_EQ(mdrsim::contact_radius_at_force(p, 1.0, 1e6), radius);
  EXPECT_EQ(p.outer_radius(), radius);
  EXPECT_THROW(mdrsim::FlatPunchProfile(-1.0), std::invalid_argument);
}

// kappa(n) = sqrt(pi) Gamma(n/2 + 1)/Gamma(n/2 + 1/2): pi/2 (cone), 2 (parabola), 3 pi/4,
// 8/3, and eq. 4 of c r^n at other n, including n < 1 where f' is singular at the tip.
TEST(PowerLawProfile, ImageFactorIsHesss) {
  EXPECT_NEAR(mdrsim::PowerLawProfile::image_factor(1.0), kPi / 2.0, 1e-15);
  EXPECT_NEAR(mdrsim::PowerLawProfile::image_factor(2.0), 2.0, 1e-15);
  EXPECT_NEAR(mdrsim::PowerLawProfile::image_factor(3.0), 3.0 * kPi / 4.0, 1e-15);
  EXPECT_NEAR(mdrsim::PowerLawProfile::image_factor(4.0), 8.0 / 3.0, 1e-15);
  // Large n: kappa ~ sqrt(pi n / 2) (1 + 1/(4n)); finite where the Gammas alone overflow.
  const double n = 1000.0;
  EXPECT_NEAR(mdrsim::PowerLawProfile::image_factor(n), std::sqrt(kPi * n / 2.0) * (1.0 + 0.25 / n),
              1e-6 * std::sqrt(n));
  for (const double exponent : {0.5, 1.5, 2.7}) {
    const mdrsim::PowerLawProfile p(0.8, exponent);
    const double x = 3e-4;
    const double g = mdrsim::mdr_transform(
        [&](double r) { return 0.8 * exponent * std::pow(r, exponent - 1.0); }, x);
    EXPECT_NEAR(p.mdr_image(x), g, 1e-12 * g) << "n = " << exponent;
    // The default's Gauss-Kronrod converges slowly on x^n below n = 1 (slope singular at 0).
    EXPECT_NEAR(p.nonadhesive_force_per_modulus(x), p.Profile::nonadhesive_force_per_modulus(x),
                (exponent < 1.0 ? 1e-9 : 1e-12) * p.nonadhesive_force_per_modulus(x));
    EXPECT_NEAR(p.contact_radius_at_depth(p.mdr_image(x)), x, 1e-14 * x);
    EXPECT_NEAR(p.mdr_image_slope(x), p.Profile::mdr_image_slope(x), 1e-9 * p.mdr_image_slope(x));
  }
}

// n = 2 with c = 1/(2R) is the parabola, n = 1 with c = tan(theta) the cone.
TEST(PowerLawProfile, ContainsTheParabolaAndTheCone) {
  const mdrsim::ParabolicProfile parabola(0.01);
  const mdrsim::PowerLawProfile as_parabola(50.0, 2.0);
  const mdrsim::ConeProfile cone(20.0);
  const mdrsim::PowerLawProfile as_cone(std::tan(20.0 * kPi / 180.0), 1.0);
  for (const double x : {1e-5, 1e-3}) {
    EXPECT_NEAR(as_parabola.mdr_image(x), parabola.mdr_image(x), 1e-15 * parabola.mdr_image(x));
    EXPECT_NEAR(as_parabola.nonadhesive_force_per_modulus(x),
                parabola.nonadhesive_force_per_modulus(x),
                1e-14 * parabola.nonadhesive_force_per_modulus(x));
    EXPECT_NEAR(as_cone.mdr_image(x), cone.mdr_image(x), 1e-15 * cone.mdr_image(x));
  }
  EXPECT_THROW(mdrsim::PowerLawProfile(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(mdrsim::PowerLawProfile(0.0, 2.0), std::invalid_argument);
}

// The growth the route plan counts a JKR branch's folds with: s(x) = d ln(sqrt(x) g'(x)) / d ln x
// is n - 1/2 for c r^n, checked on the image's own slope by a central difference in ln x over
// 1e-4 (its error ~1e-8, the slope's closed form rounding at 1e-16 / 1e-4).
TEST(PowerLawProfile, ImageSlopeGrowthIsTheExponentLessAHalf) {
  for (const double exponent : {0.3, 0.5, 0.8, 2.5}) {
    const mdrsim::PowerLawProfile p(0.8, exponent);
    const auto growth = p.image_slope_growth();
    ASSERT_TRUE(growth);
    EXPECT_EQ(growth->low, exponent - 0.5);
    EXPECT_EQ(growth->high, exponent - 0.5);
    const auto log_of = [&](double x) { return std::log(std::sqrt(x) * p.mdr_image_slope(x)); };
    for (const double x : {1e-6, 1e-3, 1.0}) {
      const double h = 1e-4;
      const double s = (log_of(x * std::exp(h)) - log_of(x * std::exp(-h))) / (2.0 * h);
      EXPECT_NEAR(s, exponent - 0.5, 1e-8) << "n = " << exponent << ", x = " << x;
    }
  }
  EXPECT_FALSE(mdrsim::ParabolicProfile(0.01).image_slope_growth());
}

// The springs' stored energy per E*, int_0^a (d - k x^n)^2 dx, in closed form against tanh-sinh
// in long double on x = a t (the t^n at 0 costs it nothing; its own error near 1e-18 relative),
// pressed (d > g(a)), stretched (d < g(a)) and pulled (d < 0): off by no more than
// the 1e-15 of its terms' magnitudes the continuum work reports as its rounding.
TEST(PowerLawProfile, SquaredGapIntegralIsTheClosedForm) {
  for (const double exponent : {0.3, 0.5, 1.0, 1.3947656, 2.0, 3.7}) {
    const mdrsim::PowerLawProfile p(3.25, exponent);
    for (const double a : {2.4e-5, 7.6e-5, 1e-3}) {
      const double edge = p.mdr_image(a);
      for (const double d : {1.5 * edge, edge, 0.6 * edge, 0.1 * edge, -0.3 * edge}) {
        const long double k = p.mdr_image(1.0);
        const auto integrand = [&](long double t) {
          const long double gap = d - k * std::pow(a * t, static_cast<long double>(exponent));
          return a * gap * gap;
        };
        const long double want = boost::math::quadrature::tanh_sinh<long double>().integrate(
            integrand, 0.0L, 1.0L, 1e-18L);
        const auto got = p.squared_gap_integral(a, d);
        ASSERT_TRUE(got.has_value());
        EXPECT_LE(std::abs(got->value - static_cast<double>(want)), 1e-15 * got->magnitude)
            << "n = " << exponent << ", a = " << a << ", d = " << d;
        EXPECT_GE(got->magnitude, std::abs(got->value));
      }
    }
  }
  EXPECT_EQ(mdrsim::PowerLawProfile(3.25, 1.5).squared_gap_integral(0.0, 1e-6)->value, 0.0);
}
