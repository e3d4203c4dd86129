// The fixed-grips loop of a parabolic contact whose work of adhesion varies with radius, tracked
// front by front from the MDR equilibrium alone (no spring row, no program engine).
#include "engine/reference/radial_front_reference.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

namespace mdrsim::radial_front_reference {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// The walk over the grid of d'(a) gives up after this many samples.
constexpr std::int64_t kMaxSamples = 100'000'000;

/// The root of f in [lo, hi] (f(lo) and f(hi) of opposite signs or zero), to about 1e-15
/// relative (TOMS 748).
template <class F>
double bracketed_root(F f, double lo, double hi, double f_lo, double f_hi) {
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  std::uintmax_t iterations = 200;
  const auto close_enough = [](double x, double y) {
    return std::abs(x - y) <= 1e-15 * std::max(std::abs(x), std::abs(y));
  };
  const auto [left, right] =
      boost::math::tools::toms748_solve(f, lo, hi, f_lo, f_hi, close_enough, iterations);
  return 0.5 * (left + right);
}

/// int_lo^hi f by adaptive Gauss-Kronrod to 1e-14 relative, over t in [-1, 1]: Boost 1.74
/// compares the error on [-1, 1] with the tolerance times the integral on [lo, hi], so on a
/// short interval it would bisect down to its deepest level.
template <class F>
double integral_over(F f, double lo, double hi) {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const auto g = [&](double t) { return half * f(mid + half * t); };
  return boost::math::quadrature::gauss_kronrod<double, 31>::integrate(g, -1.0, 1.0, 15, 1e-14);
}

/// A monotone piece of the curve d(a), in the order of a: smooth on [lo, hi] inside one interval
/// between steps of w, or vertical at a step (lo == hi, from d(b-) to d(b+)).
struct Piece {
  double lo = 0.0;
  double hi = 0.0;
  double start_depth = 0.0;  ///< d at lo (from inside the piece)
  double end_depth = 0.0;    ///< d at hi
  bool rising = false;
  bool vertical = false;
  std::size_t interval = 0;  ///< the interval between steps that holds a smooth piece
};

/// Consecutive pieces of one direction: a rising branch runs from a local minimum of d(a) to a
/// local maximum, a falling one the other way.
struct Branch {
  std::size_t first = 0;  ///< its first piece
  std::size_t last = 0;   ///< its last piece
  bool rising = false;
};

/// d(a) = g(a) - sqrt(2 pi a w(a)/E*) cut into pieces and branches, from a = 0 out to the first
/// passage of d(a) through the deepest indentation (the approach goes no further).
class EquilibriumCurve {
 public:
  EquilibriumCurve(double effective_modulus, double tip_radius, const RadialWorkOfAdhesion& w,
                   double deepest_indentation, int samples_per_scale)
      : modulus_(effective_modulus),
        tip_radius_(tip_radius),
        w_(w),
        griffith_(2.0 * std::numbers::pi / effective_modulus) {
    double scale = w.finest_scale;
    const double w0 = w.value(0.0);
    if (w0 > 0.0) scale = std::min(scale, std::cbrt(griffith_ * w0 * tip_radius * tip_radius));
    spacing_ = scale / samples_per_scale;
    walk(deepest_indentation);
  }

  const std::vector<Piece>& pieces() const { return pieces_; }
  const std::vector<Branch>& branches() const { return branches_; }
  double spacing() const { return spacing_; }

  double start_depth(const Branch& b) const { return pieces_[b.first].start_depth; }
  double end_depth(const Branch& b) const { return pieces_[b.last].end_depth; }
  double lo(const Branch& b) const { return pieces_[b.first].lo; }
  double hi(const Branch& b) const { return pieces_[b.last].hi; }

  /// d(a) inside interval m (at its ends: w just inside).
  double depth(double a, std::size_t m) const {
    return a * a / tip_radius_ - std::sqrt(griffith_ * a * work(w_.value, a, m));
  }
  /// d'(a) inside interval m.
  double depth_slope(double a, std::size_t m) const {
    const double w = work(w_.value, a, m);
    const double dw = work(w_.slope, a, m);
    return 2.0 * a / tip_radius_ - griffith_ * (w + a * dw) / (2.0 * std::sqrt(griffith_ * a * w));
  }
  /// F = E* (2 a d - 2 a^3/(3R)).
  double force(double a, double d) const {
    return modulus_ * (2.0 * a * d - 2.0 * a * a * a / (3.0 * tip_radius_));
  }
  RadialFrontState state(double a, double d) const { return {d, a, force(a, d)}; }

  /// The radius on piece p where d(a) = d (d within the piece's range).
  double radius_on(const Piece& p, double d) const {
    if (p.vertical || d == p.start_depth) return p.lo;
    if (d == p.end_depth) return p.hi;
    const auto f = [&](double a) { return depth(a, p.interval) - d; };
    return bracketed_root(f, p.lo, p.hi, p.start_depth - d, p.end_depth - d);
  }
  /// The radius on the rising branch b where d(a) = d (clamped to the branch's ends).
  double radius_on(const Branch& b, double d) const {
    for (std::size_t i = b.first; i <= b.last; ++i) {
      const Piece& p = pieces_[i];
      if (d <= p.end_depth) return d <= p.start_depth ? p.lo : radius_on(p, d);
    }
    return hi(b);
  }

 private:
  double lower(std::size_t m) const { return m == 0 ? 0.0 : w_.steps[m - 1]; }
  double upper(std::size_t m) const { return m < w_.steps.size() ? w_.steps[m] : kInfinity; }

  /// f(a) inside interval m: at a step bounding it, f just inside (one ulp off the step).
  double work(const std::function<double(double)>& f, double a, std::size_t m) const {
    if (m > 0 && a <= lower(m)) return f(std::nextafter(lower(m), kInfinity));
    if (a >= upper(m)) return f(std::nextafter(upper(m), 0.0));
    return f(a);
  }

  /// Appends a monotone piece and grows or starts a branch.
  void add(Piece p) {
    pieces_.push_back(p);
    if (!branches_.empty() && branches_.back().rising == p.rising) {
      branches_.back().last = pieces_.size() - 1;
    } else {
      branches_.push_back({pieces_.size() - 1, pieces_.size() - 1, p.rising});
    }
  }
  void add_smooth(double lo, double hi, bool rising, std::size_t m) {
    if (hi <= lo) return;
    const double start = lo == 0.0 ? 0.0 : depth(lo, m);
    add({lo, hi, start, depth(hi, m), rising, false, m});
  }

  /// Samples d'(a) interval by interval, cuts the curve at every sign change (located by TOMS
  /// 748 on d') and at every step, and stops at the first a where d(a) >= d_max on a rising
  /// piece.
  void walk(double deepest_indentation) {
    std::int64_t samples = 0;
    for (std::size_t m = 0; m <= w_.steps.size(); ++m) {
      const double lo = lower(m), hi = upper(m);
      if (m > 0) {
        const double inside = depth(lo, m - 1), outside = depth(lo, m);
        if (outside != inside) {
          add({lo, lo, inside, outside, outside > inside, true, m});
          if (outside > inside && outside >= deepest_indentation) return;
        }
      }
      // Out of a = 0 itself (d' is infinite there) the first sample sits just beside it.
      double x_prev = m == 0 ? 1e-9 * spacing_ : lo;
      double s_prev = depth_slope(x_prev, m);
      double piece_lo = lo;
      const auto slope = [&](double a) { return depth_slope(a, m); };
      for (std::int64_t i = 1;; ++i) {
        if (++samples > kMaxSamples) {
          throw std::runtime_error(
              "radial_fixed_grips_loop: d(a) stays below the deepest "
              "indentation out to a = " +
              std::to_string(x_prev));
        }
        double x = lo + static_cast<double>(i) * spacing_;
        const bool last = x >= hi;
        if (last) x = hi;
        const double s = depth_slope(x, m);
        if (!std::isfinite(s) || !std::isfinite(s_prev)) {
          throw std::invalid_argument("radial_fixed_grips_loop: d'(a) is not finite near a = " +
                                      std::to_string(x) + " (is w(r) > 0 there?)");
        }
        if ((s > 0.0) != (s_prev > 0.0)) {
          const double extremum = bracketed_root(slope, x_prev, x, s_prev, s);
          add_smooth(piece_lo, extremum, s_prev > 0.0, m);
          if (s_prev > 0.0 && depth(extremum, m) >= deepest_indentation) return;
          piece_lo = extremum;
        }
        if (s > 0.0 && depth(x, m) >= deepest_indentation) {
          add_smooth(piece_lo, x, true, m);
          return;
        }
        if (last) {
          add_smooth(piece_lo, hi, s > 0.0, m);
          break;
        }
        x_prev = x;
        s_prev = s;
      }
    }
  }

  double modulus_;
  double tip_radius_;
  const RadialWorkOfAdhesion& w_;
  double griffith_;  ///< 2 pi / E*
  double spacing_ = 0.0;
  std::vector<Piece> pieces_;
  std::vector<Branch> branches_;
};

/// Follows the front along the curve and adds up the loop.
class Tracker {
 public:
  Tracker(const EquilibriumCurve& curve, double finest_scale)
      : curve_(curve), quadrature_length_(finest_scale / 4.0) {}

  /// Moves the front along branch b from d = from to d = to (both in the branch's range), piece
  /// by piece, appending the segments, their int F dd and (retract) the most negative F.
  void follow(const Branch& b, double from, double to, std::vector<RadialFrontSegment>& path,
              bool retract) {
    if (from == to) return;
    const double low = std::min(from, to), high = std::max(from, to);
    const std::size_t n = b.last - b.first + 1;
    for (std::size_t k = 0; k < n; ++k) {
      const Piece& p = curve_.pieces()[to > from ? b.first + k : b.last - k];
      const double piece_low = std::max(low, p.start_depth);
      const double piece_high = std::min(high, p.end_depth);
      if (piece_high <= piece_low) continue;
      const double d1 = to > from ? piece_low : piece_high;
      const double d2 = to > from ? piece_high : piece_low;
      const RadialFrontSegment s{curve_.state(curve_.radius_on(p, d1), d1),
                                 curve_.state(curve_.radius_on(p, d2), d2)};
      path.push_back(s);
      energy_ += work_along(p, s);
      if (retract) lowest_force_on(p, s);
    }
  }

  /// The front pinned at `from`'s radius while d runs to `to`'s (F linear in d).
  void pinned(const RadialFrontState& from, const RadialFrontState& to,
              std::vector<RadialFrontSegment>& path) {
    path.push_back({from, to});
    energy_ += 0.5 * (from.normal_force + to.normal_force) * (to.indentation - from.indentation);
    for (const RadialFrontState& end : {from, to}) {
      if (end.normal_force < peak_tension_.normal_force) peak_tension_ = end;
    }
  }

  /// Starts the record of the most negative F at the turn of the path.
  void start_retract(const RadialFrontState& turn) { peak_tension_ = turn; }

  double energy() const { return energy_; }
  const RadialFrontState& peak_tension() const { return peak_tension_; }

 private:
  /// int F dd over one segment: int F(a) d'(a) da, or at a pinned front (F linear in d)
  /// E* (a (d2^2 - d1^2) - (2 a^3/(3R)) (d2 - d1)), i.e. the mean of F at both ends times the
  /// change of d.
  double work_along(const Piece& p, const RadialFrontSegment& s) const {
    if (p.vertical) {
      return 0.5 * (s.from.normal_force + s.to.normal_force) *
             (s.to.indentation - s.from.indentation);
    }
    const double a1 = std::min(s.from.contact_radius, s.to.contact_radius);
    const double a2 = std::max(s.from.contact_radius, s.to.contact_radius);
    const double orientation = s.to.contact_radius > s.from.contact_radius ? 1.0 : -1.0;
    const auto integrand = [&](double a) {
      return curve_.force(a, curve_.depth(a, p.interval)) * curve_.depth_slope(a, p.interval);
    };
    const auto parts = static_cast<int>(std::max(1.0, std::ceil((a2 - a1) / quadrature_length_)));
    double sum = 0.0;
    for (int i = 0; i < parts; ++i) {
      const double lo = a1 + (a2 - a1) * i / parts;
      const double hi = i + 1 == parts ? a2 : a1 + (a2 - a1) * (i + 1) / parts;
      sum += integral_over(integrand, lo, hi);
    }
    return orientation * sum;
  }

  /// Lowers the record of the most negative F by the segment's ends and by every local minimum
  /// of F(a) along it (sampled at the grid spacing, refined by Brent's method).
  void lowest_force_on(const Piece& p, const RadialFrontSegment& s) {
    for (const RadialFrontState& end : {s.from, s.to}) {
      if (end.normal_force < peak_tension_.normal_force) peak_tension_ = end;
    }
    if (p.vertical) return;  // F is linear in d at a pinned front
    const double a1 = std::min(s.from.contact_radius, s.to.contact_radius);
    const double a2 = std::max(s.from.contact_radius, s.to.contact_radius);
    const auto force = [&](double a) { return curve_.force(a, curve_.depth(a, p.interval)); };
    const auto count = static_cast<int>(std::ceil((a2 - a1) / curve_.spacing()));
    if (count < 2) return;
    std::vector<double> radii(static_cast<std::size_t>(count) + 1), forces(radii.size());
    for (std::size_t i = 0; i < radii.size(); ++i) {
      radii[i] = i + 1 == radii.size() ? a2 : a1 + (a2 - a1) * static_cast<double>(i) / count;
      forces[i] = force(radii[i]);
    }
    for (std::size_t i = 1; i + 1 < radii.size(); ++i) {
      if (forces[i] > forces[i - 1] || forces[i] > forces[i + 1]) continue;
      // Over t in [0, 1]: Brent's tolerance has an absolute part (2^-27), too coarse in a [m].
      const double lo = radii[i - 1], width = radii[i + 1] - radii[i - 1];
      const auto [t, f] =
          boost::math::tools::brent_find_minima([&](double t) { return force(lo + t * width); },
                                                0.0, 1.0, std::numeric_limits<double>::digits);
      if (f < peak_tension_.normal_force) {
        const double a = lo + t * width;
        peak_tension_ = curve_.state(a, curve_.depth(a, p.interval));
      }
    }
  }

  const EquilibriumCurve& curve_;
  double quadrature_length_;
  double energy_ = 0.0;
  RadialFrontState peak_tension_;
};

void check_arguments(double effective_modulus, double tip_radius, const RadialWorkOfAdhesion& w,
                     double deepest_indentation, int samples_per_scale) {
  const auto refuse = [](const std::string& what) {
    throw std::invalid_argument("radial_fixed_grips_loop: " + what);
  };
  if (!(effective_modulus > 0.0) || !std::isfinite(effective_modulus)) refuse("E* must be > 0");
  if (!(tip_radius > 0.0) || !std::isfinite(tip_radius)) refuse("R must be > 0");
  if (!w.value || !w.slope) refuse("w(r) and dw/dr must both be given");
  if (!(w.finest_scale > 0.0) || !std::isfinite(w.finest_scale)) {
    refuse("the finest scale of w must be > 0");
  }
  for (std::size_t i = 0; i < w.steps.size(); ++i) {
    if (!(w.steps[i] > (i == 0 ? 0.0 : w.steps[i - 1])) || !std::isfinite(w.steps[i])) {
      refuse("the steps of w must be > 0, finite and ascending");
    }
  }
  if (!(deepest_indentation >= 0.0) || !std::isfinite(deepest_indentation)) {
    refuse("the deepest indentation must be >= 0 (the contact forms at d = 0)");
  }
  if (samples_per_scale < 2) refuse("at least 2 samples per scale");
}

}  // namespace

std::size_t RadialLoopReference::jumps_in() const {
  return static_cast<std::size_t>(std::count_if(
      jumps.begin(), jumps.end(), [](const RadialFrontJump& j) { return j.advancing; }));
}

std::size_t RadialLoopReference::jumps_out() const { return jumps.size() - jumps_in(); }

RadialLoopReference radial_fixed_grips_loop(double effective_modulus, double tip_radius,
                                            const RadialWorkOfAdhesion& work_of_adhesion,
                                            double deepest_indentation, int samples_per_scale) {
  return radial_fixed_grips_loop(effective_modulus, tip_radius, work_of_adhesion, work_of_adhesion,
                                 deepest_indentation, samples_per_scale);
}

RadialLoopReference radial_fixed_grips_loop(double effective_modulus, double tip_radius,
                                            const RadialWorkOfAdhesion& work_of_adhesion,
                                            const RadialWorkOfAdhesion& approach,
                                            double deepest_indentation, int samples_per_scale) {
  check_arguments(effective_modulus, tip_radius, work_of_adhesion, deepest_indentation,
                  samples_per_scale);
  check_arguments(effective_modulus, tip_radius, approach, deepest_indentation, samples_per_scale);
  const double finest = std::min(work_of_adhesion.finest_scale, approach.finest_scale);
  RadialLoopReference loop;

  // Approach: the touch at d = 0 from a = 0, then up the advancing curve's branches to d_max.
  const EquilibriumCurve advancing(effective_modulus, tip_radius, approach, deepest_indentation,
                                   samples_per_scale);
  Tracker approach_tracker(advancing, finest);
  double a_max = 0.0;
  {
    const std::vector<Branch>& branches = advancing.branches();
    const std::size_t last = branches.size() - 1;  // rising: it reaches d_max
    // The first rising branch from `from` on that d(a) passes through d upward: where a
    // jump-in at d lands (the first passage of d(a) through d beyond the jump).
    const auto landing_in = [&](std::size_t from, double d) {
      for (std::size_t j = from; j < last; ++j) {
        if (branches[j].rising && advancing.end_depth(branches[j]) > d) return j;
      }
      return last;
    };
    std::size_t k = landing_in(0, 0.0);
    double d = 0.0;
    if (const double a = advancing.radius_on(branches[k], 0.0); a > 0.0) {
      loop.jumps.push_back({0.0, 0.0, a, true});
    }
    while (k != last && advancing.end_depth(branches[k]) < deepest_indentation) {
      const double top = advancing.end_depth(branches[k]);
      approach_tracker.follow(branches[k], d, top, loop.approach, false);
      const std::size_t j = landing_in(k + 1, top);
      loop.jumps.push_back(
          {top, advancing.hi(branches[k]), advancing.radius_on(branches[j], top), true});
      k = j;
      d = top;
    }
    approach_tracker.follow(branches[k], d, deepest_indentation, loop.approach, false);
    a_max = advancing.radius_on(branches[k], deepest_indentation);
  }

  // Retract on the receding curve, which lies below the advancing one and so reaches d_max
  // beyond a_max.
  const EquilibriumCurve curve(effective_modulus, tip_radius, work_of_adhesion, deepest_indentation,
                               samples_per_scale);
  const std::vector<Branch>& branches = curve.branches();
  Tracker tracker(curve, finest);
  // The nearest rising branch below `from` whose bottom lies under d: where a jump-out at d
  // lands; none, the contact separates.
  const auto landing_out = [&](std::size_t from, double d) -> std::optional<std::size_t> {
    for (std::size_t j = from; j-- > 0;) {
      if (branches[j].rising && curve.start_depth(branches[j]) < d) return j;
    }
    return std::nullopt;
  };
  // The branch and piece of the receding curve that hold a_max, and d there.
  std::size_t k = branches.size() - 1;
  std::size_t piece = 0;
  for (std::size_t b = 0; b < branches.size(); ++b) {
    if (curve.hi(branches[b]) >= a_max) {
      k = b;
      break;
    }
  }
  for (std::size_t i = branches[k].first; i <= branches[k].last; ++i) {
    piece = i;
    if (curve.pieces()[i].hi >= a_max) break;
  }
  // One w both ways: the front turns on its branch at d_max itself.
  const bool reversible = &approach == &work_of_adhesion;
  double d = reversible ? deepest_indentation : curve.depth(a_max, curve.pieces()[piece].interval);
  const RadialFrontState turn = curve.state(a_max, deepest_indentation);
  tracker.start_retract(turn);
  if (d < deepest_indentation) tracker.pinned(turn, curve.state(a_max, d), loop.retract);
  if (!branches[k].rising) {
    // A falling branch: the front cannot recede at a_max, it jumps back at once.
    const std::optional<std::size_t> j = landing_out(k, d);
    if (!j) {
      loop.separation = curve.state(a_max, d);
      loop.jumps.push_back({d, a_max, 0.0, false});
      loop.peak_tension = tracker.peak_tension();
      loop.loop_energy = approach_tracker.energy() + tracker.energy();
      return loop;
    }
    loop.jumps.push_back({d, a_max, curve.radius_on(branches[*j], d), false});
    k = *j;
  }
  for (;;) {
    const double bottom = curve.start_depth(branches[k]);
    tracker.follow(branches[k], d, bottom, loop.retract, true);
    const double from = curve.lo(branches[k]);
    const std::optional<std::size_t> j = from > 0.0 ? landing_out(k, bottom) : std::nullopt;
    if (!j) {
      loop.separation = curve.state(from, bottom);
      if (from > 0.0) loop.jumps.push_back({bottom, from, 0.0, false});
      break;
    }
    loop.jumps.push_back({bottom, from, curve.radius_on(branches[*j], bottom), false});
    k = *j;
    d = bottom;
  }
  loop.peak_tension = tracker.peak_tension();
  loop.loop_energy = approach_tracker.energy() + tracker.energy();
  return loop;
}

}  // namespace mdrsim::radial_front_reference
