// What meeting rtol means, for every engine and driver: one rule for every estimate.
#pragma once

#include <algorithm>
#include <cmath>

namespace mdrsim {

/// Whether the error estimate `error` of `value` meets the relative tolerance `rtol`:
/// error <= rtol max(|value|, floor). `floor` [the value's unit] is the scale below which a
/// value is held to rtol absolutely (what is zero on the rows, or a share of the path's largest
/// value), so that a value near zero is not asked for digits it cannot have; `absolute` a
/// tolerance no rtol goes below (the rounding of the sums behind a work).
inline bool meets_rtol(double error, double value, double rtol, double floor = 0.0,
                       double absolute = 0.0) {
  return error <= std::max(rtol * std::max(std::abs(value), floor), absolute);
}

}  // namespace mdrsim
