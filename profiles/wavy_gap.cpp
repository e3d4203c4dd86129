// The wavy ripple's Dugdale gap integral: an elementary weight on half-wave Gauss panels.
#include "profiles/wavy_gap.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>

#include "engine/base/angle_series.hpp"

namespace mdrsim {
namespace {

constexpr double kRipplePi = std::numbers::pi;
/// Below this zone angle f'(a) is taken out of the integrand (wavy_ripple_gap).
constexpr double kSubtractBelow = 0.3;

/// The 10-point Gauss-Legendre rule on [-1, 1]: its positive abscissae and their weights (the
/// angle's panels).
using AngleRule = boost::math::quadrature::gauss<double, 10>;
const auto& kAngleNodes = AngleRule::abscissa();
const auto& kAngleWeights = AngleRule::weights();
/// The 12-point rule (the radius's panels, one wavelength each).
using RippleWaveRule = boost::math::quadrature::gauss<double, 12>;
const auto& kWaveNodes = RippleWaveRule::abscissa();
const auto& kWaveWeights = RippleWaveRule::weights();

/// G(x) = 1 - arctan(x)/x = sum_(n>=1) (-1)^(n+1) x^(2n)/(2n+1), by the series up to x = 1/2
/// (the difference would keep only the digits of x^2/3).
double arctan_deficit(double x) {
  if (x > 0.5) return 1.0 - std::atan(x) / x;
  const double w = x * x;
  double sum = 0.0, power = 1.0;
  for (int n = 1; n < 60; ++n) {
    power *= -w;
    const double term = -power / (2.0 * n + 1.0);
    sum += term;
    if (std::abs(term) <= 1e-17 * sum) break;
  }
  return sum;
}

/// delta - sin(delta), by its series below delta = 1 (terms to delta^19, the next below 1e-17 of
/// the sum there), where the difference would cancel.
double angle_minus_sine(double delta) {
  if (std::abs(delta) >= 1.0) return delta - std::sin(delta);
  const double d2 = delta * delta;
  double term = delta, sum = 0.0;
  for (int n = 1; n <= 9; ++n) {
    term *= -d2 / ((2.0 * n) * (2.0 * n + 1.0));
    sum -= term;
  }
  return sum;
}

/// The zone's weight B and its slope dB/dt at sin(psi) = s, cos(psi) = p (both given: each is
/// exact where the other is near 1).
struct ZoneWeight {
  double value;  ///< B [rad]
  double slope;  ///< dB/dt [1]
};

/// The angle t's parts the weights share.
struct ZoneAngle {
  double angle;          ///< t
  double tangent;        ///< T = tan t
  double deficit;        ///< G(T), where T <= 1/2
  bool less_edge_slope;  ///< whether the integrand is f'(a cos psi) - f'(a), or f'(a cos psi)
};

/// B = T (F(X) - F(T)) with F(x) = arctan(x)/x and X = T/s >= T: where X <= 1/2 the difference
/// of F, O(T^2) of F, is summed as its series' divided difference (X^2 - T^2 = T^2 p^2/s^2
/// times sum_(n>=1) (-1)^n (X^2n - T^2n)/((X^2 - T^2)(2n+1))); beyond, where T <= 1/2, as
/// G(T) - G(X) (G(X) >= G(1/2) = 0.07); otherwise as s arctan(X) - t.
ZoneWeight zone_weight(const ZoneAngle& z, double s, double p) {
  const double t2 = z.tangent * z.tangent;
  const double slope = -t2 * p * p / (s * s + t2);
  const double x = z.tangent / s;
  if (x <= 0.5) {
    const double w1 = x * x;
    double sum = 0.0, spread = 1.0, power2 = 1.0;  // e_n = sum_j w1^j t2^(n-1-j); t2^(n-1)
    for (int n = 1; n < 80; ++n) {
      const double term = spread / (2.0 * n + 1.0);
      sum += (n % 2 == 1) ? -term : term;
      if (term <= 1e-17 * std::abs(sum)) break;
      power2 *= t2;
      spread = w1 * spread + power2;
    }
    return {z.tangent * (t2 * p * p / (s * s)) * sum, slope};
  }
  if (z.tangent <= 0.5) return {z.tangent * (z.deficit - arctan_deficit(x)), slope};
  return {s * std::atan(x) - z.angle, slope};
}

/// Sums of the integrand's value and slope.
struct RippleSums {
  double value = 0.0;
  double slope = 0.0;
};

/// int (f'(a cos psi) - f'(a)) (B, dB/dt) dpsi over [lo, hi] by the 10-point rule, with f' =
/// sin(k r) and sin(ka cos psi) - sin(ka) = -2 cos(ka (1 + cos psi)/2) sin(ka sin^2(psi)/(2 (1 +
/// cos psi))), exact where psi is small (in the layer it is O(psi^2) and B O(1)).
void add_angle_panel(const ZoneAngle& z, double ka, double lo, double hi, RippleSums& sums) {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (std::size_t i = 0; i < kAngleNodes.size(); ++i) {
    for (const double psi : {mid - half * kAngleNodes[i], mid + half * kAngleNodes[i]}) {
      const double s = std::sin(psi), p = std::cos(psi);
      const double ripple = z.less_edge_slope ? -2.0 * std::cos(0.5 * ka * (1.0 + p)) *
                                                    std::sin(0.5 * ka * s * s / (1.0 + p))
                                              : std::sin(ka * p);
      const ZoneWeight w = zone_weight(z, s, p);
      sums.value += half * kAngleWeights[i] * ripple * w.value;
      sums.slope += half * kAngleWeights[i] * ripple * w.slope;
    }
  }
}

/// The same over psi in [0, end]: panels doubling from min(T, end)/2, so that the weight's layer
/// at psi = 0 (its singularities at sin(psi) = +-i T) is resolved at its own scale, and that no
/// panel spans the ripple's whole half wave (its growth off the real axis, exp(ka sin(psi)
/// sinh(y)), held one panel over [0, end] to 1e-12).
void add_layer(const ZoneAngle& z, double ka, double end, RippleSums& sums) {
  const double first = 0.5 * std::min(z.tangent, end);
  add_angle_panel(z, ka, 0.0, first, sums);
  for (double lo = first; lo < end;) {
    const double hi = std::min(end, 2.0 * lo);
    add_angle_panel(z, ka, lo, hi, sums);
    lo = hi;
  }
}

/// In r = a cos(psi) over [lo, hi] (below a - pi/k): a f'(r) (B, dB/dt) dpsi = f'(r) (B, dB/dt)
/// dr / q with q = sin(psi) = sqrt(1 - (r/a)^2); ripple(i, side) gives sin(k r) - sin(k a) at
/// the nodes.
template <class Ripple>
void add_radius_panel(const ZoneAngle& z, double a, double lo, double hi, Ripple ripple,
                      RippleSums& sums) {
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (std::size_t i = 0; i < kWaveNodes.size(); ++i) {
    for (int side = 0; side < 2; ++side) {
      const double r = side == 0 ? mid - half * kWaveNodes[i] : mid + half * kWaveNodes[i];
      const double p = r / a;
      const double q = std::sqrt((1.0 - p) * (1.0 + p));
      const ZoneWeight w = zone_weight(z, q, p);
      const double f = ripple(i, side) * half * kWaveWeights[i] / (q * a);
      sums.value += f * w.value;
      sums.slope += f * w.slope;
    }
  }
}

}  // namespace

DugdaleGap wavy_ripple_gap(double amplitude, double wavenumber, double a, double c, double t) {
  const double k = wavenumber;
  const double tangent = std::tan(t);
  const double kc = k * c;
  if (!(a > 0.0)) {
    // J = (pi/2) f(c), dJ/dt = (pi/2) f'(c) c tan t.
    const double half_kc = std::sin(0.5 * kc);
    return {.integral = kRipplePi * amplitude * half_kc * half_kc,
            .angle_slope = 0.5 * kRipplePi * amplitude * k * std::sin(kc) * c * tangent};
  }
  // In a thin zone J is O(t^3) and its parts (pi/2) (f(c) - f(a)) and a int f'(a cos psi) B dpsi
  // are O(t^2) each: below t = kSubtractBelow f'(a) is taken out of the integral, whose weight
  // then integrates in closed form (the cone's J: int_0^(pi/2) B dpsi = (pi/2) (tan t - t - (c -
  // a)/a), and int_0^(pi/2) dB/dt dpsi = (pi/2) (c/a) tan t (sin t - 1)):
  //   J = (pi/2) (f(c) - f(a) - f'(a) (c - a)) + (pi/2) f'(a) a (tan t - t)
  //       + a int_0^(pi/2) (f'(a cos psi) - f'(a)) B dpsi,
  //   dJ/dt = (pi/2) (f'(c) - f'(a)) c tan t + (pi/2) f'(a) c tan t sin t
  //           + a int_0^(pi/2) (f'(a cos psi) - f'(a)) dB/dt dpsi,
  // each part O(t^3) (O(t^2) for dJ/dt). Above, the plain form: f'(a cos psi) oscillates about
  // 0 over many ripples, and f'(a) taken out would be a part far larger than J to cancel again.
  // With delta = k (c - a) and c - a = 2 c sin^2(t/2) (exact where the zone is thin),
  //   f(c) - f(a) - f'(a) (c - a) = A (cos ka (1 - cos delta) - sin ka (delta - sin delta)).
  const double ka = k * a;
  const double cos_ka = std::cos(ka), sin_ka = std::sin(ka);
  const double half_t = std::sin(0.5 * t);
  const double delta = 2.0 * kc * half_t * half_t;
  const double half_delta = std::sin(0.5 * delta);
  const bool less_edge_slope = t < kSubtractBelow;
  const double edge =
      less_edge_slope ? 0.5 * kRipplePi * amplitude *
                            (cos_ka * 2.0 * half_delta * half_delta -
                             sin_ka * angle_minus_sine(delta) + sin_ka * ka * tan_minus_angle(t))
                      : kRipplePi * amplitude * std::sin(0.5 * (ka + kc)) * half_delta;
  const double edge_slope =
      less_edge_slope ? 0.5 * kRipplePi * amplitude * k * c * tangent *
                            (2.0 * std::cos(0.5 * (ka + kc)) * half_delta + sin_ka * std::sin(t))
                      : 0.5 * kRipplePi * amplitude * k * c * tangent * std::sin(kc);
  const double offset = less_edge_slope ? sin_ka : 0.0;

  const ZoneAngle z{.angle = t,
                    .tangent = tangent,
                    .deficit = tangent <= 0.5 ? arctan_deficit(tangent) : 0.0,
                    .less_edge_slope = less_edge_slope};
  RippleSums angle_sums;   // d psi
  RippleSums radius_sums;  // d r / a
  if (ka <= kRipplePi) {
    add_layer(z, ka, 0.5 * kRipplePi, angle_sums);
  } else {
    // r in [a - pi/k, a]: psi in [0, arccos(1 - pi/(k a))], with the layer.
    add_layer(z, ka, 2.0 * std::asin(std::sqrt(0.5 * kRipplePi / ka)), angle_sums);
    // Whole waves [a - (m+2) pi/k, a - m pi/k], m = 1, 3, 5, ...: k r = k a - (m + 1) pi + pi x,
    // sin(k r) = sin(k a + pi x) at the rule's nodes x.
    const double wave = 2.0 * kRipplePi / k;
    std::array<std::array<double, 2>, 6> sines{};  // sin(k a -+ pi node)
    for (std::size_t i = 0; i < kWaveNodes.size(); ++i) {
      const double u = kRipplePi * kWaveNodes[i];
      const double cu = std::cos(u), su = std::sin(u);
      sines[i][0] = sin_ka * cu - cos_ka * su - offset;
      sines[i][1] = sin_ka * cu + cos_ka * su - offset;
    }
    // Each panel's ends from a (not summed wave by wave): their nodes' phases are the sines'.
    int waves = 0;
    while (a - (waves + 1.5) * wave > 0.0) {
      const double hi = a - (waves + 0.5) * wave;
      add_radius_panel(
          z, a, hi - wave, hi, [&](std::size_t i, int side) { return sines[i][side]; },
          radius_sums);
      ++waves;
    }
    const double rest = a - (waves + 0.5) * wave;  // less than a wave, down to the axis
    if (rest > 0.0) {
      add_radius_panel(
          z, a, 0.0, rest,
          [&](std::size_t i, int side) {
            const double r = 0.5 * rest + (side == 0 ? -1.0 : 1.0) * 0.5 * rest * kWaveNodes[i];
            return std::sin(k * r) - offset;
          },
          radius_sums);
    }
  }
  const double scale = amplitude * k * a;
  return {.integral = edge + scale * (angle_sums.value + radius_sums.value),
          .angle_slope = edge_slope + scale * (angle_sums.slope + radius_sums.slope)};
}

}  // namespace mdrsim
