// Numerical defaults of the Profile interface: root search on g(x), quadratures of the force and
// of the Dugdale zone's gap.
#include "profiles/profile.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstddef>
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

DugdaleGap Profile::dugdale_gap(double contact_radius, double cohesive_radius, double angle) const {
  return dugdale_gap_quadrature(*this, contact_radius, cohesive_radius, angle);
}

namespace {

/// J's integrand and dJ/dt's over one panel: by Kronrod's rule, by Gauss' embedded in it, and
/// the Kronrod sum of J's magnitudes.
struct GapPanel {
  double gap = 0.0, gap_gauss = 0.0, gap_mass = 0.0;
  double slope = 0.0;

  bool converged(double tolerance) const {
    return std::abs(gap - gap_gauss) <= tolerance * gap_mass;
  }
};

/// The integrands in psi, x = c cos(psi): J's by parts, c g'(x) psi sin(psi), or as defined,
/// g(x) - g(a); dJ/dt's (without its factor tan t), x g'(x).
struct GapIntegrand {
  const Profile& profile;
  double cohesive_radius;  ///< c [m]
  bool by_parts;
  double image_at_contact;  ///< g(a) [m], for J as defined
};

/// Gauss-Kronrod 10/21 on [lo, hi].
GapPanel gap_panel(const GapIntegrand& f, double lo, double hi) {
  using Kronrod = boost::math::quadrature::gauss_kronrod<double, 21>;
  using Gauss = boost::math::quadrature::gauss<double, 10>;
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  GapPanel p;
  const auto add = [&](double psi, double kronrod_weight, double gauss_weight) {
    const double x = f.cohesive_radius * std::cos(psi);
    const double slope = f.profile.mdr_image_slope(x);
    const double gap = f.by_parts ? f.cohesive_radius * slope * psi * std::sin(psi)
                                  : f.profile.mdr_image(x) - f.image_at_contact;
    p.gap += kronrod_weight * gap;
    p.gap_gauss += gauss_weight * gap;
    p.gap_mass += kronrod_weight * std::abs(gap);
    p.slope += kronrod_weight * x * slope;
  };
  // Ten Gauss points: Kronrod's odd abscissae (0 is Kronrod's alone).
  const auto& nodes = Kronrod::abscissa();
  const auto& weights = Kronrod::weights();
  add(mid, weights[0], 0.0);
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    const double gauss_weight = i % 2 == 1 ? Gauss::weights()[i / 2] : 0.0;
    add(mid + half * nodes[i], weights[i], gauss_weight);
    add(mid - half * nodes[i], weights[i], gauss_weight);
  }
  for (double* sum : {&p.gap, &p.gap_gauss, &p.gap_mass, &p.slope}) *sum *= half;
  return p;
}

/// Sums the panels of [lo, hi], halving a panel until J's Gauss and Kronrod sums agree to
/// `tolerance` of its mass or `depth` halvings are spent.
void add_gap_panels(const GapIntegrand& f, double lo, double hi, int depth, double tolerance,
                    GapPanel& total) {
  const GapPanel p = gap_panel(f, lo, hi);
  // A panel that is not finite (a sphere's image diverges at its radius) stays so when halved:
  // it ends the sum at once, and the zone's solve reads the excess as lying past the root.
  if (depth == 0 || p.converged(tolerance) || !std::isfinite(p.gap) || !std::isfinite(p.slope)) {
    total.gap += p.gap;
    total.slope += p.slope;
    return;
  }
  const double mid = 0.5 * (lo + hi);
  add_gap_panels(f, lo, mid, depth - 1, tolerance, total);
  add_gap_panels(f, mid, hi, depth - 1, tolerance, total);
}

}  // namespace

DugdaleGap dugdale_gap_quadrature(const Profile& profile, double contact_radius,
                                  double cohesive_radius, double angle) {
  // J = int_a^c (g(x) - g(a)) / sqrt(c^2 - x^2) dx by parts with d arccos(x/c): the boundary
  // terms vanish (g(x) - g(a) at a, arccos at c), leaving int_a^c g'(x) arccos(x/c) dx; in
  // x = c cos(psi) that is int_0^t c g'(x) psi sin(psi) dpsi, which nothing cancels. As defined,
  // int_0^t (g(x) - g(a)) dpsi cancels to eps g(a) out of about g'(a) a t^2/3: some ten ulps
  // from t = 0.3 on, where it takes over as the smoother of the two (a table's Hermite image
  // has a kink in g' at every grid node, which by parts costs thousands of panels across a
  // wide zone). dJ/dt at fixed a, with dc/dt = c tan(t) and the integrand g(x) - g(a) zero at
  // psi = t: tan(t) int_0^t x g'(x) dpsi, on J's panels (it steers the zone's Newton steps).
  const bool by_parts = angle < 0.3;
  const GapIntegrand f{.profile = profile,
                       .cohesive_radius = cohesive_radius,
                       .by_parts = by_parts,
                       .image_at_contact = by_parts ? 0.0 : profile.mdr_image(contact_radius)};
  GapPanel total;
  // 1e-12 of the mass on the Gauss half: on analytic integrands the Kronrod sum is then good to
  // a few ulps; on a table's image, whose kinks hold both rules to their estimate's order, to
  // about 1e-13 (measured: 1.5e-13 at the worst of 60 zones, against the rule at 1e-15).
  add_gap_panels(f, 0.0, angle, 12, 1e-12, total);
  return {.integral = total.gap, .angle_slope = std::tan(angle) * total.slope};
}

double contact_radius_at_force(const Profile& profile, double force, double effective_modulus) {
  if (const auto fixed = profile.fixed_contact_radius()) return *fixed;
  return invert_increasing([&](double a) { return profile.nonadhesive_force_per_modulus(a); },
                           force / effective_modulus, profile.outer_radius(), "the preload force");
}

}  // namespace mdrsim
