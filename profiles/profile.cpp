// Numerical defaults of the Profile interface: root search on g(x) and quadrature of the force.
#include "profiles/profile.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

/// Smallest x in [0, outer] with fn(x) >= target, for fn non-decreasing; throws if none.
/// An fn that diverges at a finite outer edge (the sphere's image at r = R) is approached
/// from inside, halving the distance to the edge until fn reaches the target.
template <class Fn>
double invert_increasing(Fn fn, double target, double outer, const char* what) {
  if (fn(0.0) >= target) return 0.0;
  const auto out_of_reach = [&] {
    return std::domain_error(std::string(what) + " is out of the profile's reach");
  };
  double lo = 0.0;
  double hi = std::isfinite(outer) ? outer : 1.0;
  if (!std::isfinite(outer)) {
    for (int i = 0; fn(hi) < target; ++i) {
      if (i > 2000) throw out_of_reach();
      lo = hi;
      hi *= 2.0;
    }
  } else if (const double at_edge = fn(outer); !std::isfinite(at_edge)) {
    double gap = 0.5 * outer;
    hi = outer - gap;
    while (fn(hi) < target) {
      lo = hi;
      gap *= 0.5;
      hi = outer - gap;
      if (!(hi > lo)) throw out_of_reach();
    }
  } else if (at_edge < target) {
    throw out_of_reach();
  }
  // Narrow [0, hi] to [hi/2, hi] by halving: with 0 as an end the relative tolerance below
  // cannot converge on a tiny root (R = 1e-100 m gives a ~ 1e-37 m).
  if (lo == 0.0) {
    for (double half = 0.5 * hi; fn(half) >= target; half *= 0.5)
      hi = half;  // ends: fn(0) < target
    lo = 0.5 * hi;
  }
  return bracket_root([&](double x) { return fn(x) - target; }, lo, hi,
                      std::numeric_limits<double>::digits - 2)
      .hi;
}

}  // namespace

double Profile::mdr_image_slope(double x) const {
  if (!(x > 0.0)) {
    const double h = 1e-9;
    return (mdr_image(h) - mdr_image(0.0)) / h;
  }
  const double h = 1e-3 * x;
  return (8.0 * (mdr_image(x + h) - mdr_image(x - h)) -
          (mdr_image(x + 2 * h) - mdr_image(x - 2 * h))) /
         (12.0 * h);
}

double Profile::contact_radius_at_depth(double depth) const {
  return invert_increasing([this](double x) { return mdr_image(x); }, depth, outer_radius(),
                           "the preload depth");
}

double Profile::nonadhesive_force_per_modulus(double contact_radius) const {
  const double ga = mdr_image(contact_radius);
  const double integral = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double x) { return ga - mdr_image(x); }, 0.0, contact_radius, 12, 1e-14);
  return 2.0 * integral;
}

double Profile::dugdale_gap_integral(double contact_radius, double cohesive_radius,
                                     double angle) const {
  const double ga = mdr_image(contact_radius);
  // x = c cos(psi): dx / sqrt(c^2 - x^2) = -dpsi, from psi = 0 (x = c) to t (x = a). The
  // integrand g(c cos psi) - g(a) cancels to about eps g(a) out of g'(a) a t^2, so no rule
  // gets the integral closer than 4 eps / t^2 relative; asking for more only bisects noise.
  const double noise = 4.0 * std::numeric_limits<double>::epsilon() / (angle * angle);
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
      [&](double psi) { return mdr_image(cohesive_radius * std::cos(psi)) - ga; }, 0.0, angle, 10,
      std::max(1e-14, noise));
}

double contact_radius_at_force(const Profile& profile, double force, double effective_modulus) {
  if (const auto fixed = profile.fixed_contact_radius()) return *fixed;
  return invert_increasing([&](double a) { return profile.nonadhesive_force_per_modulus(a); },
                           force / effective_modulus, profile.outer_radius(), "the preload force");
}

}  // namespace mdrsim
