// A running total of exponential sums that share their decay times, each entering and leaving
// at its own time: the sum of many springs' loads read in O(terms), not O(springs).
#pragma once

#include <vector>

#include "engine/model/prony_root.hpp"

namespace mdrsim {

/// sum_i f_i(t - t_i) over the sums f_i in it, f_i entered at t_i; every f_i has the same decay
/// times in the same order. Kept as one sum on its own clock: an entry or a leave rebases it to
/// the present (the constant takes slope times the step, each amplitude its decay), so that no
/// amplitude is ever carried to a time before its entry.
class ExponentialSumTotal {
 public:
  /// Empty, at time `now` [s].
  void clear(double now);
  /// f, a function of s = t - since, enters (sign +1) or leaves (sign -1) at time `now` >= since.
  void add(const ExponentialSum& f, double since, double now, double sign);
  /// The total at time t [s], t at or after the last entry or leave.
  double at(double t) const;

 private:
  void rebase(double now);

  double time_ = 0.0;
  ExponentialSum total_;
};

}  // namespace mdrsim
