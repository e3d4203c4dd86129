// The monotone pieces of an exponential sum and the first that reaches a level.
#include "engine/model/prony_root.hpp"

#include <boost/container/small_vector.hpp>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/lambert_w.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/base/bracketed_root.hpp"

namespace mdrsim {
namespace {

// A run's events each locate a root: its few terms (and the pieces' ends) stay off the heap,
// which took most of an event's time.
constexpr std::size_t kInlineTerms = 8;
template <class T>
using InlineVector = boost::container::small_vector<T, kInlineTerms>;

// p(s) = constant + sum_j amplitude_j exp(-rate_j s), rates >= 0 and distinct after merging.
struct ConstantPlusDecays {
  double constant = 0.0;
  InlineVector<std::pair<double, double>> terms;  // amplitude, rate [1/s]

  double at(double s) const {
    double sum = constant;
    if (s == 0.0) {
      for (const auto& term : terms) sum += term.first;  // exp(-rate 0) is 1 exactly
      return sum;
    }
    for (const auto& [amplitude, rate] : terms) {
      sum += amplitude * std::exp(-rate * s);
    }
    return sum;
  }
};

// Equal rates merged, zero amplitudes dropped, a zero rate folded into the constant, rates
// ascending.
ConstantPlusDecays merged_decays(ConstantPlusDecays p) {
  std::sort(p.terms.begin(), p.terms.end(),
            [](const auto& x, const auto& y) { return x.second < y.second; });
  ConstantPlusDecays out{p.constant, {}};
  for (const auto& [amplitude, rate] : p.terms) {
    if (rate == 0.0) {
      out.constant += amplitude;
    } else if (!out.terms.empty() && out.terms.back().second == rate) {
      out.terms.back().first += amplitude;
    } else {
      out.terms.emplace_back(amplitude, rate);
    }
  }
  out.terms.erase(std::remove_if(out.terms.begin(), out.terms.end(),
                                 [](const auto& term) { return term.first == 0.0; }),
                  out.terms.end());
  return out;
}

// bracketed_root with fn's values at the ends known: TOMS 748 takes the same steps from them.
template <class Fn>
double bracketed_root_from(Fn fn, double lo, double hi, double fn_lo, double fn_hi) {
  const RootBracket b = bracket_root(fn, lo, hi, fn_lo, fn_hi);
  return 0.5 * (b.lo + b.hi);
}

// Whether p is nonzero and of one sign everywhere: a nonzero constant and decays of its sign.
// Then p has no zeros to look for (a sum of terms of one sign rounds to that sign, and with a
// nonzero constant never to zero).
bool one_signed(const ConstantPlusDecays& p) {
  if (p.constant == 0.0) return false;
  const bool positive = p.constant > 0.0;
  return std::all_of(p.terms.begin(), p.terms.end(), [&](const auto& term) {
    return positive ? term.first >= 0.0 : term.first <= 0.0;
  });
}

// Appends to `roots` the sign changes of fn strictly inside (points.front(), points.back()),
// fn monotone on each [points[i], points[i+1]]. (Appended in place: a small vector returned by
// value trips GCC's -Wstringop-overread inside Boost.Container.)
template <class Fn>
void append_sign_changes(Fn fn, const InlineVector<double>& points, InlineVector<double>& roots) {
  const double first = points.front(), last = points.back();
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double lo = points[i], hi = points[i + 1];
    const double f_lo = fn(lo), f_hi = fn(hi);
    double root = 0.0;
    if (f_hi == 0.0) {
      root = hi;
    } else if (f_lo != 0.0 && (f_lo < 0.0) != (f_hi < 0.0)) {
      root = bracketed_root_from(fn, lo, hi, f_lo, f_hi);
    } else {
      continue;
    }
    if (root > first && root < last) roots.push_back(root);
  }
}

// Whether append_decay_sum_zeros(raw, 0, hi) finds no zero because raw falls from below zero
// throughout: a negative constant and decays of nonnegative amplitude, so p' has its sign
// wherever it is read (its own constant -a_1 r_1 negative, its decays not positive) and p's
// rounded values only fall (each a_j exp(-r_j s) rounds to at most a_j), from p(0) < 0 read as
// append_sign_changes reads it. Its one call to exp, at hi, is then not needed.
bool falls_below_zero(const ConstantPlusDecays& raw) {
  if (!(raw.constant < 0.0)) return false;
  if (!std::all_of(raw.terms.begin(), raw.terms.end(),
                   [](const auto& term) { return term.first >= 0.0; })) {
    return false;
  }
  const ConstantPlusDecays p = merged_decays(raw);
  if (p.terms.empty()) return true;
  return p.terms.front().first * p.terms.front().second > 0.0 && p.at(0.0) < 0.0;
}

// Appends to `zeros` the zeros of p in (lo, hi): p' = exp(-r_1 s) q(s) with q = -a_1 r_1 -
// sum_{j >= 2} a_j r_j exp(-(r_j - r_1) s), one decay fewer; p is monotone between q's zeros.
void append_decay_sum_zeros(const ConstantPlusDecays& raw, double lo, double hi,
                            InlineVector<double>& zeros) {
  const ConstantPlusDecays p = merged_decays(raw);
  if (p.terms.empty()) {
    return;
  }
  const double slowest = p.terms.front().second;
  ConstantPlusDecays derivative{-p.terms.front().first * slowest, {}};
  for (std::size_t j = 1; j < p.terms.size(); ++j) {
    const auto& [amplitude, rate] = p.terms[j];
    derivative.terms.emplace_back(-amplitude * rate, rate - slowest);
  }
  InlineVector<double> points{lo};
  if (!one_signed(derivative)) append_decay_sum_zeros(derivative, lo, hi, points);
  points.push_back(hi);
  append_sign_changes([&](double s) { return p.at(s); }, points, zeros);
}

// Where g(s) = A + b s + c exp(-s / tau) vanishes on [lo, hi], in closed form: with
// u = s + A / b, (u / tau) exp(u / tau) = -c exp(A / (b tau)) / (b tau) =: x, so s = tau W(x) -
// A / b, W_0 or W_-1 (both where -1/e < x < 0) whichever falls on the piece; with b = 0,
// s = tau ln(-c / A). None where x leaves W's domain or overflows. Exact to a few ulps of its
// terms, which may cancel: it is a start for Newton, not the root.
std::optional<double> one_decay_start(double a, double b, double c, double tau, double lo,
                                      double hi) {
  const auto on_piece = [&](double s) { return s >= lo && s <= hi; };
  if (b == 0.0) {
    const double ratio = -c / a;
    if (!(ratio > 0.0)) return std::nullopt;
    const double s = tau * std::log(ratio);
    return on_piece(s) ? std::optional<double>(s) : std::nullopt;
  }
  const double scale = b * tau;
  const double x = -c / scale * std::exp(a / scale);
  if (!std::isfinite(x) || x < -boost::math::constants::exp_minus_one<double>()) {
    return std::nullopt;
  }
  // Boost's W raises on denormals and at its domain's edges: a start is only a start, so those
  // give NaN or an infinity, off the piece.
  using Quiet = boost::math::policies::policy<
      boost::math::policies::domain_error<boost::math::policies::ignore_error>,
      boost::math::policies::overflow_error<boost::math::policies::ignore_error>,
      boost::math::policies::underflow_error<boost::math::policies::ignore_error>,
      boost::math::policies::evaluation_error<boost::math::policies::ignore_error>>;
  const double principal = tau * boost::math::lambert_w0(x, Quiet()) - a / b;
  if (on_piece(principal)) return principal;
  if (x < -std::numeric_limits<double>::min()) {
    const double lower = tau * boost::math::lambert_wm1(x, Quiet()) - a / b;
    if (on_piece(lower)) return lower;
  }
  return std::nullopt;
}

// The root of g(s) = f(s) - level on a piece [lo, hi] where g is monotone and changes sign
// (g_lo its value at lo), f's decays all of one sign: g'' = sum_j (c_j / tau_j^2)
// exp(-s / tau_j) keeps their sign, so a Newton step from anywhere on the piece lands on the
// side where g has the sign of g'' (Fourier's condition), and from there moves to the root
// without overshooting, an exp a decay a step, quadratically near it. With one decay it starts
// from the closed form (one_decay_start); with several from that end, far from the root, so
// while Newton's step is longer than 1e-6 of the piece it takes Halley's (g'' is free: cubic,
// about a third fewer steps there), which may pass the root: the Newton steps after it land on
// Fourier's side again. It stops at a step within 4 eps of s, TOMS 748's tolerance; decays of
// both signs, a step that leaves the bracket (rounding far from the root) or no convergence in
// kMostNewtonSteps hand the piece to TOMS 748.
constexpr int kMostNewtonSteps = 60;
std::optional<double> one_signed_decays_root(const ExponentialSum& f, double level, double lo,
                                             double hi, double g_lo, std::optional<double> near,
                                             double slope_sign = 0.0) {
  const bool convex = std::any_of(f.decays.begin(), f.decays.end(),
                                  [](const ExponentialDecay& d) { return d.amplitude > 0.0; });
  const bool concave = std::any_of(f.decays.begin(), f.decays.end(),
                                   [](const ExponentialDecay& d) { return d.amplitude < 0.0; });
  if (convex == concave) return std::nullopt;
  std::optional<double> start;
  if (near && *near >= lo && *near <= hi) {
    // Near the root: on Fourier's side Newton goes on from there, on the other its first step
    // lands there (the tangent of a convex or concave piece crosses the level on that side).
    start = near;
  } else if (f.decays.size() == 1) {
    const ExponentialDecay& d = f.decays.front();
    start = one_decay_start(f.constant - level, f.slope, d.amplitude, d.time, lo, hi);
  }
  double s = start.value_or((g_lo > 0.0) == convex ? lo : hi);
  const bool halley = f.decays.size() > 1;
  // From a start near the root the steps shrink quadratically: once the next one, about
  // |g'' / (2 g')| times this one squared, falls within an eps of s, this step's end is the root
  // to that eps and the step that would confirm it is not taken. The estimate holds where the
  // step is short against the fastest decay's time (g'' and g' barely change along it).
  const bool foresee = near.has_value() && start == near;
  const double eps = std::numeric_limits<double>::epsilon();
  double shortest = HUGE_VAL;
  // Each decay's rate 1 / tau once: a step multiplies by it (a division a decay and step would
  // stall every step on its latency).
  InlineVector<double> rates;
  for (const ExponentialDecay& d : f.decays) {
    shortest = std::min(shortest, d.time);
    rates.push_back(1.0 / d.time);
  }
  for (int step = 0; step < kMostNewtonSteps; ++step) {
    double g = f.constant + f.slope * s;
    double slope = f.slope;
    double curvature = 0.0;
    for (std::size_t m = 0; m < f.decays.size(); ++m) {
      const double e = f.decays[m].amplitude * std::exp(-s * rates[m]);
      g += e;
      slope -= e * rates[m];
      if (halley || foresee) curvature += e * rates[m] * rates[m];
    }
    g -= level;
    // A piece taken whole on trust (hinted_first_crossing): g' keeps its sign on it at every point
    // Newton reads, or the piece is not one.
    if (slope_sign != 0.0 && !(slope * slope_sign > 0.0)) return std::nullopt;
    if (g == 0.0) return s;
    if (!(slope != 0.0)) return std::nullopt;
    double next = s - g / slope;
    if (halley && std::abs(next - s) > 1e-6 * (hi - lo)) {
      const double far = s - 2.0 * g * slope / (2.0 * slope * slope - g * curvature);
      if (far >= lo && far <= hi) next = far;
    }
    if (!(next >= lo && next <= hi)) return std::nullopt;
    const double taken = std::abs(next - s);
    if (taken <= 4.0 * eps * std::abs(next)) return next;
    if (foresee && taken <= 1e-3 * shortest &&
        std::abs(curvature) * taken * taken <= 2.0 * eps * std::abs(next) * std::abs(slope)) {
      return next;
    }
    s = next;
  }
  return std::nullopt;
}

}  // namespace

double ExponentialSum::at(double s) const {
  double sum = constant + slope * s;
  if (s == 0.0) {
    // exp(-0 / tau) is 1 exactly: the same sum without the calls (most reads are at s = 0).
    for (const ExponentialDecay& decay : decays) sum += decay.amplitude;
    return sum;
  }
  for (const ExponentialDecay& decay : decays) {
    sum += decay.amplitude * std::exp(-s / decay.time);
  }
  return sum;
}

double ExponentialSum::slope_at(double s) const {
  double sum = slope;
  if (s == 0.0) {
    for (const ExponentialDecay& decay : decays) sum -= decay.amplitude / decay.time;
    return sum;
  }
  for (const ExponentialDecay& decay : decays) {
    sum -= decay.amplitude / decay.time * std::exp(-s / decay.time);
  }
  return sum;
}

std::optional<double> first_crossing(const ExponentialSum& f, double level, double span) {
  return first_crossing(f, level, span, std::nullopt);
}

/// first_crossing's root where a hint `near` in (0, span] is given, f's decays are of one sign
/// (f' is monotone) and f moves towards the level at 0: Newton from the hint on [0, span] taken
/// as one piece, every point it reads keeping f''s sign at 0, so f is monotone from 0 to the
/// root and no crossing comes earlier. The pieces first_crossing would cut end where f' changes
/// sign, which those points never pass: where this finds a root, first_crossing's Newton finds
/// the same to its 4 eps (bit for bit where f' keeps its sign up to span: the same piece),
/// without reading f at span or cutting the pieces. None otherwise.
namespace {
std::optional<double> hinted_first_crossing(const ExponentialSum& f, double level, double span,
                                            double near) {
  if (!(near > 0.0 && near <= span)) return std::nullopt;
  const double g0 = f.at(0.0) - level;
  const double slope0 = f.slope_at(0.0);
  if (g0 == 0.0 || !(slope0 != 0.0) || (g0 > 0.0) == (slope0 > 0.0)) return std::nullopt;
  const bool convex = std::any_of(f.decays.begin(), f.decays.end(),
                                  [](const ExponentialDecay& d) { return d.amplitude > 0.0; });
  const bool concave = std::any_of(f.decays.begin(), f.decays.end(),
                                   [](const ExponentialDecay& d) { return d.amplitude < 0.0; });
  if (convex == concave) return std::nullopt;
  return one_signed_decays_root(f, level, 0.0, span, g0, near, slope0 > 0.0 ? 1.0 : -1.0);
}
}  // namespace

std::optional<double> first_crossing(const ExponentialSum& f, double level, double span,
                                     std::optional<double> near) {
  if (!(span > 0.0)) {
    return std::nullopt;
  }
  if (near) {
    if (const auto root = hinted_first_crossing(f, level, span, *near)) return root;
  }
  const auto g = [&](double s) { return f.at(s) - level; };
  ConstantPlusDecays derivative{f.slope, {}};
  for (const ExponentialDecay& decay : f.decays) {
    derivative.terms.emplace_back(-decay.amplitude / decay.time, 1.0 / decay.time);
  }
  InlineVector<double> points{0.0};
  if (!one_signed(derivative) && !falls_below_zero(derivative)) {
    append_decay_sum_zeros(derivative, 0.0, span, points);
  }
  points.push_back(span);
  // The side: g at 0, or where g starts at the level, g at the end of the first piece (g moves
  // monotonically away from the level there).
  double side = g(0.0);
  // Starting at the level with one monotone piece, f moves away from it up to span: the piece
  // that would give the side is the whole span.
  if (side == 0.0 && points.size() == 2) return std::nullopt;
  if (side == 0.0) {
    side = g(points[1]);
    if (side == 0.0) {
      return std::nullopt;  // g vanishes on the whole first piece: constant, no crossing
    }
    points.erase(points.begin());
  }
  double g_lo = side;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double lo = points[i], hi = points[i + 1];
    const double g_hi = g(hi);
    if (g_hi == 0.0 || (g_hi < 0.0) != (side < 0.0)) {
      if (g_hi == 0.0) return hi;
      if (const auto root = one_signed_decays_root(f, level, lo, hi, g_lo, near)) return root;
      return bracketed_root_from(g, lo, hi, g_lo, g_hi);
    }
    g_lo = g_hi;
  }
  return std::nullopt;
}

}  // namespace mdrsim
