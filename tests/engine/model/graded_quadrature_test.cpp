// The graded image by quadrature against closed forms derived apart: power laws' K |x|^n, the
// sphere's hypergeometric series, and the inverse transform giving back the sphere.
#include "engine/model/graded_quadrature.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "engine/model/graded_image.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"

namespace mdrsim {
namespace {

/// f = c r^n as a GradedShape (n a whole number: f' analytic at the tip, as the sphere's,
/// tables' and ripples' are), with optional breakpoints that split it for nothing.
class PowerLawSlopes final : public GradedShape {
 public:
  PowerLawSlopes(double c, double n, std::vector<double> breaks = {})
      : c_(c), n_(n), breaks_(std::move(breaks)) {}
  double slope(double r, std::size_t) const override { return c_ * n_ * std::pow(r, n_ - 1.0); }
  double radial_slope_derivative(double r, std::size_t) const override {
    return c_ * n_ * n_ * std::pow(r, n_ - 1.0);
  }
  std::size_t breakpoints_below(double x) const override {
    std::size_t i = 0;
    while (i < breaks_.size() && breaks_[i] < x) ++i;
    return i;
  }
  double breakpoint(std::size_t j) const override { return breaks_[j]; }

 private:
  double c_, n_;
  std::vector<double> breaks_;
};

TEST(GradedQuadrature, JacobiRuleIntegratesMonomials) {
  // int_-1^1 (1 + y)^b y^m dy = sum_j C(m, j) (-1)^(m-j) 2^(b+j+1) / (b + j + 1), exact for
  // m <= 2n - 1 = 39; the alternating sum loses a few digits at m = 15: 1e-11.
  for (double b : {0.0, 0.1, 0.5, 0.9}) {
    std::vector<double> y, w;
    gauss_jacobi_rule(20, 0.0, b, y, w);
    for (int m = 0; m <= 15; ++m) {
      double exact = 0.0, binomial = 1.0;
      for (int j = 0; j <= m; ++j) {
        exact += binomial * ((m - j) % 2 ? -1.0 : 1.0) * std::pow(2.0, b + j + 1.0) / (b + j + 1.0);
        binomial *= static_cast<double>(m - j) / (j + 1.0);
      }
      double sum = 0.0;
      for (std::size_t i = 0; i < y.size(); ++i) sum += w[i] * std::pow(y[i], m);
      EXPECT_NEAR(sum, exact, 1e-11 * std::pow(2.0, b + m + 1.0)) << b << " " << m;
    }
  }
}

TEST(GradedQuadrature, PowerLawsMatchTheClosedForm) {
  // K |x|^n and its integrals (graded_image.cpp) to 1e-10, with and without breakpoints.
  for (double k : {0.1, 0.25, 0.5, 0.75, 0.9}) {
    for (double n : {1.0, 2.0, 3.0, 4.0}) {
      for (bool split : {false, true}) {
        const double c = 3.0;
        auto shape = std::make_shared<PowerLawSlopes>(
            c, n, split ? std::vector<double>{1e-4, 0.3, 0.59999, 0.9} : std::vector<double>{});
        const GradedImage q = GradedImage::by_quadrature(shape, k);
        const GradedImage exact = GradedImage::of_power_law(c, n, k);
        for (double x : {1e-3, 0.2, 0.6, 1.0, 2.5}) {
          EXPECT_NEAR(q.image(x) / exact.image(x), 1.0, 1e-10) << k << " " << n << " " << x;
          EXPECT_NEAR(q.image_slope(x) / exact.image_slope(x), 1.0, 1e-10) << k << " " << n;
          EXPECT_NEAR(q.nonadhesive_force_per_constant(x) / exact.nonadhesive_force_per_constant(x),
                      1.0, 1e-10)
              << k << " " << n << " " << x;
          const double d = 0.7 * exact.image(x);
          EXPECT_NEAR(q.squared_gap_integral(x, d) / exact.squared_gap_integral(x, d), 1.0, 1e-10)
              << k << " " << n << " " << x;
        }
      }
    }
  }
}

TEST(GradedQuadrature, SphereMatchesItsHypergeometricSeries) {
  // f' = (r/R) sum_j (1/2)_j / j! (r/R)^(2j), and int_0^(pi/2) sin^(2j+1) t cos^k t dt =
  // B(j + 1, (1+k)/2) / 2, so g_k = x^2 / ((1 + k) R) 2F1(1/2, 1; (3 + k)/2; x^2/R^2), summed
  // here term by term (2000 terms: 0.95^4000 is far below 1e-16). 1e-12.
  const double r = 0.01;
  for (double k : {0.0, 0.25, 0.5, 0.9}) {
    const GradedImage q = GradedImage::by_quadrature(graded_sphere(r), k);
    for (double t : {1e-4, 0.05, 0.3, 0.7, 0.95}) {
      const double x = t * r, rho = t * t;
      double term = 1.0, sum = 0.0;
      for (int j = 0; j < 2000; ++j) {
        sum += term;
        term *= (0.5 + j) * rho / (0.5 * (3.0 + k) + j);
      }
      const double exact = x * x / ((1.0 + k) * r) * sum;
      EXPECT_NEAR(q.image(x) / exact, 1.0, 1e-12) << k << " " << t;
    }
    if (k == 0.0) {
      // The homogeneous sphere's closed forms.
      const SphereProfile sphere(r);
      for (double t : {0.01, 0.5, 0.9, 0.999}) {
        EXPECT_NEAR(q.image(t * r) / sphere.mdr_image(t * r), 1.0, 1e-12) << t;
        EXPECT_NEAR(q.image_slope(t * r) / sphere.mdr_image_slope(t * r), 1.0, 1e-12) << t;
        EXPECT_NEAR(2.0 * q.nonadhesive_force_per_constant(t * r) /
                        sphere.nonadhesive_force_per_modulus(t * r),
                    1.0, 1e-12)
            << t;
      }
    }
  }
}

/// The inverse of the graded transform, derived apart: with u = r^2 and v = x^2,
/// x^(k-1) g_k(x) = int_0^v phi(u) (v - u)^(alpha - 1) du, phi(u) = f'(sqrt u) / (2 sqrt u),
/// alpha = (1 + k)/2, is Gamma(alpha) times the Riemann-Liouville integral I^alpha phi; so
/// f(r) = I^1 phi (r^2) = I^(1-alpha) [I^alpha phi] (r^2), with Gamma(alpha) Gamma(1 - alpha)
/// = pi / cos(pi k / 2):
///   f(r) = (2 cos(pi k / 2) / pi) int_0^r x^k g_k(x) (r^2 - x^2)^(-(1+k)/2) dx
/// (k = 0: the MDR's f = (2/pi) int_0^r g / sqrt(r^2 - x^2)). By tanh-sinh, whose strength is
/// the endpoint singularity.
double inverse_graded_transform(const GradedImage& g, double k, double r) {
  boost::math::quadrature::tanh_sinh<double> rule;
  const auto integrand = [&](double x, double complement) {
    const double to_end = complement > 0.0 ? complement : r - x;
    return std::pow(x, k) * g.image(x) * std::pow(to_end * (r + x), -0.5 * (1.0 + k));
  };
  return 2.0 * std::cos(0.5 * std::numbers::pi * k) / std::numbers::pi *
         rule.integrate(integrand, 0.0, r, 1e-13);
}

TEST(GradedQuadrature, InverseTransformGivesBackTheSphere) {
  // R - sqrt(R^2 - r^2) from the quadrature image through the inverse above, to 1e-8 (the
  // tanh-sinh rule reaches about 1e-12 on the (r - x)^(-(1+k)/2) singularity; 1e-8 leaves
  // room for k = 0.9, the strongest).
  const double radius = 0.01;
  for (double k : {0.0, 0.25, 0.5, 0.75, 0.9}) {
    const GradedImage g = GradedImage::by_quadrature(graded_sphere(radius), k);
    for (double t : {0.01, 0.2, 0.5, 0.8, 0.95}) {
      const double r = t * radius;
      const double exact = r * r / (radius + std::sqrt((radius - r) * (radius + r)));
      EXPECT_NEAR(inverse_graded_transform(g, k, r) / exact, 1.0, 1e-8) << k << " " << t;
    }
  }
}

TEST(GradedQuadrature, WavyMatchesItsDefiningIntegral) {
  // g_k(x) = x^(1-k) int_0^x f'(r) (x^2 - r^2)^((k-1)/2) dr with f' = r/R + A q sin(q r) by
  // tanh-sinh on the integral as defined (about 1e-13 on its endpoint singularity; the ripple's
  // 10 periods at x = 1 mm): 1e-10.
  const double radius = 0.01, amplitude = 1e-7, wavelength = 1e-4;
  const double q = 2.0 * std::numbers::pi / wavelength;
  for (double k : {0.25, 0.75}) {
    const GradedImage g = GradedImage::by_quadrature(graded_wavy(radius, amplitude, wavelength), k);
    for (double x : {3e-5, 2.6e-4, 1e-3}) {
      boost::math::quadrature::tanh_sinh<double> rule;
      const auto integrand = [&](double r, double complement) {
        const double to_end = complement > 0.0 ? complement : x - r;
        return (r / radius + amplitude * q * std::sin(q * r)) *
               std::pow(to_end * (x + r), 0.5 * (k - 1.0));
      };
      const double exact = std::pow(x, 1.0 - k) * rule.integrate(integrand, 0.0, x, 1e-14);
      EXPECT_NEAR(g.image(x) / exact, 1.0, 1e-10) << k << " " << x;
    }
  }
}

TEST(GradedQuadrature, TableOfAParabolaIsTheParabolasImage) {
  // A table of r^2 / (2R) (the not-a-knot cubic is exact on it, and f'' jumps nowhere) split
  // at its 41 knots: the parabola's x^2 / ((1 + k) R) and its integrals to 1e-10.
  ProfileTable table;
  const double radius = 0.01;
  for (int i = 0; i <= 40; ++i) {
    const double r = 5e-5 * i;
    table.radii.push_back(r);
    table.gaps.push_back(r * r / (2.0 * radius));
  }
  const TabulatedProfile profile(table);
  for (double k : {0.25, 0.75}) {
    const GradedImage q = GradedImage::by_quadrature(graded_table(profile.interpolated_shape()), k);
    const GradedImage exact = GradedImage::of_power_law(0.5 / radius, 2.0, k);
    for (double x : {3e-5, 5e-4, 1.2345e-3, 2e-3}) {
      EXPECT_NEAR(q.image(x) / exact.image(x), 1.0, 1e-10) << k << " " << x;
      EXPECT_NEAR(q.image_slope(x) / exact.image_slope(x), 1.0, 1e-10) << k << " " << x;
      EXPECT_NEAR(q.nonadhesive_force_per_constant(x) / exact.nonadhesive_force_per_constant(x),
                  1.0, 1e-10);
      const double d = 0.5 * exact.image(x);
      EXPECT_NEAR(q.squared_gap_integral(x, d) / exact.squared_gap_integral(x, d), 1.0, 1e-10);
    }
    EXPECT_NEAR(q.radius_at_depth(exact.image(1.5e-3)) / 1.5e-3, 1.0, 1e-12);
    // Beyond the table's last point (2 mm) as the homogeneous table refuses it.
    EXPECT_THROW(q.radius_at_depth(exact.image(2.5e-3)), std::domain_error);
  }
}

}  // namespace
}  // namespace mdrsim
