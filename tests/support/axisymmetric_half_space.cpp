// The ring boundary-element half-space of axisymmetric_half_space.hpp: its quadrature rules, the
// collocation system and the quantities read from its solution.
#include "tests/support/axisymmetric_half_space.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace mdrsim::test {
namespace {

constexpr double kPi = std::numbers::pi;

/// Gauss-Legendre points and weights on [-1, 1] (Newton on P_n from Chebyshev's guess).
struct GaussRule {
  std::vector<double> x, w;
};

GaussRule gauss_legendre(int n) {
  GaussRule rule{std::vector<double>(n), std::vector<double>(n)};
  for (int i = 0; i < n; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.x[n - 1 - i] = x;
    rule.w[n - 1 - i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return rule;
}

/// The rule for pieces at least their own length away from the singular point: the log there
/// lies outside the Bernstein ellipse rho = 3 + sqrt(8), so 12 points leave rho^-24 ~ 5e-19.
const GaussRule& piece_rule() {
  static const GaussRule rule = gauss_legendre(12);
  return rule;
}

/// tanh-sinh on (0, 1) from a log-singular end at 0: delta = 1 / (1 + exp(-2u)),
/// u = (pi/2) sinh(t), t = k h. With h = 1/8 and |t| <= 3.25 the nodes reach 1e-17 of the
/// end; the error exp(-pi^2 / (2h)) ~ 7e-18 for an integrand analytic in the strip.
struct TanhSinhRule {
  std::vector<double> delta, weight;
};

const TanhSinhRule& tanh_sinh_rule() {
  static const TanhSinhRule rule = [] {
    TanhSinhRule r;
    const double h = 0.125;
    for (int k = -26; k <= 26; ++k) {
      const double t = k * h;
      const double u = 0.5 * kPi * std::sinh(t);
      const double delta = 1.0 / (1.0 + std::exp(-2.0 * u));
      const double sech = 1.0 / std::cosh(u);
      const double weight = h * 0.25 * kPi * std::cosh(t) * sech * sech;
      if (delta > 0.0 && weight > 0.0) {
        r.delta.push_back(delta);
        r.weight.push_back(weight);
      }
    }
    return r;
  }();
  return rule;
}

/// Visits the nodes of a rule for int_lo^hi g(t) dt whose g is log-singular at t = x:
/// visit(t, t - x, weight), with t - x exact near x. Inside (lo, hi), tanh-sinh from x to each
/// end; outside, Gauss-Legendre on pieces [D, 2D] of distance from x, each as long as it is far.
template <class Visit>
void for_each_node(double lo, double hi, double x, Visit&& visit) {
  if (!(hi > lo)) return;
  const auto from_point = [&](double length, double direction) {
    const TanhSinhRule& rule = tanh_sinh_rule();
    for (std::size_t k = 0; k < rule.delta.size(); ++k) {
      const double offset = direction * length * rule.delta[k];
      visit(x + offset, offset, length * rule.weight[k]);
    }
  };
  const auto piece = [&](double from, double to) {
    const GaussRule& rule = piece_rule();
    const double mid = 0.5 * (from + to), half = 0.5 * (to - from);
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      const double t = mid + half * rule.x[k];
      visit(t, t - x, half * rule.w[k]);
    }
  };
  if (x > lo && x < hi) {
    from_point(x - lo, -1.0);
    from_point(hi - x, 1.0);
    return;
  }
  const double direction = x <= lo ? 1.0 : -1.0;
  const double near = x <= lo ? lo - x : x - hi;
  const double far = near + (hi - lo);
  if (near == 0.0) {
    from_point(hi - lo, direction);
    return;
  }
  for (double from = near; from < far;) {
    const double to = std::min(2.0 * from, far);
    const double one = x + direction * from, other = x + direction * to;
    piece(std::min(one, other), std::max(one, other));
    from = to;
  }
}

/// The Lagrange polynomial of point j of `nodes` at xi.
double lagrange(const std::vector<double>& nodes, std::size_t j, double xi) {
  double value = 1.0;
  for (std::size_t m = 0; m < nodes.size(); ++m) {
    if (m != j) value *= (xi - nodes[m]) / (nodes[j] - nodes[m]);
  }
  return value;
}

}  // namespace

double elliptic_k_of_complement(double complementary_modulus) {
  double a = 1.0, b = complementary_modulus;
  while (std::abs(a - b) > 4.0 * std::numeric_limits<double>::epsilon() * a) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return 0.5 * kPi / a;
}

double ring_kernel(double r, double s, double offset) {
  if (s <= 0.0) return 0.0;
  const double complement = std::abs(offset) / (r + s);
  // At the singular point itself (k' = 0) the rules give the node a weight below 1e-17 of
  // the piece: its value, ln(4/k'), adds nothing there.
  if (complement == 0.0) return 0.0;
  return s / (r + s) * elliptic_k_of_complement(complement);
}

double annulus_displacement(double effective_modulus, double pressure, double inner, double outer,
                            double r) {
  double sum = 0.0;
  for_each_node(inner, outer, r, [&](double s, double offset, double weight) {
    sum += weight * ring_kernel(r, s, offset);
  });
  return 4.0 / (kPi * effective_modulus) * pressure * sum;
}

DugdaleHalfSpace::DugdaleHalfSpace(DugdaleHalfSpaceProblem problem, RingMesh mesh)
    : problem_(std::move(problem)), mesh_(mesh), nodes_(gauss_legendre(mesh.points).x) {
  const int n = mesh_.elements, p = mesh_.points, size = n * p;
  Eigen::MatrixXd matrix(size, size);
  Eigen::VectorXd rhs(size);
  for (int i = 0; i < size; ++i) {
    const double tau_i = (i / p + 0.5 * (1.0 + nodes_[i % p])) / n;
    const double r_i = problem_.contact_radius * std::sin(phi_of_tau(tau_i));
    // (pi E*/4) u = sum of the rings' integrals: the unknowns' plus the zone's, which is known.
    rhs(i) =
        0.25 * kPi * problem_.effective_modulus * (problem_.indentation - problem_.shape(r_i)) -
        zone_part(r_i);
    for (int f = 0; f < n; ++f) {
      const std::vector<double> moments = element_moments(f, r_i, tau_i);
      for (int m = 0; m < p; ++m) matrix(i, f * p + m) = moments[m];
    }
  }
  const Eigen::VectorXd solution = matrix.partialPivLu().solve(rhs);
  w_.assign(solution.data(), solution.data() + size);
}

double DugdaleHalfSpace::phi_of_tau(double tau) const {
  const int q = mesh_.grading;
  const double up = std::pow(tau, q), down = std::pow(1.0 - tau, q);
  return 0.5 * kPi * up / (up + down);
}

double DugdaleHalfSpace::phi_slope(double tau) const {
  const int q = mesh_.grading;
  const double up = std::pow(tau, q), down = std::pow(1.0 - tau, q), sum = up + down;
  return 0.5 * kPi * q * std::pow(tau * (1.0 - tau), q - 1) / (sum * sum);
}

double DugdaleHalfSpace::phi_difference(double tau, double sigma, double difference) const {
  // G(tau) - G(sigma) = ((tau (1 - sigma))^q - (sigma (1 - tau))^q) / (D(tau) D(sigma)), whose
  // bases differ by tau - sigma: the difference of powers as that times their sum.
  const int q = mesh_.grading;
  const double x = tau * (1.0 - sigma), y = sigma * (1.0 - tau);
  double sum = 0.0;
  for (int k = 0; k < q; ++k) sum += std::pow(x, q - 1 - k) * std::pow(y, k);
  const auto d = [q](double t) { return std::pow(t, q) + std::pow(1.0 - t, q); };
  return 0.5 * kPi * difference * sum / (d(tau) * d(sigma));
}

double DugdaleHalfSpace::phi_complement(double tau) const {
  const int q = mesh_.grading;
  const double up = std::pow(tau, q), down = std::pow(1.0 - tau, q);
  return 0.5 * kPi * down / (up + down);
}

double DugdaleHalfSpace::tau_of_radius(double r) const {
  const double g = std::asin(std::min(1.0, r / problem_.contact_radius)) / (0.5 * kPi);
  if (g >= 1.0) return 1.0;
  const double ratio = std::pow(g / (1.0 - g), 1.0 / mesh_.grading);
  return ratio / (1.0 + ratio);
}

double DugdaleHalfSpace::w_at(int e, double xi) const {
  double value = 0.0;
  for (int j = 0; j < mesh_.points; ++j) {
    value += w_[e * mesh_.points + j] * lagrange(nodes_, j, xi);
  }
  return value;
}

std::vector<double> DugdaleHalfSpace::element_moments(int f, double r, double tau_r) const {
  const int n = mesh_.elements;
  const double a = problem_.contact_radius;
  const bool inside = r < a;
  const double complement_r = inside ? phi_complement(tau_r) : 0.0;
  std::vector<double> moments(mesh_.points, 0.0);
  for_each_node(
      double(f) / n, double(f + 1) / n, tau_r, [&](double tau, double offset, double weight) {
        const double phi = phi_of_tau(tau);
        double ds = 0.0;
        if (inside) {
          // s - r = a (sin phi - sin phi_r) = 2a cos((phi + phi_r)/2) sin((phi - phi_r)/2), the
          // cosine as the sine of the complements: exact near phi_r and near pi/2.
          ds = 2.0 * a * std::sin(0.5 * (phi_complement(tau) + complement_r)) *
               std::sin(0.5 * phi_difference(tau, tau_r, offset));
        } else {
          // s - r = -(r - a) - a (1 - sin phi), 1 - sin phi = 2 sin^2((pi/2 - phi)/2).
          const double half = std::sin(0.5 * phi_complement(tau));
          ds = -(r - a) - 2.0 * a * half * half;
        }
        const double g = weight * a * phi_slope(tau) * ring_kernel(r, a * std::sin(phi), ds);
        const double xi = 2.0 * (tau * n - f) - 1.0;
        for (int m = 0; m < mesh_.points; ++m) moments[m] += g * lagrange(nodes_, m, xi);
      });
  return moments;
}

double DugdaleHalfSpace::zone_part(double r) const {
  double sum = 0.0;
  for_each_node(
      problem_.contact_radius, problem_.cohesive_radius, r,
      [&](double s, double offset, double weight) { sum += weight * ring_kernel(r, s, offset); });
  return -problem_.adhesive_stress * sum;
}

double DugdaleHalfSpace::displacement(double r) const {
  const double a = problem_.contact_radius;
  // Outside the contact the singular point has no tau; the near-singularity of s = r at the
  // end tau = 1 lies at a distance in phi of about sqrt(2 (r - a) / a), in tau about that over
  // pi/2 to the power 1/q: the pieces are graded towards it from there.
  const double tau_r =
      r < a ? tau_of_radius(r)
            : 1.0 + std::pow(std::sqrt(2.0 * (r - a) / a) / (0.5 * kPi), 1.0 / mesh_.grading);
  double sum = zone_part(r);
  for (int f = 0; f < mesh_.elements; ++f) {
    const std::vector<double> moments = element_moments(f, r, tau_r);
    for (int m = 0; m < mesh_.points; ++m) sum += w_[f * mesh_.points + m] * moments[m];
  }
  return 4.0 / (kPi * problem_.effective_modulus) * sum;
}

double DugdaleHalfSpace::gap(double r) const {
  return problem_.shape(r) - problem_.indentation + displacement(r);
}

double DugdaleHalfSpace::normal_force() const {
  const int n = mesh_.elements;
  const double a = problem_.contact_radius, c = problem_.cohesive_radius;
  const GaussRule& rule = piece_rule();
  double sum = 0.0;
  for (int f = 0; f < n; ++f) {
    for (std::size_t k = 0; k < rule.x.size(); ++k) {
      const double tau = (f + 0.5 * (1.0 + rule.x[k])) / n;
      sum += 0.5 * rule.w[k] / n * phi_slope(tau) * std::sin(phi_of_tau(tau)) * w_at(f, rule.x[k]);
    }
  }
  // p ds = a w dphi and r = a sin(phi); the zone's stress is uniform.
  return 2.0 * kPi * a * a * sum - kPi * problem_.adhesive_stress * (c * c - a * a);
}

double DugdaleHalfSpace::stress_intensity() const {
  return -w_at(mesh_.elements - 1, 1.0) * std::sqrt(kPi * problem_.contact_radius);
}

double DugdaleHalfSpace::pressure(double r) const {
  const double a = problem_.contact_radius;
  if (r >= problem_.cohesive_radius) return 0.0;
  if (r >= a) return -problem_.adhesive_stress;
  const double tau = tau_of_radius(r);
  const int e = std::min(int(tau * mesh_.elements), mesh_.elements - 1);
  return w_at(e, 2.0 * (tau * mesh_.elements - e) - 1.0) / std::cos(phi_of_tau(tau));
}

Richardson richardson(const std::vector<double>& values) {
  if (values.size() < 3) throw std::invalid_argument("richardson: needs three meshes");
  const double v0 = values[values.size() - 3], v1 = values[values.size() - 2], v2 = values.back();
  const double ratio = (v1 - v0) / (v2 - v1);
  // Changes that do not shrink (rounding): no order, the last value stands.
  if (!std::isfinite(ratio) || std::abs(ratio) <= 1.0) return {.value = v2, .order = 0.0};
  return {.value = v2 + (v2 - v1) / (ratio - 1.0), .order = std::log2(std::abs(ratio))};
}

}  // namespace mdrsim::test
