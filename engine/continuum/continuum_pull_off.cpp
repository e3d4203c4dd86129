// The walk down the branch: stable while the control falls as a falls, a jump at each fold.
#include "engine/continuum/continuum_pull_off.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "engine/base/bracketed_minimum.hpp"
#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

constexpr int kDecades = 14;
/// Bits of Brent's minimization: half a double's, the most a minimum's place can have; the
/// value there is then exact to rounding (the error is quadratic in the place's).
constexpr int kMinimumBits = std::numeric_limits<double>::digits / 2;
/// The control slope is a difference quotient (about 1e-13 relative): its root is
/// searched to that, not to the last bit.
constexpr int kSlopeDigits = std::numeric_limits<double>::digits - 8;

struct Walk {
  ContinuumBranch& branch;
  std::vector<BranchState> samples;
  ContinuumPullOff out;

  /// The fold among three radii lower < mid <= upper where the sampled control turned (the
  /// control at `lower` is not below the one at `mid`; its slope at `upper` is > 0).
  BranchState fold_between(double lower, double mid, double upper, double& error) {
    const double slope_mid = branch.control_slope(mid);
    double lo = lower, hi = mid, slope_lo = 0.0, slope_hi = slope_mid;
    if (slope_mid > 0.0) {
      slope_lo = branch.control_slope(lower);
    } else {
      lo = mid;
      slope_lo = slope_mid;
      hi = upper;
      slope_hi = branch.control_slope(upper);
    }
    const auto slope = [&](double a) { return branch.control_slope(a); };
    double a = upper;
    if (slope_hi > 0.0 && slope_lo < 0.0) {
      const RootBracket r = bracket_root(slope, lo, hi, kSlopeDigits);
      branch.iterations() += r.iterations;
      a = 0.5 * (r.lo + r.hi);
      if (holds_force(branch.normal())) {
        // The fold of the force itself: F is off by F'' delta^2 / 2 only. Its place is off by
        // the bracket and the quotient's error (about 1e-12 of a); F there bounds it.
        const double place = (r.hi - r.lo) + 1e-12 * a;
        const BranchState s = branch.at(a);
        error = std::abs(branch.at(a + place).normal_force - s.normal_force);
        return s;
      }
      // The quotient's error moves the root by up to ~1e-12 of a, its rounding included, which
      // no estimate from the quotient itself sees (a let-go tabulated to 1e-15 makes it ten
      // times that). The precise slope there, whose root is the fold to a few ulps, measures
      // how far: c'(a) = c'' (a - a_fold), with c'' from quotients a small step apart, give or
      // take the precise slope's own error, taken twice (on 10200 random scenes that bounds the
      // error the fold's place makes in F, within 0.98 of it at worst; once, 1.15x short).
      double precise_error = 0.0;
      const double precise = branch.precise_control_slope(a, &precise_error);
      double step = 1e-3 * (a - branch.shear_off_radius());
      const double room = branch.profile().outer_radius() - a;
      if (room > 0.0) step = std::min(step, 0.1 * room);
      const double curvature =
          std::abs(branch.control_slope(a + step) - branch.control_slope(a - step)) / (2.0 * step);
      const double place_error =
          (std::abs(precise) + 2.0 * precise_error) / std::max(curvature, 1e-300);
      error = std::abs(branch.force_slope(a)) * place_error;
    } else {
      // No clean sign change (a turn the difference quotient cannot see): the minimum of the
      // control value itself, whose place is then known to half the digits.
      a = bracketed_minimum([&](double x) { return branch.at(x).control; }, lower, upper,
                            kMinimumBits)
              .at;
      const double step = std::ldexp(a, -kMinimumBits);
      error = std::abs(branch.at(a + step).normal_force - branch.at(a).normal_force);
    }
    return branch.at(a);
  }

  /// The radius below `fold` where the control comes back down to `level`, searched
  /// from sample `from` on; nothing if it never does.
  std::optional<std::pair<double, std::size_t>> landing(const BranchState& fold, std::size_t from) {
    const double level = fold.control;
    std::size_t m = from;
    while (m < samples.size() && !(samples[m].control < level)) ++m;
    if (m == samples.size()) return std::nullopt;
    const auto excess = [&](double a) { return branch.at(a).control - level; };
    double upper = m > from ? samples[m - 1].contact_radius : fold.contact_radius;
    double upper_excess = m > from ? samples[m - 1].control - level : 0.0;
    for (int k = 1; k <= 60 && !(upper_excess > 0.0); ++k) {
      upper = fold.contact_radius -
              (fold.contact_radius - samples[m].contact_radius) * std::ldexp(1.0, -k);
      upper_excess = excess(upper);
    }
    if (!(upper_excess > 0.0)) return std::pair{samples[m].contact_radius, m};
    const RootBracket r = bracket_root(excess, samples[m].contact_radius, upper);
    branch.iterations() += r.iterations;
    return std::pair{r.lo, m};
  }

  /// The most tensile state of the stable stretch from `top` down to `bottom` (both
  /// equilibria of it), among the samples strictly between them.
  void visit_segment(const BranchState& top, const BranchState& bottom) {
    out.segments.emplace_back(top.contact_radius, bottom.contact_radius);
    if (holds_force(branch.normal())) {
      // The control is the force, and it falls along a stable stretch: its end is the minimum.
      if (!out.peak || bottom.normal_force < out.peak->normal_force) {
        out.peak = bottom;
        out.peak_error = 0.0;
      }
      return;
    }
    std::vector<const BranchState*> points{&top};
    for (const BranchState& s : samples) {
      if (s.contact_radius < top.contact_radius && s.contact_radius > bottom.contact_radius) {
        points.push_back(&s);
      }
    }
    points.push_back(&bottom);
    std::size_t k = 0;
    for (std::size_t j = 1; j < points.size(); ++j) {
      if (points[j]->normal_force < points[k]->normal_force) k = j;
    }
    BranchState best = *points[k];
    double error = 0.0;
    // The bracket of the minimum: around an inner sample, or next to an end where F still
    // falls into the stretch (a minimum between the end and its neighbouring sample).
    const std::size_t last = points.size() - 1;
    std::optional<std::pair<double, double>> bracket;
    if (k > 0 && k < last) {
      bracket.emplace(points[k + 1]->contact_radius, points[k - 1]->contact_radius);
    } else if (k == 0 && last > 0 && branch.force_slope(top.contact_radius) > 0.0) {
      bracket.emplace(points[1]->contact_radius, top.contact_radius);
    } else if (k == last && last > 0 && branch.force_slope(bottom.contact_radius) < 0.0) {
      bracket.emplace(bottom.contact_radius, points[last - 1]->contact_radius);
    }
    if (bracket) {
      const auto [lo, hi] = *bracket;
      const auto slope = [&](double a) { return branch.precise_force_slope(a); };
      const double slope_lo = slope(lo), slope_hi = slope(hi);
      if (slope_lo < 0.0 && slope_hi > 0.0) {
        // The minimum as the root of dF/da, as a fold is the root of its condition: to a few
        // ulps of a, where a search on F's values stops at sqrt(eps) (F is flat there).
        const RootBracket r = bracket_root(slope, lo, hi);
        branch.iterations() += r.iterations;
        const double a = 0.5 * (r.lo + r.hi);
        const BranchState s = branch.at(a);
        if (s.normal_force < best.normal_force) best = s;
        // F is off by F'' delta^2 / 2 for a place off by delta: the bracket and the slope's
        // error over F'' (the bracket's secant: a factor of its ends' curvature).
        double slope_error = 0.0;
        branch.precise_force_slope(a, &slope_error);
        const double curvature = (slope_hi - slope_lo) / (hi - lo);
        const double place = (r.hi - r.lo) + slope_error / curvature;
        error = 0.5 * curvature * place * place;
      } else {
        // No sign change of the slope at the bracket's ends (a minimum the samples straddle
        // twice): Brent's search on F itself.
        const auto force = [&](double a) { return branch.at(a).normal_force; };
        const Minimum m = bracketed_minimum(force, lo, hi, kMinimumBits);
        if (m.value < best.normal_force) best = branch.at(m.at);
        // The minimum's value is off by F'' delta^2 / 2 for a place off by delta.
        const double step = std::ldexp(best.contact_radius, -kMinimumBits);
        error = std::abs(force(best.contact_radius + step) - best.normal_force);
      }
    }
    if (!out.peak || best.normal_force < out.peak->normal_force) {
      out.peak = best;
      out.peak_error = error;
    }
  }
};

ContinuumPullOff walk_down(ContinuumBranch& branch, double glued_radius, int per_decade) {
  Walk w{branch, {}, {}};
  ContinuumPullOff& out = w.out;
  const double ag = glued_radius;
  if (!branch.locate_shear_off(ag)) {
    out.end = ContinuumPullOff::End::shear_off_at_application;
    out.tangential_strength =
        2.0 * branch.material().effective_shear_modulus * ag * branch.zero_stretch_limit(ag);
    return out;
  }
  if (branch.profile().fixed_contact_radius()) {
    // A flat punch: every glued spring sits at the same gap, so the boundary's let-go at a_g
    // takes every spring inside with it (their thresholds are lower): the jump starts there.
    out.end = ContinuumPullOff::End::first_detachment;
    out.critical = branch.at(ag);
    out.peak = out.critical;
    out.segments.emplace_back(ag, ag);
    return out;
  }
  const double as = branch.shear_off_radius();
  const int count = kDecades * std::max(per_decade, 2);
  const double ratio = std::pow(10.0, -1.0 / std::max(per_decade, 2));
  w.samples.reserve(static_cast<std::size_t>(count) + 1);
  double t = ag - as;
  for (int j = 0; j <= count; ++j, t *= ratio) {
    const double a = j == 0 ? ag : as + t;
    if (!(a > as)) break;
    w.samples.push_back(branch.at(a));
  }

  BranchState top = w.samples.front();
  std::size_t next = 1;  // the first sample below `top`
  bool first = true;
  while (true) {
    // The fold of this stable stretch: the first turn of the control among the samples.
    std::optional<BranchState> fold;
    double fold_error = 0.0;
    if (branch.control_slope(top.contact_radius) <= 0.0) {
      fold = top;
    } else {
      const BranchState* above = &top;
      const BranchState* above2 = &top;
      for (std::size_t j = next; j < w.samples.size(); ++j) {
        const BranchState& s = w.samples[j];
        // A control that stops falling by no more than the rounding of its own value has not
        // turned (flat to the bit where g(a) sinks below the rounding of e, d = g - e at
        // a ~ 1e-12 m): the peel goes on to a -> 0. Any real rise is a turn, however small the
        // force it carries (a power law's fold at 1e-13 of its preload is its closed-form F0).
        const double flat = 4.0 * std::numeric_limits<double>::epsilon() *
                            std::max(std::abs(s.control), std::abs(above->control));
        if (!(s.control <= above->control + flat)) {
          fold = w.fold_between(s.contact_radius, above->contact_radius, above2->contact_radius,
                                fold_error);
          next = j;
          break;
        }
        // Compared with the lowest sample since, so that a rise is seen once it adds up.
        if (!(s.control < above->control)) continue;
        above2 = above;
        above = &s;
      }
    }
    if (!fold) {
      if (as > 0.0) {
        out.end = ContinuumPullOff::End::shear_off;
        out.critical = branch.state(as, 0.0);
        // F = E* nf(a_s), nf' = 2 a g': off by that times the place's bracket.
        out.critical_error = 2.0 * branch.material().effective_modulus * as *
                             branch.profile().mdr_image_slope(as) * branch.shear_off_bracket();
      } else {
        out.end = ContinuumPullOff::End::smooth_peel;
        out.critical = w.samples.back();
      }
      w.visit_segment(top, out.critical);
      if (out.end == ContinuumPullOff::End::smooth_peel && out.peak &&
          out.peak->contact_radius == out.critical.contact_radius) {
        out.peak.reset();  // F -> 0 at a -> 0: the last sample's tension is no peak
      }
      return out;
    }
    w.visit_segment(top, *fold);
    while (next < w.samples.size() && w.samples[next].contact_radius >= fold->contact_radius) {
      ++next;
    }
    const auto land = w.landing(*fold, next);
    if (!land) {
      out.end = first && fold->contact_radius == ag ? ContinuumPullOff::End::first_detachment
                                                    : ContinuumPullOff::End::fold;
      out.critical = *fold;
      out.critical_error = fold_error;
      return out;
    }
    const BranchState landed = branch.at(land->first);
    out.partial_jumps.push_back({*fold, landed});
    top = landed;
    next = land->second;
    first = false;
  }
}

}  // namespace

ContinuumPullOff continuum_pull_off(ContinuumBranch& branch, double glued_radius, int per_decade) {
  ContinuumPullOff out = walk_down(branch, glued_radius, per_decade);
  // The let-go's own error moves F = E* (nf - 2 a e) by 2 E* a de wherever e is the let-go's.
  // de is its residual in the criterion's margin, taken twice: the margin itself rounds about
  // as much where the let-go is tabulated. On the 2027 mode-dependent scenes of five random
  // sets that bounds F's error but for one fixed-load fold (1.06x short, 1.4e-13 of F; 1.84x
  // with the residual once) and one peak (1.02x, 4e-14 of F), against a reference of its own.
  const auto let_go_error = [&](const BranchState& s) {
    return 2.0 * (2.0 * branch.material().effective_modulus * s.contact_radius *
                  branch.stretch_error(s.contact_radius));
  };
  if (out.end == ContinuumPullOff::End::fold ||
      out.end == ContinuumPullOff::End::first_detachment) {
    out.critical_error += let_go_error(out.critical);
  }
  if (out.peak) out.peak_error += let_go_error(*out.peak);
  return out;
}

}  // namespace mdrsim
