// The disk check against closed forms: Hertz's and JKR's surface displacement outside the
// contact, a power law's through the incomplete beta function, and Hertz's pressure inside it;
// a wavy sphere that re-contacts outside its disk.
#include "engine/model/disk_validity.hpp"

#include <gtest/gtest.h>

#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <numbers>

#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/wavy_profile.hpp"

namespace mdrsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kR = 0.01;  // [m]
constexpr double kA = 2e-4;  // contact radius [m]
constexpr double kE = 1e6;   // E* [Pa]

/// Hertz's surface displacement outside a contact of radius a on a parabola of radius R
/// (Johnson, Contact Mechanics, eq. 3.42b): (1/(pi R)) [(2a^2 - r^2) asin(a/r) + a sqrt(r^2 -
/// a^2)].
double hertz_outside(double r) {
  return ((2.0 * kA * kA - r * r) * std::asin(kA / r) + kA * std::sqrt(r * r - kA * kA)) /
         (kPi * kR);
}

// dgamma = 0: 12 digits, from the edge (where w = a^2/(2R)) outwards.
TEST(DiskValidity, HertzSurfaceDisplacementOutsideTheContact) {
  const ParabolicProfile parabola(kR);
  const double d = kA * kA / kR;
  for (const double r : {kA, 1.0001 * kA, 1.3 * kA, 2.0 * kA, 7.7 * kA}) {
    SCOPED_TRACE(r);
    const double w = mdr_surface_displacement(parabola, kA, d, r);
    EXPECT_NEAR(w, hertz_outside(r), 1e-12 * hertz_outside(r));
  }
  EXPECT_NEAR(mdr_surface_displacement(parabola, kA, d, kA), kA * kA / (2.0 * kR), 1e-12 * d);
}

// JKR: the glued contact pulled up by dl from Hertz's depth adds a flat punch's lift,
// -(2 dl / pi) asin(a/r): 1e-12 of the Hertz term.
TEST(DiskValidity, JkrSurfaceDisplacementIsHertzMinusAPunch) {
  const ParabolicProfile parabola(kR);
  const double dl = std::sqrt(2.0 * kPi * kA * 0.05 / kE);
  const double d = kA * kA / kR - dl;
  for (const double r : {kA, 1.01 * kA, 3.0 * kA}) {
    SCOPED_TRACE(r);
    const double expected = hertz_outside(r) - 2.0 * dl / kPi * std::asin(kA / r);
    EXPECT_NEAR(mdr_surface_displacement(parabola, kA, d, r), expected, 1e-12 * hertz_outside(r));
  }
}

// A power law f = c r^n has the image g(x) = G x^n, so outside a contact of radius a
// w(r) = (2/pi) int_0^T (d - G (r sin t)^n) dt, T = asin(a/r), and int_0^T sin^n t dt is the
// incomplete beta function B(sin^2 T; (n+1)/2, 1/2) / 2. Exponents below 2 make the integrand
// in t grow like t^n at 0, which the quadrature's substitution t = T q^2 smooths: 1e-12 of the
// depth scale at every exponent, from the edge outwards.
TEST(DiskValidity, PowerLawSurfaceDisplacementOutsideTheContact) {
  for (const double n : {0.5, 1.5, 2.5}) {
    const PowerLawProfile law(0.8, n);
    const double image_coefficient = law.mdr_image(kA) / std::pow(kA, n);  // G
    const double d = 1.2 * law.mdr_image(kA);
    for (const double r : {kA, 1.0001 * kA, 1.3 * kA, 2.0 * kA, 7.7 * kA}) {
      SCOPED_TRACE(testing::Message() << "n = " << n << ", r = " << r);
      const double sine = std::min(1.0, kA / r);  // sin T
      const double top = std::asin(sine);
      const double sin_power_integral = 0.5 * boost::math::beta((n + 1.0) / 2.0, 0.5, sine * sine);
      const double expected =
          (2.0 / kPi) * (d * top - image_coefficient * std::pow(r, n) * sin_power_integral);
      EXPECT_NEAR(mdr_surface_displacement(law, kA, d, r), expected, 1e-12 * d);
    }
  }
}

// Hertz's pressure, (2 E* / (pi R)) sqrt(a^2 - r^2), to 1e-10 of p0 = 2 E* a / (pi R) (at the
// centre to 1e-9: it is taken 1e-9 a away).
TEST(DiskValidity, HertzPressureInsideTheContact) {
  const ParabolicProfile parabola(kR);
  const double d = kA * kA / kR;
  const double p0 = 2.0 * kE * kA / (kPi * kR);
  for (const double r : {0.0, 0.3 * kA, 0.9 * kA, 0.999 * kA}) {
    SCOPED_TRACE(r);
    const double expected = 2.0 * kE / (kPi * kR) * std::sqrt(kA * kA - r * r);
    EXPECT_NEAR(mdr_pressure(parabola, kE, kA, d, r), expected, (r == 0.0 ? 1e-9 : 1e-10) * p0);
  }
}

// Hertz and JKR states are one disk; nothing is reported.
TEST(DiskValidity, HertzAndJkrStatesAreOneDisk) {
  const ParabolicProfile parabola(kR);
  const double dl = std::sqrt(2.0 * kPi * kA * 0.05 / kE);
  for (const double d : {kA * kA / kR, kA * kA / kR - dl}) {
    const DiskValidity check = check_disk(parabola, kE, kA, d, kA);
    EXPECT_TRUE(check.valid);
    EXPECT_FALSE(check.worst_radius.has_value());
  }
  // Pressed without glue, the whole Hertz disk is checked for pressure too.
  EXPECT_TRUE(check_disk(parabola, kE, kA, kA * kA / kR, 0.0).valid);
}

// A wavy sphere (R = 1 cm, lambda = 100 um) pressed without adhesion to the depth g(a) that
// puts its edge spring at rest at a = 0.6 lambda, just past the first crest: outside the
// contact the ripple's trough closes the gap once A >= A* = 8.11891963563612e-8 m, an
// annular re-contact. A* and the gap at 1.01 A* (-1.4937839669700667e-10 m at r =
// 6.714939520462187e-5 m) are from an independent computation (SciPy: g through the Struve
// function H0, w by adaptive quadrature, the minimum by a bounded Brent search).
TEST(DiskValidity, WavySphereRecontactsOutsideItsDiskAboveTheThresholdAmplitude) {
  constexpr double kThreshold = 8.11891963563612e-8;
  constexpr double kWavelength = 1e-4;
  const double a = 0.6 * kWavelength;
  const WavyProfile below(kR, 0.99 * kThreshold, kWavelength);
  const DiskValidity one_disk = check_disk(below, kE, a, below.mdr_image(a), a);
  EXPECT_TRUE(one_disk.valid);
  const WavyProfile above(kR, 1.01 * kThreshold, kWavelength);
  const DiskValidity annulus = check_disk(above, kE, a, above.mdr_image(a), a);
  EXPECT_FALSE(annulus.valid);
  EXPECT_EQ(annulus.violation, DiskValidity::Violation::gap);
  ASSERT_TRUE(annulus.worst_radius.has_value());
  // The minimum of a smooth gap: its value to 1e-6, its place to about sqrt(1e-13) of it.
  EXPECT_NEAR(annulus.worst, -1.4937839669700667e-10, 1e-6 * 1.4937839669700667e-10);
  EXPECT_NEAR(*annulus.worst_radius, 6.714939520462187e-5, 1e-3 * 6.714939520462187e-5);
}

}  // namespace
}  // namespace mdrsim
