// Derivations of the loading-program references; units and relations in the header.
#include "engine/reference/program_reference.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "engine/reference/parabolic_reference.hpp"

namespace mdrsim::program_reference {
namespace {

namespace paper = mdrsim::parabolic_reference;

/// The root of fn on [lo, hi] (signs differ at the ends) to full double precision, TOMS 748.
template <class Fn>
double root(Fn fn, double lo, double hi) {
  std::uintmax_t iterations = 300;
  const auto r = boost::math::tools::toms748_solve(
      fn, lo, hi,
      boost::math::tools::eps_tolerance<double>(std::numeric_limits<double>::digits - 1),
      iterations);
  return 0.5 * (r.first + r.second);
}

/// The first of start, 2 start, 4 start, ... at which the increasing fn is positive.
template <class Fn>
double upper_bracket(Fn fn, double start) {
  double hi = start;
  while (fn(hi) <= 0.0) hi *= 2.0;
  return hi;
}

/// int_lo^hi f dd by adaptive 61-point Gauss-Kronrod (f smooth on [lo, hi]).
template <class Fn>
double integrate(Fn f, double lo, double hi) {
  if (lo == hi) return 0.0;
  const double sign = lo < hi ? 1.0 : -1.0;
  return sign * boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
                    f, std::min(lo, hi), std::max(lo, hi), 15, 1e-13);
}

/// int f over [from, to] split at the kinks that lie inside.
template <class Fn>
double integrate_piecewise(Fn f, double from, double to, std::vector<double> kinks) {
  const double lo = std::min(from, to);
  const double hi = std::max(from, to);
  std::vector<double> cuts{lo};
  std::sort(kinks.begin(), kinks.end());
  for (const double k : kinks) {
    if (k > lo && k < hi) cuts.push_back(k);
  }
  cuts.push_back(hi);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) sum += integrate(f, cuts[i], cuts[i + 1]);
  return from <= to ? sum : -sum;
}

State from_paper(const paper::CriticalPoint& c) {
  return {c.contact_radius, c.indentation, c.normal_force, c.tangential_displacement,
          c.tangential_force};
}

double fold_radius() { return std::cbrt(1.0 / 9.0); }

/// Hess limit in d0 units (eq. 12 over d0): dl(a) = 4 sqrt(a).
double hess_limit(double a) { return 4.0 * std::sqrt(a); }

/// The JKR depth of eq. 18, where a boundary glued at a reaches the Hess limit.
double jkr_indentation(double a) { return 3.0 * a * a - hess_limit(a); }

/// Springs glued over [0, a] at depth d: F = (a/2)(d - a^2) (eq. 26).
double glued_force(double a, double d) { return 0.5 * a * (d - a * a); }

/// A normal contact under fixed grips that glues on touch (dgamma_a = 0): springs over [0, A]
/// are glued; with rebinding = false those over (A, L] have let go and push only where
/// g(x) = 3 x^2 <= d, with F = (1/2) int_A^b (d - 3 x^2) dx = (1/2)(d (b - A) - (b^3 - A^3)),
/// b = min(L, sqrt(d/3)). With rebinding = true a let-go spring is a fresh one, L = A.
///
/// press (d rises): the front at A glues each spring as it is touched (gap 0 = the advancing
/// limit at dgamma_a = 0), so A = max(A, sqrt(d/3)) and F is Hertz above 3 A^2, F = b^3.
/// Without rebinding a let-go band blocks the front: A stays, the band pushes.
/// pull (d falls): the boundary at A holds while its elongation 3 A^2 - d < dl(A), i.e.
/// d > d_JKR(A); below, A follows eq. 18 down to the fold a_c (under fixed grips the branch is
/// stable where dd/da > 0, a > a_c), where the contact jumps off; if A <= a_c the first
/// let-go already empties it. On eq. 18 the boundary is stretched (3 A^2 - d = dl > 0), so
/// g > d outside A: no let-go spring pushes while the contact peels.
class GluedOnTouchRow {
 public:
  explicit GluedOnTouchRow(bool rebinding) : rebinding_(rebinding) {}

  double force(double d) const {
    if (lost_) return 0.0;
    double f = glued_force(glued_, d);
    if (!rebinding_ && band_ > glued_ && d > 3.0 * glued_ * glued_) {
      const double b = std::min(band_, std::sqrt(d / 3.0));
      f += 0.5 * (d * (b - glued_) - (b * b * b - glued_ * glued_ * glued_));
    }
    return f;
  }

  double indentation() const { return depth_; }
  bool lost() const { return lost_; }
  const State& critical() const { return critical_; }

  /// Raises d to `to`; returns the machine's work.
  double press(double to) {
    if (to < depth_) throw std::invalid_argument("press: the depth must rise");
    double work = 0.0;
    if (!rebinding_ && band_ > glued_) {
      if (to > 3.0 * band_ * band_) {
        throw std::domain_error(
            "press: springs beyond the let-go band would be pressed against "
            "a blocked front; not derived here");
      }
      work = integrate_piecewise([&](double d) { return force(d); }, depth_, to,
                                 {3.0 * glued_ * glued_, 3.0 * band_ * band_});
    } else {
      const double a = glued_;
      work = integrate_piecewise(
          [a](double d) { return glued_force(std::max(a, std::sqrt(d / 3.0)), d); }, depth_, to,
          {3.0 * a * a});
      glued_ = std::max(glued_, std::sqrt(to / 3.0));
      band_ = glued_;
    }
    lost_ = false;
    depth_ = to;
    return work;
  }

  /// Lowers d to `to`, or to the jump out if that comes first; returns the machine's work.
  double pull(double to) {
    if (to > depth_) throw std::invalid_argument("pull: the depth must fall");
    const double let_go = jkr_indentation(glued_);
    const double fixed_end = std::max(to, let_go);
    double work = 0.0;
    if (fixed_end < depth_) {
      work += integrate_piecewise([&](double d) { return force(d); }, depth_, fixed_end,
                                  {3.0 * glued_ * glued_, 3.0 * band_ * band_});
    }
    depth_ = fixed_end;
    if (to >= let_go) return work;
    const double ac = fold_radius();
    if (glued_ <= ac) {  // the first let-go empties the contact (dd/da < 0 below a_c)
      critical_ = {glued_, let_go, force(let_go), 0.0, 0.0};
      lose();
      return work;
    }
    const State fold = jkr_fold();
    const double end = to >= fold.indentation ? jkr_radius_at_indentation(to) : ac;
    work += jkr_branch_work(glued_, end);
    band_ = rebinding_ ? end : std::max(band_, glued_);
    glued_ = end;
    depth_ = std::max(to, fold.indentation);
    if (to < fold.indentation) {
      critical_ = fold;
      lose();
    }
    return work;
  }

 private:
  void lose() {
    lost_ = true;
    glued_ = 0.0;
    if (rebinding_) band_ = 0.0;
  }

  bool rebinding_;
  double glued_ = 0.0;  ///< A
  double band_ = 0.0;   ///< L >= A
  double depth_ = 0.0;  ///< d
  bool lost_ = false;
  State critical_;
};

}  // namespace

// ---- The JKR branch ----

State jkr_fold() { return jkr_state(fold_radius()); }

double jkr_radius_at_indentation(double d) {
  const double ac = fold_radius();
  const double dc = jkr_indentation(ac);
  if (!(d >= dc)) throw std::domain_error("jkr_radius_at_indentation: d is below the fold d_c");
  if (d == dc) return ac;
  const auto fn = [d](double a) { return jkr_indentation(a) - d; };
  return root(fn, ac, upper_bracket(fn, 1.0));
}

// F = a^3 - 2 a^(3/2) = (a^(3/2) - 1)^2 - 1: the root with a^(3/2) >= 1 is 1 + sqrt(1 + F).
double jkr_radius_at_force(double f) {
  if (!(f >= -1.0)) throw std::domain_error("jkr_radius_at_force: F is below -1");
  return std::pow(1.0 + std::sqrt(1.0 + f), 2.0 / 3.0);
}

State jkr_state(double a) { return {a, jkr_indentation(a), paper::normal_force(a), 0.0, 0.0}; }

// On eqs. 18-19, F = a^3 - 2 a^(3/2) and dd/da = 6 a - 2 a^(-1/2), so
//   F dd/da = 6 a^4 - 14 a^(5/2) + 4 a,   P(a) = int = (6/5) a^5 - 4 a^(7/2) + 2 a^2,
// and int F dd from a_from to a_to is P(a_to) - P(a_from).
double jkr_branch_work(double from, double to) {
  const auto p = [](double a) {
    return 1.2 * std::pow(a, 5) - 4.0 * std::pow(a, 3.5) + 2.0 * a * a;
  };
  return p(to) - p(from);
}

// ---- (a) ----
//
// Out of contact nothing pushes (F = 0, no work). At d = 0 the first spring touches; with
// dgamma_a = dgamma the advancing limit is the Hess limit, so the front glues every spring
// with 3 x^2 - 0 <= 4 sqrt(x), x^(3/2) <= 4/3, in one cascade: the jump-in lands on eq. 18
// at d = 0, a*^(3/2) = 4/3, a*^3 = 16/9, F = (a*/2)(0 - a*^2) = -8/9. Pressing on and
// retracting, the advancing and receding limits coincide, so the contact follows eqs. 18-19
// both ways (stable under fixed grips for a > a_c) down to the fold: a_c^3 = 1/9,
// d_c = 3 a_c^2 - 4 a_c^(1/2) = 3^(-1/3) - 4 3^(-1/3) = -3^(2/3), F_c = 1/9 - 2/3 = -5/9;
// then it jumps off at fixed d (no work). The machine's work over the cycle is
//   [P(a_m) - P(a*)] + [P(a_c) - P(a_m)] = P(a_c) - P(a*),
// d_max drops out. With a*^(3/2) = 4/3: P(a*) = a*^2 (6/5 16/9 - 16/3 + 2) = -(6/5) a*^2;
// with a_c^(3/2) = 1/3: P(a_c) = a_c^2 (6/45 - 4/3 + 2) = (4/5) a_c^2. So
//   W = (6/5) (16/9)^(2/3) + (4/5) 9^(-2/3) = 1.945924... F0 d0,
// and W/|d_c| = [(6/5) 16^(2/3)/9 + 4/45] = 4 (6 2^(2/3) + 1)/45 = 0.935503.
ReversibleCycle reversible_jkr_cycle(double max_indentation) {
  if (!(max_indentation > 0.0)) {
    throw std::domain_error("reversible_jkr_cycle: the approach must press past d = 0");
  }
  const double jump_in_radius = std::cbrt(16.0 / 9.0);
  ReversibleCycle c;
  c.jump_in_after = {jump_in_radius, 0.0, glued_force(jump_in_radius, 0.0), 0.0, 0.0};
  c.approach_end = jkr_state(jkr_radius_at_indentation(max_indentation));
  c.retract_critical = jkr_fold();
  c.dissipated_work = jkr_branch_work(jump_in_radius, c.approach_end.contact_radius) +
                      jkr_branch_work(c.approach_end.contact_radius, fold_radius());
  return c;
}

double reversible_cycle_work_per_fold_depth() { return 4.0 * (6.0 * std::cbrt(4.0) + 1.0) / 45.0; }

// ---- (b) ----
//
// Approach: the front glues on touch, a = sqrt(d/3) (Hertz: d = a^2/R), F = a^3, so the
// loading work is int_0^{d_max} (d/3)^(3/2) dd = (6/5) a_m^5. Retract at the fixed glued
// radius a_m: F = (a_m/2)(d - a_m^2), linear in d, until the boundary elongation
// 3 a_m^2 - d reaches dl(a_m) = 4 sqrt(a_m), at d_1 = d_JKR(a_m):
//   int_{d_max}^{d_1} F dd = (a_m/4)[(d_1 - a_m^2)^2 - (d_max - a_m^2)^2]
//                          = (a_m/4)[(2 a_m^2 - 4 a_m^(1/2))^2 - 4 a_m^4] = 4 a_m^2 - 4 a_m^(7/2).
// If a_m > a_c the contact then peels along eqs. 18-19 to the fold (work P(a_c) - P(a_m)) and
// jumps off there; the sum telescopes to
//   W = (6/5) a_m^5 + 4 a_m^2 - 4 a_m^(7/2) + (4/5) a_c^2 - (6/5) a_m^5 + 4 a_m^(7/2) - 2 a_m^2
//     = 2 a_m^2 + (4/5) a_c^2 = (2/3) d_max + (4/45) |d_c|     (a_c^2 = |d_c|/9).
// If a_m <= a_c the first let-go at d_1 empties the contact (eq. 18 falls with a there):
//   W = (6/5) a_m^5 - 4 a_m^(7/2) + 4 a_m^2, less than the formula by P(a_c) - P(a_m) > 0.
GlueOnTouchCycle glue_on_touch_cycle(double max_indentation) {
  if (!(max_indentation > 0.0)) throw std::domain_error("glue_on_touch_cycle: d_max must be > 0");
  GlueOnTouchCycle c;
  const double am = std::sqrt(max_indentation / 3.0);
  c.max_radius = am;
  c.load_end = {am, max_indentation, am * am * am, 0.0, 0.0};
  c.let_go_onset = {am, jkr_indentation(am), glued_force(am, jkr_indentation(am)), 0.0, 0.0};
  c.jumps_at_first_let_go = am <= fold_radius();
  c.retract_critical = c.jumps_at_first_let_go ? c.let_go_onset : jkr_fold();
  c.loading_work = 1.2 * std::pow(am, 5);
  const double d1 = c.let_go_onset.indentation;
  const double fixed_radius_work =
      0.25 * am * (std::pow(d1 - am * am, 2) - std::pow(max_indentation - am * am, 2));
  const double peel_work = c.jumps_at_first_let_go ? 0.0 : jkr_branch_work(am, fold_radius());
  c.dissipated_work = c.loading_work + fixed_radius_work + peel_work;
  return c;
}

double glue_on_touch_retract_force(double max_indentation, double d) {
  GluedOnTouchRow row(false);
  row.press(max_indentation);
  row.pull(std::min(d, max_indentation));
  return row.force(d);
}

double claimed_glue_on_touch_dissipation(double max_indentation) {
  return 2.0 / 3.0 * max_indentation + 4.0 / 45.0 * std::cbrt(9.0);
}

// ---- (c) ----
//
// Glued at u = 0, every spring carries u - 0 = u: the paper's uniform u (eqs. 22-27). At a
// held F the equilibria are F(a, u) = F (eq. 26 with eq. 25), at a held d they are d(a, u) = d.
// Along such a curve dF = F_a da + F_u du = 0, so du/da = -F_a/F_u; F_u = gamma a u/(2 S) is
// nonzero for u > 0, so u(a) is stationary exactly where F_a = 0 at fixed u: the fold of the
// held-F ramp is eq. 29's fixed-load critical point at that F. Likewise du/da = -d_a/d_u with
// d_u = gamma u/S: the held-d ramp ends on eq. 31's fixed-grips critical point at that d. The
// envelope is path independent; it is reached if the ramp starts (u = 0 or at the first
// let-go) at a radius above the fold's, since u grows as a falls on the stable side.

State fixed_load_critical_at_force(double f, double gamma) {
  if (!(f >= -1.0)) throw std::domain_error("fixed_load_critical_at_force: F is below -1");
  const auto fn = [&](double u) { return paper::fixed_load_critical(u, gamma).normal_force - f; };
  if (fn(0.0) >= 0.0) return from_paper(paper::fixed_load_critical(0.0, gamma));
  return from_paper(paper::fixed_load_critical(root(fn, 0.0, upper_bracket(fn, 1.0)), gamma));
}

State fixed_grips_critical_at_indentation(double d, double gamma) {
  const auto fn = [&](double u) { return paper::fixed_grips_critical(u, gamma).indentation - d; };
  if (fn(0.0) > 0.0) {
    throw std::domain_error("fixed_grips_critical_at_indentation: d is below the fold d_c");
  }
  if (fn(0.0) == 0.0) return from_paper(paper::fixed_grips_critical(0.0, gamma));
  return from_paper(paper::fixed_grips_critical(root(fn, 0.0, upper_bracket(fn, 1.0)), gamma));
}

namespace {

/// The ramp from a start state at rest (u = 0): the boundary holds until e^2 + gamma u^2 =
/// 16 a (eq. 20) with e = 3 a^2 - d fixed (F or d held, a fixed, so both stay); then it peels
/// along the held curve to the fold, or jumps at once if the fold lies above a.
ShearRamp ramp_from(const State& start, const State& fold, double gamma) {
  const double a = start.contact_radius;
  const double e = 3.0 * a * a - start.indentation;
  if (e < 0.0) throw std::domain_error("shear ramp: the boundary is compressed; not derived here");
  ShearRamp r;
  r.start = start;
  r.first_let_go = start;
  r.first_let_go.tangential_displacement = std::sqrt(std::max(0.0, 16.0 * a - e * e) / gamma);
  r.first_let_go.tangential_force = 0.5 * gamma * a * r.first_let_go.tangential_displacement;
  r.jumps_at_first_let_go = fold.contact_radius >= a;
  r.critical = r.jumps_at_first_let_go ? r.first_let_go : fold;
  return r;
}

}  // namespace

// The unload from the preload (glued on touch at a_p, d_p = 3 a_p^2, F_p = a_p^3) at fixed
// load keeps a_p while F >= F_JKR(a_p) (the boundary below its limit), d = a_p^2 + 2 F/a_p;
// below it the contact peels along eq. 19, stable under fixed load for a >= 1.
ShearRamp shear_ramp_at_held_force(double ap, double f, double gamma) {
  if (f > ap * ap * ap) throw std::domain_error("shear_ramp_at_held_force: F above the preload's");
  State start;
  if (f >= paper::normal_force(ap)) {
    start = {ap, ap * ap + 2.0 * f / ap, f, 0.0, 0.0};
  } else {
    if (ap <= 1.0) throw std::domain_error("shear_ramp_at_held_force: the unload pulls it off");
    start = jkr_state(jkr_radius_at_force(f));
  }
  return ramp_from(start, fixed_load_critical_at_force(f, gamma), gamma);
}

// The same under fixed grips: a_p holds while d >= d_JKR(a_p); below it eq. 18, stable for a > a_c.
ShearRamp shear_ramp_at_held_indentation(double ap, double d, double gamma) {
  if (d > 3.0 * ap * ap) {
    throw std::domain_error("shear_ramp_at_held_indentation: d above the preload's");
  }
  State start;
  if (d >= jkr_indentation(ap)) {
    start = {ap, d, glued_force(ap, d), 0.0, 0.0};
  } else {
    if (ap <= fold_radius()) {
      throw std::domain_error("shear_ramp_at_held_indentation: the unload pulls it off");
    }
    start = jkr_state(jkr_radius_at_indentation(d));
  }
  return ramp_from(start, fixed_grips_critical_at_indentation(d, gamma), gamma);
}

// ---- (d) ----
//
// Preload glued on touch: a_p = sqrt(d_p/3), every spring glued at u = 0. Along the path
// d = d_p - s, u = k s a boundary at radius a has elongation e = 3 a^2 - d = h + s with
// h(a) = 3 a^2 - d_p <= 0, and eq. 20 (mode-mixed) reads (h + s)^2 + gamma k^2 s^2 = 16 a:
//   c s^2 + 2 h s + h^2 - 16 a = 0,  c = 1 + gamma k^2,
//   s(a) = (-h + sqrt(Q))/c,  Q = 16 a c - gamma k^2 h^2   (the root through s(a_p) > 0),
//   ds/da = (-6 a + (8 c - 6 gamma k^2 a h)/sqrt(Q))/c.
// The first let-go is at a_p (h = 0): s_1 = 4 sqrt(a_p/c). The contact peels while s(a)
// rises as a falls (ds/da < 0) and jumps at the first a below a_p where ds/da = 0 (the fold),
// unless e = h + s reaches 0 first: there gamma k^2 s^2 = 16 a, and every inner spring (e <= 0,
// 16 x < 16 a) fails on the shear term alone (the glue shears off). If ds/da >= 0 already at
// a_p the first let-go empties the contact. Forces: F_z = (a/2)(d - a^2), F_x = (gamma/2) a u.
InclinedPull inclined_pull(double dp, double k, double gamma) {
  if (!(dp > 0.0)) throw std::domain_error("inclined_pull: the preload depth must be > 0");
  const double ap = std::sqrt(dp / 3.0);
  const double c = 1.0 + gamma * k * k;
  const auto h = [&](double a) { return 3.0 * a * a - dp; };
  const auto q = [&](double a) { return 16.0 * a * c - gamma * k * k * h(a) * h(a); };
  const auto s = [&](double a) { return (-h(a) + std::sqrt(std::max(0.0, q(a)))) / c; };
  const auto slope = [&](double a) {
    return (-6.0 * a + (8.0 * c - 6.0 * gamma * k * k * a * h(a)) / std::sqrt(q(a))) / c;
  };
  const auto elongation = [&](double a) { return h(a) + s(a); };
  const auto state = [&](double a) {
    const double path = s(a);
    const double d = dp - path;
    return State{a, d, glued_force(a, d), k * path, 0.5 * gamma * a * k * path};
  };
  InclinedPull p;
  p.first_let_go = state(ap);
  double a_crit = ap;
  if (slope(ap) >= 0.0) {
    p.end = InclinedPull::End::first_let_go;
  } else {
    constexpr int kSamples = 100000;
    double prev = ap;
    for (int i = 1; i < kSamples; ++i) {
      const double a = ap * (1.0 - static_cast<double>(i) / kSamples);
      if (elongation(a) <= 0.0) {
        p.end = InclinedPull::End::shear_off;
        a_crit = root(elongation, a, prev);
        break;
      }
      if (slope(a) >= 0.0) {
        p.end = InclinedPull::End::fold;
        a_crit = root(slope, a, prev);
        break;
      }
      prev = a;
    }
  }
  p.critical = state(a_crit);
  p.path = s(a_crit);
  // After the jump a smaller glued contact [0, a] would hold at s_c if its largest holding
  // path reached s_c: s(a) while e >= 0, else the shear term alone, gamma k^2 s^2 = 16 a.
  double best = 0.0;
  for (int i = 1; i < 20000; ++i) {
    const double a = a_crit * (1.0 - static_cast<double>(i) / 20000.0);
    const double holds = elongation(a) >= 0.0 ? s(a) : 4.0 * std::sqrt(a / gamma) / k;
    best = std::max(best, holds);
  }
  p.contact_lost = p.critical.indentation < 0.0 && best < p.path;
  return p;
}

// ---- (e) ----
//
// Fixed grips, glue on touch; the stages run on GluedOnTouchRow (derivation there):
//  1. load 0 -> d1: Hertz, a1 = sqrt(d1/3), F = a1^3.
//  2. unload d1 -> d2 < d_JKR(a1): fixed radius a1, then eq. 18 down to a2, F = F_JKR(a2).
//  3. reload d2 -> d1. rebinding = true: a2 holds while d < 3 a2^2, then the front glues on
//     touch, F = (d/3)^(3/2) above. rebinding = false: springs over (a2, a1] have let go and
//     push where 3 x^2 <= d: F = (a2/2)(d - a2^2) + (1/2)(d (b - a2) - (b^3 - a2^3)),
//     b = sqrt(d/3), which is (1/2)(d b - b^3) = b^3 too: the reloads coincide, F(d1) = a1^3.
//  4. unload d1 -> d3. rebinding = true: the state is that of stage 1's end again, so the
//     force is stage 2's: (a1/2)(d3 - a1^2) if d3 >= d_JKR(a1), else F_JKR(a(d3)).
//     rebinding = false: only [0, a2] is glued, the band lifts: the force above with b capped
//     by the band, F(d3) = (a2/2)(d3 - a2^2) + band, which holds down to d_JKR(a2) = d2 < d3.
//     The band carries no tension, so for d3 < 3 a1^2 this force exceeds rebinding's.
//  5. pull-off until separation: both end at the fold of eq. 18 (a1, a2 > a_c: a2 is on the
//     stable branch because d2 >= d_c), F_c = -5/9 at d_c: the same critical force.
ReloadProgram reload_program(double d1, double d2, double d3, bool rebinding) {
  const double a1 = std::sqrt(d1 / 3.0);
  if (!(d1 > 0.0) || !(d2 < jkr_indentation(a1)) || !(d2 >= jkr_fold().indentation) ||
      !(d3 >= d2 && d3 <= d1)) {
    throw std::domain_error("reload_program: needs d1 > 0, d_c <= d2 < d_JKR(a1), d2 <= d3 <= d1");
  }
  GluedOnTouchRow row(rebinding);
  ReloadProgram p;
  p.glued_radius = a1;
  p.peeled_radius = jkr_radius_at_indentation(d2);
  p.stage_work[0] = row.press(d1);
  p.stage_end_force[0] = row.force(d1);
  p.stage_work[1] = row.pull(d2);
  p.stage_end_force[1] = row.force(d2);
  p.stage_work[2] = row.press(d1);
  p.stage_end_force[2] = row.force(d1);
  p.stage_work[3] = row.pull(d3);
  p.stage_end_force[3] = row.force(d3);
  p.stage_work[4] = row.pull(jkr_fold().indentation - 1.0);
  if (!row.lost()) throw std::logic_error("reload_program: the pull-off did not separate");
  p.pull_off_critical = row.critical();
  for (const double w : p.stage_work) p.work += w;
  return p;
}

double second_unload_force(double d1, double d2, double d, bool rebinding) {
  GluedOnTouchRow row(rebinding);
  row.press(d1);
  row.pull(d2);
  row.press(d1);
  row.pull(d);
  return row.force(d);
}

}  // namespace mdrsim::program_reference
