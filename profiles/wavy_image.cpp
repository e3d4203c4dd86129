// The ripple integrals of the wavy profile's image, by power series or Bessel sums.
#include "profiles/wavy_image.hpp"

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <numbers>

namespace mdrsim {
namespace {

/// Below this z the power series converges in a few terms without cancellation.
constexpr double kSeriesBelow = 1.0;
/// From this z on, Y_0, Y_1 and the asymptotic series (below): Miller's recurrence costs z steps
/// per call, and a ripple of 2e-9 m in a contact of 5e-4 m (z = 1.6e6) made a preload's
/// quadrature take minutes (a fuzzer's input).
constexpr double kAsymptoticFrom = 100.0;

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

/// Large z: I = (pi/2) H_0 and I' = 1 - (pi/2) H_1 with the Struve functions' expansions
/// (Abramowitz and Stegun 12.1.31), H_0 - Y_0 ~ (2/pi) (1/z - 1/z^3 + 9/z^5 - 225/z^7 + ...) and
/// H_1 - Y_1 ~ (2/pi) (1 + 1/z^2 - 3/z^4 + 45/z^6 - 1575/z^8 + ...):
///   I = (pi/2) Y_0 + 1/z - 1/z^3 + 9/z^5 - 225/z^7 + 11025/z^9,
///   I' = -(pi/2) Y_1 - 1/z^2 + 3/z^4 - 45/z^6 + 1575/z^8;
/// at z = 100 the first terms left out are 893025/z^11 and 99225/z^10, below 1e-15.
RippleIntegrals asymptotic(double z) {
  const double w = 1.0 / (z * z);
  const double tail = (1.0 / z) * (1.0 + w * (-1.0 + w * (9.0 + w * (-225.0 + w * 11025.0))));
  const double tail_slope = w * (-1.0 + w * (3.0 + w * (-45.0 + w * 1575.0)));
  const double half_pi = 0.5 * std::numbers::pi;
  return {half_pi * boost::math::cyl_neumann(0, z) + tail,
          -half_pi * boost::math::cyl_neumann(1, z) + tail_slope};
}

}  // namespace

RippleIntegrals ripple_integrals(double z) {
  if (z < kSeriesBelow) return by_series(z);
  return z < kAsymptoticFrom ? by_bessel_sums(z) : asymptotic(z);
}

}  // namespace mdrsim
