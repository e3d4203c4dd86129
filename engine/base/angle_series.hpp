// tan(t) - t without the cancellation of the difference at small t.
#pragma once

#include <cmath>

namespace mdrsim {

/// tan(t) - t [1] for 0 <= t < pi/2: below t = 0.1 by its series (terms to t^13; the next is
/// below 1e-14 of the sum there), above by the difference, which no longer cancels.
inline double tan_minus_angle(double t) {
  if (t >= 0.1) return std::tan(t) - t;
  const double t2 = t * t;
  return t * t2 *
         (1.0 / 3.0 +
          t2 * (2.0 / 15.0 +
                t2 * (17.0 / 315.0 +
                      t2 * (62.0 / 2835.0 + t2 * (1382.0 / 155925.0 + t2 * 21844.0 / 6081075.0)))));
}

}  // namespace mdrsim
