// The ripple integrals of the wavy profile's image, by power series or Bessel sums.
#include "profiles/wavy_image.hpp"

#include <math.h>  // y0, y1 (POSIX)

#include <cmath>
#include <limits>
#include <numbers>

namespace mdrsim {
namespace {

/// Below this z the power series converges in a few terms without cancellation.
constexpr double kSeriesBelow = 1.0;
/// From this z on, Y_0, Y_1 and the asymptotic series (below): Miller's recurrence costs z steps
/// per call, and a ripple of 2e-9 m in a contact of 5e-4 m (z = 1.6e6) made a preload's
/// quadrature take minutes (a fuzzer's input); a rippled contact's disk check asks millions.
constexpr double kAsymptoticFrom = 32.0;

RippleIntegrals by_series(double z) {
  // term_j = (-1)^j z^(2j+1) / ((2j+1)!!)^2; the slope's term is (2j+1) term_j / z.
  double value = 0.0;
  double slope = 0.0;
  double deficit = 0.0;  // 1 - I' = -sum_{j>=1} (2j+1) term_j / z, apart from I' (no cancellation)
  double power = 1.0;    // (-1)^j z^(2j) / ((2j+1)!!)^2
  for (int j = 0; j < 40; ++j) {
    const double odd = 2.0 * j + 1.0;
    if (j > 0) {
      power *= -z * z / (odd * odd);
      deficit -= power * odd;
    }
    value += power * z;
    slope += power * odd;
    if (std::abs(power) < 1e-18) break;
  }
  return {value, slope, deficit};
}

RippleIntegrals by_bessel_sums(double z) {
  // Miller: the backward recurrence b_{n-1} = (2n/z) b_n - b_{n+1} from far above z gives
  // b_n proportional to J_n(z); J_0 + 2 sum_j J_{2j} = 1 fixes the factor.
  const double reach = z + 30.0;
  const int start = 2 * static_cast<int>((reach + std::sqrt(40.0 * reach)) / 2.0);
  double above = 0.0;     // b_{n+1}
  double at = 1e-30;      // b_n, n = start (even)
  double norm = 0.0;      // J_0 + 2 sum J_{2j}
  double odd_sum = 0.0;   // sum J_{2j+1} / (2j+1)
  double even_sum = 0.0;  // sum_{j>=1} J_{2j} / (1 - 4 j^2)
  for (int n = start; n >= 1; --n) {
    if (n % 2 == 0) {
      const double j = 0.5 * n;
      norm += 2.0 * at;
      even_sum += at / (1.0 - 4.0 * j * j);
    } else {
      odd_sum += at / n;
    }
    const double below = (2.0 * n / z) * at - above;
    above = at;
    at = below;
    if (std::abs(at) > 1e250) {  // keep the unnormalized values in range
      constexpr double kRescale = 1e-250;
      at *= kRescale;
      above *= kRescale;
      norm *= kRescale;
      odd_sum *= kRescale;
      even_sum *= kRescale;
    }
  }
  norm += at;  // J_0
  const double slope = (at + 2.0 * even_sum) / norm;
  return {2.0 * odd_sum / norm, slope, 1.0 - slope};
}

/// The sum of an asymptotic series from its first term, each next term `next(term, k)` for
/// k = 1, 2, ..., while the terms shrink and are above 1e-17.
template <class Next>
double asymptotic_sum(double first, Next next) {
  double term = first;
  double sum = first;
  for (int k = 1; k < 64; ++k) {
    const double following = next(term, k);
    if (std::abs(following) >= std::abs(term) || std::abs(following) < 1e-17) break;
    term = following;
    sum += term;
  }
  return sum;
}

/// Large z: I = (pi/2) H_0 and I' = 1 - (pi/2) H_1 with the Struve functions' asymptotic
/// expansions (Abramowitz and Stegun 12.1.31):
///   H_0 - Y_0 ~ (2/pi) sum_k>=0 (-1)^k ((2k-1)!!)^2 / z^(2k+1),
///   H_1 - Y_1 ~ (2/pi) (1 + sum_k>=1 (-1)^(k+1) (2k-1)!! (2k-3)!! / z^(2k)),
/// so I = (pi/2) Y_0 + S_0 with S_0 = 1/z - 1/z^3 + 9/z^5 - ..., and I' = -(pi/2) Y_1 + S_1
/// with S_1 = -1/z^2 + 3/z^4 - 45/z^6 + .... The terms shrink while 2k < z: from z = 32 the
/// smallest is below 1e-15.
RippleIntegrals asymptotic(double z) {
  const double w = 1.0 / (z * z);
  const double value_tail = asymptotic_sum(1.0 / z, [w](double term, int k) {
    const double odd = 2.0 * k - 1.0;
    return -term * odd * odd * w;
  });
  const double slope_tail = asymptotic_sum(
      -w, [w](double term, int k) { return -term * (2.0 * k + 1.0) * (2.0 * k - 1.0) * w; });
  const double half_pi = 0.5 * std::numbers::pi;
  // The C library's Y_0 and Y_1 in double (POSIX y0, y1): Boost's, promoted to long double,
  // cost ten times as much, and the disk check of a rippled contact asks millions of times.
  const double slope = -half_pi * ::y1(z) + slope_tail;
  return {half_pi * ::y0(z) + value_tail, slope, 1.0 - slope};
}

}  // namespace

RippleIntegrals ripple_integrals(double z) {
  // A contact state asks g(a), g'(a) and the force at one a, each the ripple integrals at one z
  // (a Bessel sum of up to 130 steps): the last z's are kept, per thread.
  thread_local double last_z = std::numeric_limits<double>::quiet_NaN();
  thread_local RippleIntegrals last{};
  if (z == last_z) return last;
  last = z < kSeriesBelow ? by_series(z) : z < kAsymptoticFrom ? by_bessel_sums(z) : asymptotic(z);
  last_z = z;
  return last;
}

}  // namespace mdrsim
