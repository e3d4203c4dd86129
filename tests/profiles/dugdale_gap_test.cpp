// The Dugdale zone's gap integral J(a, t) and its slope dJ/dt: the closed forms (parabola, cone,
// power laws) and the quadrature against an independent 50-digit quadrature of the definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/power_law_profile.hpp"
#include "profiles/profile.hpp"
#include "profiles/sphere_profile.hpp"
#include "profiles/tabulated_profile.hpp"
#include "profiles/wavy_gap.hpp"
#include "profiles/wavy_profile.hpp"

namespace mdrsim {
namespace {

using Wide = boost::multiprecision::cpp_bin_float_50;
using WideImage = std::function<Wide(const Wide&)>;

/// J = int_0^t (g(c cos psi) - g(a)) dpsi, c = a / cos t, as defined (no integration by parts),
/// in 50 digits: the difference cancels to 1e-50 g(a) out of ~ g'(a) a t^2, 1e-34 relative at
/// t = 1e-8, and the 61-point Kronrod rule is halved until its Gauss half agrees to 1e-30 (a
/// tolerance below that noise would halve it to the depth limit).
Wide wide_gap(const WideImage& g, const Wide& a, const Wide& t) {
  const Wide c = a / cos(t);
  const Wide ga = g(a);
  // Over psi = t u, u in [0, 1]: Boost's error estimate is not scaled by the interval's width,
  // so on [0, t] the rounding of g - g(a) alone would exceed 1e-30 of the integral at t = 1e-8.
  return boost::math::quadrature::gauss_kronrod<Wide, 61>::integrate(
      [&](const Wide& u) { return Wide(t * (g(c * cos(t * u)) - ga)); }, Wide(0), Wide(1), 12,
      Wide(1e-30));
}

struct WideGap {
  double integral;
  double angle_slope;
  /// What the rounding of each is relative to: the integrals of their integrands' magnitudes
  /// (J and dJ/dt themselves where unset).
  double integral_mass = 0.0;
  double angle_slope_mass = 0.0;
};

/// J and dJ/dt at fixed a, the slope by a central difference of J in t with the step 1e-12 t:
/// its truncation 1e-24 and the quadrature's 1e-30 over 1e-12 stay below a double's ulp.
WideGap wide_gap_and_slope(const WideImage& g, double a, double t) {
  const Wide h = Wide(1e-12) * t;
  const Wide slope = (wide_gap(g, a, Wide(t) + h) - wide_gap(g, a, Wide(t) - h)) / (2 * h);
  return {static_cast<double>(wide_gap(g, a, t)), static_cast<double>(slope)};
}

/// Zone angles from a thin zone (the series in t, JKR side) through the switches of the power
/// law's forms (t = min(0.75, sqrt(2/n)), pi/2 - t = min(1.5, sqrt(6/n))) and of the sphere's
/// (c = R/2 at a = 3e-3 R/0.01, t = 0.9273) to a zone thousands of times the contact (DMT side).
const std::vector<double> kAngles = {1e-8, 1e-6, 1e-4, 1e-2, 0.07,  0.1, 0.2, 0.3, 0.44, 0.46,
                                     0.7,  0.74, 0.76, 0.92, 0.935, 1.0, 1.1, 1.3, 1.5,  1.5702};

void expect_gap(const std::string& what, const DugdaleGap& gap, const WideGap& wide,
                double tolerance) {
  const double integral_mass = std::max(wide.integral_mass, std::abs(wide.integral));
  const double slope_mass = std::max(wide.angle_slope_mass, std::abs(wide.angle_slope));
  EXPECT_NEAR(gap.integral, wide.integral, tolerance * integral_mass) << what;
  EXPECT_NEAR(gap.angle_slope, wide.angle_slope, tolerance * slope_mass) << what;
}

// The closed forms within 2e-14 (the worst seen: 5e-15, the cone's tan t - t at t = 0.1): each
// sums a few terms of one sign (the parabola's a^2 (tan t - t) + t s^2), or series whose
// alternating terms sum to at most e^2 times their sum (the power law's), or subtracts where
// at most 3/(n t^2) ulps are lost (the power law's H - t cos^n t above t = min(0.75,
// sqrt(2/n)): 11 at n = 1/2); c = a / cos t and the powers c^n round to a few ulps more.
TEST(DugdaleGap, ClosedFormsMatchA50DigitQuadrature) {
  const double a = 2e-4;
  const double radius = 0.01;
  const ParabolicProfile parabola(radius);
  const ConeProfile cone(30.0);
  // The images' coefficients as the profiles hold them (the closed forms' inputs).
  const Wide cone_slope = cone.mdr_image(1.0);
  for (const double t : kAngles) {
    const double c = a / std::cos(t);
    const std::string at = "t = " + std::to_string(t);
    expect_gap("parabola " + at, parabola.dugdale_gap(a, c, t),
               wide_gap_and_slope([&](const Wide& x) { return Wide(x * x / radius); }, a, t),
               2e-14);
    expect_gap("cone " + at, cone.dugdale_gap(a, c, t),
               wide_gap_and_slope([&](const Wide& x) { return Wide(cone_slope * x); }, a, t),
               2e-14);
    for (const double n : {0.5, 1.0, 1.5, 2.5, 4.0, 6.0, 7.0, 12.0}) {
      const PowerLawProfile power(3e3, n);
      const Wide k = power.mdr_image(1.0);
      expect_gap("power law n = " + std::to_string(n) + " " + at, power.dugdale_gap(a, c, t),
                 wide_gap_and_slope([&](const Wide& x) { return Wide(k * pow(x, Wide(n))); }, a, t),
                 2e-14);
    }
  }
}

// The quadrature (dugdale_gap_quadrature) within 2e-14 where the image's slope is exact: the
// parabola and the power law x^1.5 (the closed forms' images, through the generic path) and the
// sphere, whose image x artanh(x/R) has no closed-form gap integral (its series, SphereProfile::
// dugdale_gap, to c = R/2; the quadrature beyond), out to c = 0.999 R, where g' grows like
// R/(R - x). The integrands have no difference to cancel: the rule's own error
// (1e-13 of the mass on the Gauss half of each panel, the Kronrod sum far closer) and a few
// ulps of rounding remain (the worst seen: 1e-15).
TEST(DugdaleGap, QuadratureMatchesA50DigitQuadrature) {
  const double radius = 0.01;
  const SphereProfile sphere(radius);
  const PowerLawProfile power(3e3, 1.5);
  const ParabolicProfile parabola(radius);
  for (const double a : {2e-4, 3e-3}) {
    for (const double t : kAngles) {
      const double c = a / std::cos(t);
      const std::string at = "a = " + std::to_string(a) + " t = " + std::to_string(t);
      expect_gap("parabola " + at, dugdale_gap_quadrature(parabola, a, c, t),
                 wide_gap_and_slope([&](const Wide& x) { return Wide(x * x / radius); }, a, t),
                 2e-14);
      const DugdaleGap closed = power.dugdale_gap(a, c, t);
      const DugdaleGap by_quadrature = dugdale_gap_quadrature(power, a, c, t);
      EXPECT_NEAR(by_quadrature.integral, closed.integral, 2e-14 * closed.integral) << at;
      EXPECT_NEAR(by_quadrature.angle_slope, closed.angle_slope, 2e-14 * closed.angle_slope) << at;
      if (c > 0.999 * radius) continue;
      expect_gap(
          "sphere " + at, sphere.dugdale_gap(a, c, t),
          wide_gap_and_slope([&](const Wide& x) { return Wide(x * atanh(x / radius)); }, a, t),
          2e-14);
    }
  }
}

// A table of the parabola: its spline reproduces r^2/(2R) and the Hermite image reproduces
// x^2/R between its nodes, which carry eq. 4's values to their rounding: the quadrature of the
// tabulated image meets the parabola's closed form within 1e-13 (the worst seen: 3e-14).
TEST(DugdaleGap, TabulatedParabolaMeetsTheClosedForm) {
  const double radius = 0.01;
  ProfileTable table;
  for (int i = 0; i <= 40; ++i) {
    const double r = 2e-3 * i / 40.0;
    table.radii.push_back(r);
    table.gaps.push_back(r * r / (2.0 * radius));
  }
  const TabulatedProfile tabulated(table);
  const ParabolicProfile parabola(radius);
  for (const double t : {1e-6, 1e-3, 0.1, 0.5, 1.0, 1.2}) {
    const double a = 5e-4, c = a / std::cos(t);
    const DugdaleGap exact = parabola.dugdale_gap(a, c, t);
    const DugdaleGap table_gap = tabulated.dugdale_gap(a, c, t);
    EXPECT_NEAR(table_gap.integral, exact.integral, 1e-13 * exact.integral) << t;
    EXPECT_NEAR(table_gap.angle_slope, exact.angle_slope, 1e-13 * exact.angle_slope) << t;
  }
}

/// J and dJ/dt of a table's image by 15-point Gauss-Kronrod in the angle, 16 equal panels on
/// each of the image's Hermite pieces (split at its knots' angles arccos(x_k / c), so that every
/// panel's integrand is smooth: a trig polynomial of degree 3, times psi sin(psi) by parts,
/// whose 7-point Gauss half alone is exact to rounding on panels below 0.02 wide); J by parts
/// below t = 0.3, c g'(x) psi sin(psi), where g(x) - g(a) would cancel.
WideGap fine_table_gap(const TabulatedProfile& tabulated, double a, double t) {
  using Rule = boost::math::quadrature::gauss_kronrod<double, 15>;
  const double c = a / std::cos(t);
  const bool by_parts = t < 0.3;
  const double image_at_contact = tabulated.mdr_image(a);
  std::vector<double> ends = {0.0};
  const std::vector<double>& knots = tabulated.interpolated_image().knots();
  for (auto k = knots.rbegin(); k != knots.rend(); ++k) {
    if (*k<c&& * k> a) ends.push_back(std::acos(*k / c));
  }
  ends.push_back(t);
  double integral = 0.0, slope = 0.0, integral_mass = 0.0, slope_mass = 0.0;
  constexpr int kPanels = 16;
  for (std::size_t piece = 0; piece + 1 < ends.size(); ++piece) {
    for (int p = 0; p < kPanels; ++p) {
      const double width = ends[piece + 1] - ends[piece];
      const double lo = ends[piece] + width * p / kPanels;
      const double hi = ends[piece] + width * (p + 1) / kPanels;
      // The piece's own cubic throughout the panel, at its middle.
      const double x_mid = c * std::cos(0.5 * (lo + hi));
      const std::size_t k = tabulated.interpolated_image().piece(x_mid);
      const ShapePreservingCubic& image = tabulated.interpolated_image();
      const auto gap_integrand = [&](double psi) {
        const double x = c * std::cos(psi);
        return by_parts ? c * image.slope_on(k, x) * psi * std::sin(psi)
                        : image.value_on(k, x) - image_at_contact;
      };
      const auto slope_integrand = [&](double psi) {
        return c * std::cos(psi) * image.slope_on(k, c * std::cos(psi));
      };
      integral += Rule::integrate(gap_integrand, lo, hi, 0, 0.0);
      slope += Rule::integrate(slope_integrand, lo, hi, 0, 0.0);
      integral_mass +=
          Rule::integrate([&](double psi) { return std::abs(gap_integrand(psi)); }, lo, hi, 0, 0.0);
      slope_mass += Rule::integrate([&](double psi) { return std::abs(slope_integrand(psi)); }, lo,
                                    hi, 0, 0.0);
    }
  }
  return {integral, std::tan(t) * slope, integral_mass, std::tan(t) * slope_mass};
}

// A table of the sphere (200 points to 0.6 R, the bench's): its gap on the image's Hermite
// pieces (TabulatedProfile::dugdale_gap) against the fine quadrature, within 2e-14 (the worst
// seen: 5e-15), from a zone inside one piece (t = 1e-6) to one 14 times the contact. The adaptive
// default missed dJ/dt by up to 1e-10 there: its panels are halved for J alone.
TEST(DugdaleGap, TabulatedSphereMatchesAFineQuadratureOnEveryPiece) {
  const double radius = 0.01;
  ProfileTable table;
  for (int i = 0; i < 200; ++i) {
    const double r = 0.6 * radius * i / 199.0;
    table.radii.push_back(r);
    table.gaps.push_back(radius - std::sqrt(radius * radius - r * r));
  }
  const TabulatedProfile tabulated(table);
  for (const double a : {2.5e-4, 1e-3}) {
    for (const double t : {1e-6, 1e-3, 0.01, 0.1, 0.29, 0.31, 0.7, 1.3, 1.5}) {
      const double c = a / std::cos(t);
      if (c > 0.6 * radius) continue;  // past the table's end
      const std::string at = "a = " + std::to_string(a) + " t = " + std::to_string(t);
      expect_gap(at, tabulated.dugdale_gap(a, c, t), fine_table_gap(tabulated, a, t), 2e-14);
    }
  }
}

// A rough table: 1500 points of the sphere with a ripple of 1 % of the gap at every fourth
// point (the image's grid keeps every second point, so its cubic pieces bend at their own
// scale: their Taylor terms about an arc's middle are as large as the gap's change there,
// where a smooth image's fall off with the piece's width). J and dJ/dt change sign along the
// zone, so the tolerance is relative to their integrands' magnitudes: 1e-13 (the worst seen:
// 7e-14, on thin zones, t = 0.1; 3e-14 above t = 0.3). The 4- and 8-node Gauss rules the arcs'
// closed form replaced erred by up to 6e-11 here: their error grows with a piece's bending,
// (c/h)^2 times the smooth image's.
TEST(DugdaleGap, RoughTableMatchesAFineQuadratureOnEveryPiece) {
  const double radius = 0.01;
  ProfileTable table;
  for (int i = 0; i < 1500; ++i) {
    const double r = 0.6 * radius * i / 1499.0;
    const double ripple = 1.0 + 0.01 * std::sin(0.5 * std::numbers::pi * i);
    table.radii.push_back(r);
    table.gaps.push_back((radius - std::sqrt(radius * radius - r * r)) * ripple);
  }
  const TabulatedProfile tabulated(table);
  for (const double a : {2.5e-4, 1e-3}) {
    for (const double t : {1e-3, 0.01, 0.1, 0.29, 0.31, 0.7, 1.3, 1.5}) {
      const double c = a / std::cos(t);
      if (c > 0.6 * radius) continue;  // past the table's end
      const std::string at = "a = " + std::to_string(a) + " t = " + std::to_string(t);
      expect_gap(at, tabulated.dugdale_gap(a, c, t), fine_table_gap(tabulated, a, t), 1e-13);
    }
  }
}

// The wavy profile's J and dJ/dt (the parabola's closed form and wavy_ripple_gap: the order of
// the MDR transform's double integral exchanged, on fixed Gauss rules) against the adaptive
// quadrature of its image's slope (dugdale_gap_quadrature, which the ripple integrals'
// Bessel sums feed), over ripples from a gentle one to one whose image falls between crests
// (A k^2 R from 0.004 to 440), contacts from a small part of a wavelength to 40 of them, and
// zones from t = 1e-8 (J ~ t^3, where the rule's parts of order t^2 would cancel) to 14 times
// the contact. Where the ripple outweighs the curvature J changes sign along the zone and
// the parts of its integral are far larger than J itself: the tolerance, 2e-14, is relative to
// the J of the parabolas r^2/(2R) and A k^2 r^2/2 together, the size of the two curvatures'
// shares (the worst seen: 7e-15, at t = 0.1 and 0.3, where the rule switches its form).
TEST(DugdaleGap, WavyGapMatchesTheAdaptiveQuadrature) {
  const double radius = 0.01;
  const ParabolicProfile parabola(radius);
  for (const double amplitude : {1e-8, 1e-7, 1e-6}) {
    for (const double wavelength : {1e-3, 1e-4, 3e-5}) {
      const WavyProfile wavy(radius, amplitude, wavelength);
      const double k = 2.0 * std::numbers::pi / wavelength;
      const ParabolicProfile ripple_curvature(1.0 / (amplitude * k * k));
      for (const double a : {1e-7, 3e-6, 2.4e-5, 1e-4, 2.05e-4, 5e-4, 1.3e-3}) {
        for (const double t :
             {1e-8, 1e-6, 1e-4, 1e-2, 0.07, 0.1, 0.2, 0.29, 0.31, 0.45, 0.55, 0.7, 1.0, 1.3, 1.5}) {
          const double c = a / std::cos(t);
          const std::string at = "A = " + std::to_string(amplitude) +
                                 " lambda = " + std::to_string(wavelength) +
                                 " a = " + std::to_string(a) + " t = " + std::to_string(t);
          const DugdaleGap gap = wavy.dugdale_gap(a, c, t);
          const DugdaleGap reference = dugdale_gap_quadrature(wavy, a, c, t);
          const DugdaleGap scale_r = parabola.dugdale_gap(a, c, t);
          const DugdaleGap scale_k = ripple_curvature.dugdale_gap(a, c, t);
          EXPECT_NEAR(gap.integral, reference.integral,
                      2e-14 * (scale_r.integral + scale_k.integral))
              << at;
          EXPECT_NEAR(gap.angle_slope, reference.angle_slope,
                      2e-14 * (scale_r.angle_slope + scale_k.angle_slope))
              << at;
        }
      }
    }
  }
}

// A zone around a contact of radius 0 is the ripple's (pi/2) f(c), dJ/dt = (pi/2) f'(c) c tan t;
// beyond kMaxWavyGapHalfWaves half wavelengths in the contact the profile takes the quadrature.
TEST(DugdaleGap, WavyGapAtTheAxisAndBeyondItsRule) {
  const double radius = 0.01, amplitude = 1e-7, wavelength = 1e-4;
  const WavyProfile wavy(radius, amplitude, wavelength);
  const double k = 2.0 * std::numbers::pi / wavelength;
  const double c = 3.3e-4, t = 0.5 * std::numbers::pi;
  const DugdaleGap ripple = wavy_ripple_gap(amplitude, k, 0.0, c, t);
  const double half_pi = 0.5 * std::numbers::pi;
  EXPECT_NEAR(ripple.integral, half_pi * amplitude * (1.0 - std::cos(k * c)), 1e-15 * amplitude);
  EXPECT_NEAR(ripple.angle_slope, half_pi * amplitude * k * std::sin(k * c) * c * std::tan(t),
              1e-15 * amplitude * k * c * std::tan(t));
  const double a = 1.01 * kMaxWavyGapHalfWaves * wavelength / 2.0, t_far = 0.4;
  const DugdaleGap far = wavy.dugdale_gap(a, a / std::cos(t_far), t_far);
  const DugdaleGap quadrature = dugdale_gap_quadrature(wavy, a, a / std::cos(t_far), t_far);
  EXPECT_EQ(far.integral, quadrature.integral);
  EXPECT_EQ(far.angle_slope, quadrature.angle_slope);
}

}  // namespace
}  // namespace mdrsim
