// The error-estimate rule every combination of rows uses: the values of rows of N, 2N, 4N ...
// springs, plain or extrapolated, and how far the finest of them may be from the continuum.
#pragma once

#include <algorithm>
#include <cmath>
#include <span>

namespace mdrsim {

/// No estimate is below the rounding of the sums behind a value (rows of up to 2^25 springs).
inline constexpr double kEstimateRounding = 1e-13;

/// kEstimateRounding of |value|: the floor of every estimate of `value`.
inline double rounding_floor(double value) { return kEstimateRounding * std::abs(value); }

/// Richardson's value from rows of N and 2N springs of an O(1/N) quantity: 2 fine - coarse.
inline double richardson_value(double coarse, double fine) { return 2.0 * fine - coarse; }

/// The estimate of |q.back() - continuum| from the values of rows of doubling springs (plain
/// Q_j or extrapolated R_j, coarsest first, at least two): 2 max(|q_j - q_j-1|,
/// |q_j-1 - q_j-2| / 2). The first difference is the error itself for a plain row (C/N_j) and
/// (2^p - 1) times it for Richardson of order p; the factor 2 and the earlier difference guard
/// against two rows that agree by chance (a plain row's sawtooth, the irregular O(dx^2) part
/// of a fold located between springs, which made the plain difference fall short by 1.5x in
/// the random set).
inline double change_estimate(std::span<const double> q) {
  const std::size_t j = q.size() - 1;
  double e = std::abs(q[j] - q[j - 1]);
  if (j >= 2) e = std::max(e, 0.5 * std::abs(q[j - 1] - q[j - 2]));
  return 2.0 * e;
}

}  // namespace mdrsim
