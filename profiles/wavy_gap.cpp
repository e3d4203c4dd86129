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

/// Gauss-Legendre rules in the angle psi (add_layer): on the layer's panel, on those doubling
/// from it, and on the ripple's first half wave below a where the layer is wider than it.
using LayerRule = boost::math::quadrature::gauss<double, 12>;
using AngleRule = boost::math::quadrature::gauss<double, 10>;
using WholeRule = boost::math::quadrature::gauss<double, 14>;
/// In the radius: 12 points on up to one wavelength, 16 on up to two (the sine's integral over
/// them to 1e-15).
using OneWaveRule = boost::math::quadrature::gauss<double, 12>;
using TwoWaveRule = boost::math::quadrature::gauss<double, 16>;

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

/// int (f'(a cos psi) - f'(a)) (B, dB/dt) dpsi over [lo, hi] by the rule, with f' =
/// sin(k r) and sin(ka cos psi) - sin(ka) = -2 cos(ka (1 + cos psi)/2) sin(ka sin^2(psi)/(2 (1 +
/// cos psi))), exact where psi is small (in the layer it is O(psi^2) and B O(1)).
template <class Rule>
void add_angle_panel(const ZoneAngle& z, double ka, double lo, double hi, RippleSums& sums) {
  const auto& nodes = Rule::abscissa();
  const auto& weights = Rule::weights();
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double sin_mid = std::sin(mid), cos_mid = std::cos(mid);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    // sin and cos at mid -+ u from theirs at mid and u: six sincos a panel instead of ten; on
    // the panel from 0 directly (there sin(mid - u) << sin(mid) would lose digits).
    const double u = half * nodes[i];
    const double sin_u = std::sin(u), cos_u = std::cos(u);
    for (const double side : {-1.0, 1.0}) {
      const double s =
          lo > 0.0 ? sin_mid * cos_u + side * cos_mid * sin_u : std::sin(mid + side * u);
      const double p =
          lo > 0.0 ? cos_mid * cos_u - side * sin_mid * sin_u : std::cos(mid + side * u);
      const double ripple = z.less_edge_slope ? -2.0 * std::cos(0.5 * ka * (1.0 + p)) *
                                                    std::sin(0.5 * ka * s * s / (1.0 + p))
                                              : std::sin(ka * p);
      const ZoneWeight w = zone_weight(z, s, p);
      sums.value += half * weights[i] * ripple * w.value;
      sums.slope += half * weights[i] * ripple * w.slope;
    }
  }
}

/// The same over psi in [0, end]. The weight's singularities lie at sin(psi) = +-i T (its layer
/// at psi = 0): where T < end, a panel [0, asinh T] reaches them at its own scale, and panels
/// doubling from it stay as far from them (Bernstein ellipses of rho >= 4.6 and 5.8). Where T
/// >= end one panel of 14 points: one of 10 over the ripple's half wave met its growth off the
/// real axis (exp(ka sin(psi) sinh(y))) with an error of 1e-12 at ka = 5.
void add_layer(const ZoneAngle& z, double ka, double end, RippleSums& sums) {
  if (z.tangent >= end) {
    add_angle_panel<WholeRule>(z, ka, 0.0, end, sums);
    return;
  }
  const double first = std::asinh(z.tangent);
  add_angle_panel<LayerRule>(z, ka, 0.0, first, sums);
  for (double lo = first; lo < end;) {
    const double hi = std::min(end, 2.0 * lo);
    add_angle_panel<AngleRule>(z, ka, lo, hi, sums);
    lo = hi;
  }
}

/// In r = a cos(psi) over [lo, hi] (below a - pi/k): a f'(r) (B, dB/dt) dpsi = f'(r) (B, dB/dt)
/// dr / q with q = sin(psi) = sqrt(1 - (r/a)^2); ripple(i, side, r) gives f'(r) (less f'(a)
/// below kSubtractBelow) / (A k) at node i's side (0: below mid, 1: above) at r.
template <class WaveRule, class Ripple>
void add_radius_panel(const ZoneAngle& z, double a, double lo, double hi, Ripple ripple,
                      RippleSums& sums) {
  const auto& nodes = WaveRule::abscissa();
  const auto& weights = WaveRule::weights();
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int side = 0; side < 2; ++side) {
      const double r = side == 0 ? mid - half * nodes[i] : mid + half * nodes[i];
      const double p = r / a;
      const double q = std::sqrt((1.0 - p) * (1.0 + p));
      const ZoneWeight w = zone_weight(z, q, p);
      const double f = ripple(i, side, r) * half * weights[i] / (q * a);
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
    // Below a - pi/k, two waves a panel, each panel's ends from a (not summed panel by panel),
    // so that its nodes' phases are those of the sines kept: with w = 2 pi/k, on [a - (m + 2.5)
    // w, a - (m + 0.5) w], m = 0, 2, 4, ..., k r = k a - (2 m + 3) pi + 2 pi x at the rule's
    // nodes x, and sin(k r) = -sin(k a + 2 pi x).
    const double wave = 2.0 * kRipplePi / k;
    int done = 0;  // waves below a - w/2
    if (a - 2.5 * wave > 0.0) {
      const auto& nodes = TwoWaveRule::abscissa();
      std::array<std::array<double, 2>, 8> sines{};  // at x = -+ node, less the offset
      for (std::size_t i = 0; i < nodes.size(); ++i) {
        const double u = 2.0 * kRipplePi * nodes[i];
        const double cu = std::cos(u), su = std::sin(u);
        sines[i][0] = -(sin_ka * cu - cos_ka * su) - offset;
        sines[i][1] = -(sin_ka * cu + cos_ka * su) - offset;
      }
      for (; a - (done + 2.5) * wave > 0.0; done += 2) {
        add_radius_panel<TwoWaveRule>(
            z, a, a - (done + 2.5) * wave, a - (done + 0.5) * wave,
            [&](std::size_t i, int side, double /*r*/) { return sines[i][side]; }, radius_sums);
      }
    }
    const double rest = a - (done + 0.5) * wave;  // less than two waves, down to the axis
    if (rest > 0.0) {
      const auto direct = [&](std::size_t, int, double r) { return std::sin(k * r) - offset; };
      if (rest <= wave) {
        add_radius_panel<OneWaveRule>(z, a, 0.0, rest, direct, radius_sums);
      } else {
        add_radius_panel<TwoWaveRule>(z, a, 0.0, rest, direct, radius_sums);
      }
    }
  }
  const double scale = amplitude * k * a;
  return {.integral = edge + scale * (angle_sums.value + radius_sums.value),
          .angle_slope = edge_slope + scale * (angle_sums.slope + radius_sums.slope)};
}

}  // namespace mdrsim
