// The wavy ripple's Dugdale gap integral: an elementary weight on fixed Gauss rules over (0, a).
#include "profiles/wavy_gap.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "engine/base/angle_series.hpp"

namespace mdrsim {
namespace {

constexpr double kRipplePi = std::numbers::pi;
/// Below this zone angle f'(a) is taken out of the integrand (wavy_ripple_gap).
constexpr double kSubtractBelow = 0.3;

/// Gauss-Legendre rules in the angle psi (add_layer_nodes): on the layer's panel, those doubling
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
  double angle;    ///< t
  double tangent;  ///< T = tan t
  double deficit;  ///< G(T), where T <= 1/2
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

/// A node of the rules over (0, a): sin(psi) and cos(psi) there, and its weight times f'(a cos
/// psi) / (A k) (less f'(a) below kSubtractBelow), times 1/(a sin psi) on the radius's panels
/// (a dpsi = dr / sin psi).
struct RippleNode {
  double s;
  double p;
  double factor;
};

/// The nodes of the rule over [lo, hi] in psi, with sin(ka cos psi) - sin(ka) = -2 cos(ka (1 +
/// cos psi)/2) sin(ka sin^2(psi)/(2 (1 + cos psi))), exact where psi is small (in the layer it
/// is O(psi^2) and B O(1)).
template <class Rule>
void add_angle_nodes(double ka, bool less_edge_slope, double lo, double hi,
                     std::vector<RippleNode>& out) {
  const auto& nodes = Rule::abscissa();
  const auto& weights = Rule::weights();
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double sin_mid = std::sin(mid), cos_mid = std::cos(mid);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    // sin and cos at mid -+ u from theirs at mid and u: one sincos a pair of nodes. Near psi =
    // 0 sin(psi) keeps eps mid absolute, not relative, which moves B by (pi/2) eps mid at most.
    const double u = half * nodes[i];
    const double sin_u = std::sin(u), cos_u = std::cos(u);
    for (const double side : {-1.0, 1.0}) {
      const double s = sin_mid * cos_u + side * cos_mid * sin_u;
      const double p = cos_mid * cos_u - side * sin_mid * sin_u;
      const double ripple = less_edge_slope ? -2.0 * std::cos(0.5 * ka * (1.0 + p)) *
                                                  std::sin(0.5 * ka * s * s / (1.0 + p))
                                            : std::sin(ka * p);
      out.push_back({.s = s, .p = p, .factor = half * weights[i] * ripple});
    }
  }
}

/// The same over psi in [0, end]. The weight's singularities lie at sin(psi) = +-i T (its layer
/// at psi = 0): where T < end (first = asinh T), a panel [0, first] reaches them at its own
/// scale, and panels doubling from it stay as far from them (Bernstein ellipses of rho >= 4.6
/// and 5.8). Where T >= end (first < 0) one panel of 14 points: one of 10 over the ripple's
/// half wave met its growth off the real axis (exp(ka sin(psi) sinh(y))) with an error of 1e-12
/// at ka = 5.
void add_layer_nodes(double ka, bool less_edge_slope, double first, double end,
                     std::vector<RippleNode>& out) {
  if (!(first > 0.0)) {
    add_angle_nodes<WholeRule>(ka, less_edge_slope, 0.0, end, out);
    return;
  }
  add_angle_nodes<LayerRule>(ka, less_edge_slope, 0.0, first, out);
  for (double lo = first; lo < end;) {
    const double hi = std::min(end, 2.0 * lo);
    add_angle_nodes<AngleRule>(ka, less_edge_slope, lo, hi, out);
    lo = hi;
  }
}

/// The nodes of the rule over [lo, hi] in r = a cos(psi) (below a - pi/k), with ripple[i][side]
/// f'(r) / (A k) (less f'(a) below kSubtractBelow) at node i's side (0: below the middle, 1:
/// above).
template <class WaveRule>
void add_radius_nodes(double a, double lo, double hi,
                      const std::array<std::array<double, 2>, 8>& ripple,
                      std::vector<RippleNode>& out) {
  const auto& nodes = WaveRule::abscissa();
  const auto& weights = WaveRule::weights();
  const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int side = 0; side < 2; ++side) {
      const double r = side == 0 ? mid - half * nodes[i] : mid + half * nodes[i];
      const double p = r / a;
      const double q = std::sqrt((1.0 - p) * (1.0 + p));
      out.push_back({.s = q, .p = p, .factor = ripple[i][side] * half * weights[i] / (q * a)});
    }
  }
}

/// All nodes over (0, a) for k a and a, f'(a) taken out or not, and the layer's first panel
/// (first < 0: none).
void build_ripple_nodes(double k, double a, bool less_edge_slope, double first,
                        std::vector<RippleNode>& out) {
  out.clear();
  const double ka = k * a;
  if (ka <= kRipplePi) {
    add_layer_nodes(ka, less_edge_slope, first, 0.5 * kRipplePi, out);
    return;
  }
  // r in [a - pi/k, a]: psi in [0, arccos(1 - pi/(k a))], with the layer.
  add_layer_nodes(ka, less_edge_slope, first, 2.0 * std::asin(std::sqrt(0.5 * kRipplePi / ka)),
                  out);
  // Below a - pi/k, two waves a panel, each panel's ends from a (not summed panel by panel), so
  // that its nodes' phases are those of the sines kept: with w = 2 pi/k, on [a - (m + 2.5) w, a -
  // (m + 0.5) w], m = 0, 2, 4, ..., k r = k a - (2 m + 3) pi + 2 pi x at the rule's nodes x, and
  // sin(k r) = -sin(k a + 2 pi x).
  const double wave = 2.0 * kRipplePi / k;
  const double sin_ka = std::sin(ka), cos_ka = std::cos(ka);
  const double offset = less_edge_slope ? sin_ka : 0.0;
  // sin(k r) - offset at a panel's nodes mid -+ half x_i from sin and cos of k mid: one sincos a
  // pair of nodes.
  const auto node_sines = [offset](const auto& nodes, double sin_mid, double cos_mid,
                                   double k_half) {
    std::array<std::array<double, 2>, 8> sines{};  // [i][0] at x = -node, [i][1] at +node
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const double u = k_half * nodes[i];
      const double cu = std::cos(u), su = std::sin(u);
      sines[i][0] = sin_mid * cu - cos_mid * su - offset;
      sines[i][1] = sin_mid * cu + cos_mid * su - offset;
    }
    return sines;
  };
  int done = 0;  // waves below a - w/2
  if (a - 2.5 * wave > 0.0) {
    const auto sines = node_sines(TwoWaveRule::abscissa(), -sin_ka, -cos_ka, 2.0 * kRipplePi);
    for (; a - (done + 2.5) * wave > 0.0; done += 2) {
      add_radius_nodes<TwoWaveRule>(a, a - (done + 2.5) * wave, a - (done + 0.5) * wave, sines,
                                    out);
    }
  }
  const double rest = a - (done + 0.5) * wave;  // less than two waves, down to the axis
  if (rest > 0.0) {
    const double k_half = 0.5 * k * rest;
    const double sin_mid = std::sin(k_half), cos_mid = std::cos(k_half);
    if (rest <= wave) {
      add_radius_nodes<OneWaveRule>(
          a, 0.0, rest, node_sines(OneWaveRule::abscissa(), sin_mid, cos_mid, k_half), out);
    } else {
      add_radius_nodes<TwoWaveRule>(
          a, 0.0, rest, node_sines(TwoWaveRule::abscissa(), sin_mid, cos_mid, k_half), out);
    }
  }
}

/// The nodes of the last (k, a, form, layer) asked on this thread: a zone's Newton steps ask J
/// at one contact radius for several angles, and the nodes depend on the angle only through the
/// form and the layer's panel, which a wide layer (tan t past the first half wave) leaves out.
const std::vector<RippleNode>& ripple_nodes(double k, double a, bool less_edge_slope,
                                            double first) {
  struct Kept {
    double k = std::numeric_limits<double>::quiet_NaN();
    double a = 0.0;
    bool less_edge_slope = false;
    double first = 0.0;
    std::vector<RippleNode> nodes;
  };
  thread_local Kept kept;
  if (!(k == kept.k && a == kept.a && less_edge_slope == kept.less_edge_slope &&
        first == kept.first)) {
    build_ripple_nodes(k, a, less_edge_slope, first, kept.nodes);
    kept = {.k = k,
            .a = a,
            .less_edge_slope = less_edge_slope,
            .first = first,
            .nodes = std::move(kept.nodes)};
  }
  return kept.nodes;
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

  const ZoneAngle z{
      .angle = t, .tangent = tangent, .deficit = tangent <= 0.5 ? arctan_deficit(tangent) : 0.0};
  // The layer's first panel, where tan t is below the first half wave's angle.
  const double end =
      ka <= kRipplePi ? 0.5 * kRipplePi : 2.0 * std::asin(std::sqrt(0.5 * kRipplePi / ka));
  const double first = tangent < end ? std::asinh(tangent) : -1.0;
  double value = 0.0, slope = 0.0;
  for (const RippleNode& node : ripple_nodes(k, a, less_edge_slope, first)) {
    const ZoneWeight w = zone_weight(z, node.s, node.p);
    value += node.factor * w.value;
    slope += node.factor * w.slope;
  }
  const double scale = amplitude * k * a;
  return {.integral = edge + scale * value, .angle_slope = edge_slope + scale * slope};
}

}  // namespace mdrsim
