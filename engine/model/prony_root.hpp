// A line load over a linear motion of a viscoelastic spring, a + b s + sum_j c_j exp(-s / tau_j),
// and the first time it reaches a level (a let-go, a lift, a touch), located exactly.
#pragma once

#include <boost/container/small_vector.hpp>

#include <optional>
#include <span>
#include <vector>

namespace mdrsim {

/// One decaying part c exp(-s / tau).
struct ExponentialDecay {
  double amplitude;  ///< c [the sum's unit]
  double time;       ///< tau [s] > 0
};

/// A few values, one per Prony term or decay: a row's events build them at every step, so they
/// stay off the heap up to four. They pass as spans.
template <class T>
class FewValues : public boost::container::small_vector<T, 4> {
 public:
  using boost::container::small_vector<T, 4>::small_vector;
  operator std::span<const T>() const { return {this->data(), this->size()}; }
  operator std::span<T>() { return {this->data(), this->size()}; }
};

/// f(s) = constant + slope s + sum_j amplitude_j exp(-s / time_j), s [s] from the motion's start.
struct ExponentialSum {
  double constant = 0.0;
  double slope = 0.0;  ///< [the sum's unit / s]
  std::vector<ExponentialDecay> decays;

  double at(double s) const;
  /// f'(s) [the sum's unit / s].
  double slope_at(double s) const;
};

/// The first s in (0, span] at which f(s) = level, f reaching it from the side it is on just
/// after s = 0 (so a spring whose load is 0 at the start and rises is not found at once);
/// nullopt when f stays on that side up to span. Exact to the last bits of s: f is split into
/// pieces where it is monotone, at the zeros of f' (found the same way, since f' = slope + a sum
/// of decays, whose own derivative divided by its slowest decay is again a constant plus decays:
/// an exponential sum with K decays has at most K such pieces), and the first piece whose ends
/// straddle the level is solved by TOMS 748, or with one decay (f convex or concave throughout)
/// by Newton from the end where it cannot overshoot, to the same 4 eps.
std::optional<double> first_crossing(const ExponentialSum& f, double level, double span);
/// The same, Newton starting from `near` [s] where it falls on the piece (a neighbouring
/// spring's crossing, found just before: Ting's releases are close in time), not from the
/// closed form or the piece's end: the same root to its 4 eps, not to the bit.
std::optional<double> first_crossing(const ExponentialSum& f, double level, double span,
                                     std::optional<double> near);

}  // namespace mdrsim
