// Maugis' path recorded through a lever: the synthetic force curves of the Maugis fit's tests
// and bench.
#include "engine/reference/maugis_lever.hpp"

#include <boost/math/tools/toms748_solve.hpp>

#include <cstdint>
#include <numbers>

namespace mdrsim::maugis_reference {

LeverPath::LeverPath(double lambda_, double kappa_, double a_max_)
    : lambda(lambda_), kappa(kappa_), c0(closing_cohesive_radius(lambda_)), a_max(a_max_) {
  for (int j = 0; j <= 400; ++j) s.push_back(c0 * j / 400.0);
  for (int j = 1; j <= 3000; ++j) {
    const double u = 1e-4 + (1.0 - 1e-4) * j / 3000.0;
    s.push_back(c0 + a_max * u * u);
  }
  for (const double at : s) q.push_back(base(at));
}

MaugisState LeverPath::state(double at) const {
  return at <= c0 ? no_contact_branch(lambda, at) : contact_branch(lambda, at - c0);
}

double LeverPath::base(double at) const {
  const MaugisState st = state(at);
  return st.indentation + st.force / kappa;
}

MaugisState LeverPath::solve(double b, std::size_t j) const {
  double lo = s[j], hi = s[j + 1];
  const double low = base(lo) - b, high = base(hi) - b;
  if ((low < 0.0) != (high < 0.0)) {
    // The root to the last bits of s (each base() on the contact branch is a root itself, so
    // toms748's dozen of them, not 70 halvings).
    std::uintmax_t iterations = 200;
    const auto r = boost::math::tools::toms748_solve(
        [&](double x) { return base(x) - b; }, lo, hi, low, high,
        boost::math::tools::eps_tolerance<double>(52), iterations);
    return state(0.5 * (r.first + r.second));
  }
  // No change of sign (b at a node, or q not monotone there): halve towards the end nearer b.
  const bool rising = q[j + 1] > q[j];
  for (int k = 0; k < 70; ++k) {
    const double mid = 0.5 * (lo + hi);
    ((base(mid) < b) == rising ? lo : hi) = mid;
  }
  return state(0.5 * (lo + hi));
}

LeverCurve lever_curve(const MaugisScales& scales, double lambda, bool approach, double kappa,
                       double peak_pulls, double phase, double reach_lead) {
  const double pull_force = -fixed_load_pull_off(lambda).force;  // Maugis' units
  double lo = 0.0, hi = 2.0;
  while (contact_branch(lambda, hi).force < peak_pulls * pull_force) hi *= 1.5;
  for (int k = 0; k < 80; ++k) {
    const double mid = 0.5 * (lo + hi);
    (contact_branch(lambda, mid).force < peak_pulls * pull_force ? lo : hi) = mid;
  }
  const LeverPath path(lambda, kappa, 0.5 * (lo + hi));
  const double q_top = path.q.back();
  const double h0 = 2.0 / (std::numbers::pi * lambda);
  LeverCurve curve;
  curve.kappa_si = kappa * scales.force() / scales.depth();
  curve.depth = contact_branch(lambda, path.a_max).indentation * scales.depth();
  curve.peak = peak_pulls * pull_force * scales.force();
  const double offset = 0.1 * curve.peak, slope = 0.05 * curve.peak / curve.depth;
  const int n = 2000;
  // The base's far end, -far, and its travel.
  const double far = 0.5 * q_top + reach_lead * h0, span = q_top + far;
  std::size_t j = approach ? 0 : path.s.size() - 2;
  bool on = !approach;
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / (n - 1);
    const double shift = phase * span / (n - 1);
    const double b = q_top - span * (approach ? 1.0 - t : t) - shift;
    double d = b, force = 0.0;  // free: the tip where the base is
    if (approach && b >= -h0) {
      while (j + 1 < path.s.size() && !(path.q[j + 1] > path.q[j] && path.q[j + 1] >= b)) ++j;
      on = j + 1 < path.s.size();
    }
    while (!approach && on && path.q[j] > b) {
      // (Rounding leaves the contact branch's nodes next to A = 0 uneven by 1e-8 of the depth
      // unit.)
      if (j == 0 || !(path.q[j - 1] < path.q[j] + 1e-6)) {
        on = false;  // q turns going down: the jump off
      } else {
        --j;
      }
    }
    if (on && (!approach || b >= -h0)) {
      const MaugisState st = path.solve(b, j);
      d = st.indentation;
      force = st.force;
    }
    const double z = curve.contact_point - d * scales.depth();
    curve.z.push_back(z);
    curve.force.push_back(offset + slope * (z - curve.contact_point) + force * scales.force());
  }
  return curve;
}

}  // namespace mdrsim::maugis_reference
