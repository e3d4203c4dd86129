// The wavy profile against independent quadratures: its ripple integrals against
// Gauss-Kronrod, its image against the MDR transform of its shape, and A = 0 as the parabola.
#include "profiles/wavy_profile.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <numbers>

#include "profiles/mdr_transform.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/profile_registry.hpp"
#include "profiles/wavy_image.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;

/// int_0^{pi/2} h(t) dt by 61-point Gauss-Kronrod on panels of at most one oscillation of
/// sin(z sin t) (z / (2 pi) of them, at least 4): independent of the Bessel sums.
template <class F>
double oscillatory_integral(F h, double z) {
  const int panels = 4 + static_cast<int>(z / (2.0 * kPi));
  double sum = 0.0;
  for (int i = 0; i < panels; ++i) {
    const double lo = 0.5 * kPi * i / panels;
    const double hi = 0.5 * kPi * (i + 1) / panels;
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(h, lo, hi, 0, 0.0);
  }
  return sum;
}

// I(z) and I'(z) to 1e-13 absolute (both are O(1): |I| < 1.4, |I'| <= 1) on both sides of
// the switches from the power series to the Bessel sums (z = 1) and to the asymptotic series
// (z = 32), and far out (z = 1.6e6 is a 2e-9 m ripple at 5e-4 m: the fuzzer's input, whose
// Bessel sums took 1.6e6 steps per call).
TEST(WavyImage, RippleIntegralsMatchQuadrature) {
  for (const double z : {1e-6, 0.01, 0.5, 0.999999, 1.0, 1.000001, 2.5, 10.0, 31.999999, 32.0,
                         32.000001, 40.5, 47.3, 99.999999, 100.0, 300.0, 2500.0, 1e5, 1.6e6}) {
    SCOPED_TRACE(z);
    const RippleIntegrals ripple = ripple_integrals(z);
    const double value =
        oscillatory_integral([z](double t) { return std::sin(z * std::sin(t)); }, z);
    const double slope =
        oscillatory_integral([z](double t) { return std::sin(t) * std::cos(z * std::sin(t)); }, z);
    EXPECT_NEAR(ripple.value, value, 1e-13);
    EXPECT_NEAR(ripple.slope, slope, 1e-13);
  }
}

// 1 - I'(z) = int_0^{pi/2} 2 sin t sin^2(z sin t / 2) dt, an integrand of one sign: relative
// 1e-13 also where z is small and 1 - I' is z^2/3 (formed from I' it would keep eps/z^2 of it).
TEST(WavyImage, SlopeDeficitMatchesQuadratureRelatively) {
  for (const double z : {1e-6, 1e-3, 0.3, 0.999999, 1.0, 2.5, 31.999999, 32.0, 47.3, 1e4}) {
    SCOPED_TRACE(z);
    const double deficit = oscillatory_integral(
        [z](double t) {
          const double half = std::sin(0.5 * z * std::sin(t));
          return 2.0 * std::sin(t) * half * half;
        },
        z);
    EXPECT_NEAR(ripple_integrals(z).slope_deficit, deficit, 1e-13 * deficit);
  }
}

// The non-adhesive force per modulus in closed form (Struve's int z H_0 = z H_1) against its
// definition 2 int_0^a (g(a) - g(x)) dx by Gauss-Kronrod on panels of a tenth of a wavelength:
// 1e-13 of 2 a g(a) + the ripple's A a, the size of the terms (the image is good to about 1e-15
// of its scale, the quadrature to rounding), on a gentle and a strong ripple, inside the first
// crest and far out.
TEST(WavyProfile, NonadhesiveForceIsItsDefinition) {
  for (const double amplitude : {1e-8, 1e-6}) {
    const double radius = 0.01, wavelength = 1e-4;
    const WavyProfile profile(radius, amplitude, wavelength);
    for (const double a : {1e-7, 3e-6, 4.9e-5, 2.5e-4, 5e-4, 2.3e-3}) {
      SCOPED_TRACE(testing::Message() << amplitude << " " << a);
      const double ga = profile.mdr_image(a);
      const int panels = 4 + static_cast<int>(10.0 * a / wavelength);
      double sum = 0.0;
      for (int i = 0; i < panels; ++i) {
        sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
            [&](double x) { return ga - profile.mdr_image(x); }, a * i / panels,
            a * (i + 1) / panels, 0, 0.0);
      }
      const double scale = 2.0 * a * (std::abs(ga) + amplitude);
      EXPECT_NEAR(profile.nonadhesive_force_per_modulus(a), 2.0 * sum, 1e-13 * scale);
    }
  }
}

// The image against eq. 4 by tanh-sinh quadrature of the shape's slope (mdr_transform), on a
// ripple strong enough that g decreases between crests (A k^2 R = 3.9): 1e-10 of g's scale.
TEST(WavyProfile, ImageIsTheMdrTransformOfTheShape) {
  const double radius = 0.01, amplitude = 1e-6, wavelength = 1e-4;
  const WavyProfile profile(radius, amplitude, wavelength);
  const double k = 2.0 * kPi / wavelength;
  const auto slope = [&](double r) { return r / radius + amplitude * k * std::sin(k * r); };
  bool decreases = false;
  double previous = 0.0;
  for (int i = 1; i <= 60; ++i) {
    const double x = 7.3e-6 * i;
    SCOPED_TRACE(x);
    const double g = profile.mdr_image(x);
    const double scale = x * x / radius + amplitude;
    EXPECT_NEAR(g, mdr_transform(slope, x), 1e-10 * scale);
    decreases = decreases || g < previous;
    previous = g;
  }
  EXPECT_TRUE(decreases);  // the case the engine's profiles did not have
}

// g' against a fourth-order central difference of g (step 1e-3 of the wavelength: truncation
// h^4 g^(5) / 30, about 3e-12 of the slope's scale A k + x / R here; rounding smaller).
TEST(WavyProfile, SlopeIsTheImagesDerivative) {
  const double radius = 0.01, amplitude = 1e-6, wavelength = 1e-4;
  const WavyProfile profile(radius, amplitude, wavelength);
  const double h = 1e-3 * wavelength;
  const auto g = [&](double x) { return profile.mdr_image(x); };
  for (const double x : {3e-7, 2e-5, 1.1e-4, 6.66e-4}) {
    SCOPED_TRACE(x);
    const double difference =
        (8.0 * (g(x + h) - g(std::abs(x - h))) - (g(x + 2.0 * h) - g(std::abs(x - 2.0 * h)))) /
        (12.0 * h);
    const double scale = amplitude * 2.0 * kPi / wavelength + x / radius;
    EXPECT_NEAR(profile.mdr_image_slope(x), difference, 1e-9 * scale);
  }
}

// The inverse transform (eq. 5) of the image gives the shape back: 1e-9 of its scale.
TEST(WavyProfile, InverseTransformOfTheImageIsTheShape) {
  const WavyProfile profile(0.01, 3e-7, 5e-5);
  for (const double r : {1e-5, 4.2e-5, 1.3e-4}) {
    SCOPED_TRACE(r);
    const double f = inverse_mdr_transform([&](double x) { return profile.mdr_image(x); }, r);
    EXPECT_NEAR(f, profile.shape(r), 1e-9 * (r * r / 0.02 + 3e-7));
  }
}

// Amplitude 0 is the parabola itself, so that every result is `parabolic`'s bit for bit.
TEST(WavyProfile, RegistryBuildsTheParabolaForAmplitudeZero) {
  ProfileRegistry registry;
  register_builtin_profiles(registry);
  ParameterValues flat;
  flat.set("radius", 0.01);
  flat.set("amplitude", 0.0);
  flat.set("wavelength", 1e-4);
  const auto parabola = registry.find("wavy")->create(flat);
  ASSERT_NE(dynamic_cast<const ParabolicProfile*>(parabola.get()), nullptr);
  ParameterValues wavy = flat;
  wavy.set("amplitude", 1e-7);
  const auto rippled = registry.find("wavy")->create(wavy);
  EXPECT_NE(dynamic_cast<const WavyProfile*>(rippled.get()), nullptr);
}

}  // namespace
}  // namespace mdrsim
