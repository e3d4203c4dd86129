// The disk check: the MDR gap outside the contact and pressure inside it, by quadrature.
#include "engine/model/disk_validity.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>

#include "engine/base/bracketed_minimum.hpp"

namespace mdrsim {
namespace {

constexpr double kNegativeShare = 1e-9;  ///< of the depth scale: below is a violation
constexpr int kGapSamples = 200;
constexpr int kPressureSamples = 200;
constexpr double kOuterFactor = 10.0;  ///< the gap is checked out to 10 a

/// int_lo^hi f by 20-point Gauss-Legendre on panels halved where they need it: a panel whose
/// halves sum to its own value within its share of 1e-12 of `scale` (by width) is done, down
/// to 1/1024 of the interval. That difference is the error of the panel itself: its halves,
/// the value kept, are more accurate by far (the tests hold Hertz's, JKR's and power laws'
/// displacement to 1e-12 of the depth, against a check whose threshold is 1e-9). Smooth
/// integrands take a panel and its two halves; a kink (a table's knot, a profile's corner) or
/// an oscillation (a wavy image) is refined where it is, not over the whole interval (halving
/// every panel took a kinked table's check a second).
template <class F>
double integral(F f, double lo, double hi, double scale) {
  constexpr int kDeepest = 10;
  const double tolerance = 1e-12 * scale / (hi - lo);  // per unit of width
  const auto gauss = [&](double a, double b) {
    return boost::math::quadrature::gauss<double, 20>::integrate(f, a, b);
  };
  const auto refine = [&](const auto& self, double a, double b, double whole, int depth) -> double {
    const double mid = 0.5 * (a + b);
    const double left = gauss(a, mid);
    const double right = gauss(mid, b);
    const double halves = left + right;
    if (depth >= kDeepest || std::abs(halves - whole) <= tolerance * (b - a)) return halves;
    return self(self, a, mid, left, depth + 1) + self(self, mid, b, right, depth + 1);
  };
  return refine(refine, lo, hi, gauss(lo, hi), 1);
}

}  // namespace

double mdr_surface_displacement(const Profile& profile, double contact_radius, double indentation,
                                double radius) {
  const double top = std::asin(std::min(1.0, contact_radius / radius));
  const double scale = std::abs(indentation) + std::abs(profile.mdr_image(contact_radius));
  // t = top q^2: an image that grows like x^n with n < 2 at the centre (a power law r^1.5, a
  // table of one) makes the integrand in t grow like t^n there, on which Gauss panels converge
  // slowly (a 201-point table of 0.8 r^1.5: 680 panels per integral on average, 45 % of them
  // stopping at the 1024 cap, 0.6 s for one continuum run); in q it grows like q^(2n+1).
  const auto in_q = [&](double q) {
    const double t = top * q * q;
    return 2.0 * top * q * (indentation - profile.mdr_image(radius * std::sin(t)));
  };
  return (2.0 / std::numbers::pi) * integral(in_q, 0.0, 1.0, scale);
}

double mdr_pressure(const Profile& profile, double effective_modulus, double contact_radius,
                    double indentation, double radius) {
  const double a = contact_radius;
  const double span = std::sqrt(std::max(0.0, a * a - radius * radius));
  const double edge = (indentation - profile.mdr_image(a)) / span;
  // x = r cosh u: dx / sqrt(x^2 - r^2) = du, smooth for r > 0.
  // At the centre itself, 1e-9 a next to it (a cone's pressure is log-singular there).
  const double r = std::max(radius, 1e-9 * a);
  const double top = std::acosh(a / r);
  const double inside =
      integral([&](double u) { return profile.mdr_image_slope(r * std::cosh(u)); }, 0.0, top,
               std::abs(profile.mdr_image_slope(a)) * top);
  return effective_modulus / std::numbers::pi * (edge + inside);
}

DiskValidity check_disk(const Profile& profile, double effective_modulus, double contact_radius,
                        double indentation, double unglued_from) {
  DiskValidity out;
  const double a = contact_radius;
  if (!(a > 0.0)) return out;
  const double depth = std::max(std::abs(indentation), std::abs(profile.mdr_image(a)));
  const double gap_floor = -kNegativeShare * depth;
  const double r_max = std::min(kOuterFactor * a, profile.outer_radius());
  const auto gap = [&](double r) {
    return mdr_surface_displacement(profile, a, indentation, r) + profile.shape(r) - indentation;
  };
  if (r_max > a) {
    // Crowded towards a, where the gap opens from zero.
    double lowest = 0.0;
    int at = -1;
    for (int j = 1; j <= kGapSamples; ++j) {
      const double s = static_cast<double>(j) / kGapSamples;
      const double r = a + (r_max - a) * s * s;
      const double h = gap(r);
      if (h < lowest) {
        lowest = h;
        at = j;
      }
    }
    if (at >= 0) {
      const auto radius_of = [&](int j) {
        const double s = static_cast<double>(std::clamp(j, 0, kGapSamples)) / kGapSamples;
        return a + (r_max - a) * s * s;
      };
      const Minimum best = bracketed_minimum(gap, radius_of(at - 1), radius_of(at + 1), 40);
      if (best.value < lowest) lowest = best.value;
      if (lowest < gap_floor) {
        out.valid = false;
        out.violation = DiskValidity::Violation::gap;
        out.worst = lowest;
        out.worst_radius = best.value <= gap(radius_of(at)) ? best.at : radius_of(at);
      }
    }
  }
  const double c = std::max(0.0, unglued_from);
  if (out.valid && c < a && indentation >= profile.mdr_image(a)) {
    const double pressure_floor = -kNegativeShare * effective_modulus * depth / a;
    for (int j = 0; j < kPressureSamples; ++j) {
      const double r = c + (a - c) * (j + 0.5) / kPressureSamples;
      const double p = mdr_pressure(profile, effective_modulus, a, indentation, r);
      if (p < std::min(out.worst, pressure_floor)) {
        out.valid = false;
        out.violation = DiskValidity::Violation::pressure;
        out.worst = p;
        out.worst_radius = r;
      }
    }
  }
  return out;
}

}  // namespace mdrsim
