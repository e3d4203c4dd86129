// The ripple integrals of the wavy profile's image, by power series or Bessel sums.
#include "profiles/wavy_image.hpp"

#include <cmath>

namespace mdrsim {
namespace {

/// Below this z the power series converges in a few terms without cancellation.
constexpr double kSeriesBelow = 1.0;

RippleIntegrals by_series(double z) {
  // term_j = (-1)^j z^(2j+1) / ((2j+1)!!)^2; the slope's term is (2j+1) term_j / z.
  double value = 0.0;
  double slope = 0.0;
  double power = 1.0;  // (-1)^j z^(2j) / ((2j+1)!!)^2
  for (int j = 0; j < 40; ++j) {
    const double odd = 2.0 * j + 1.0;
    if (j > 0) power *= -z * z / (odd * odd);
    value += power * z;
    slope += power * odd;
    if (std::abs(power) < 1e-18) break;
  }
  return {value, slope};
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
  return {2.0 * odd_sum / norm, (at + 2.0 * even_sum) / norm};
}

}  // namespace

RippleIntegrals ripple_integrals(double z) {
  return z < kSeriesBelow ? by_series(z) : by_bessel_sums(z);
}

}  // namespace mdrsim
