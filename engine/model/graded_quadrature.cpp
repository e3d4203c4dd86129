// Gauss-Jacobi and Gauss-Legendre pieces of the graded image's integrals, and the shapes'
// slopes they integrate.
#include "engine/model/graded_quadrature.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "profiles/shape_preserving_cubic.hpp"

namespace mdrsim {
namespace {

constexpr int kGradedNodes = 20;

class SphereSlopes final : public GradedShape {
 public:
  explicit SphereSlopes(double radius) : radius_(radius) {}
  double slope(double r, std::size_t) const override {
    return r / std::sqrt((radius_ - r) * (radius_ + r));
  }
  // f' + r f'' = r / sqrt(R^2 - r^2) + r R^2 / (R^2 - r^2)^(3/2) = r (2 R^2 - r^2) / (R^2 -
  // r^2)^(3/2).
  double radial_slope_derivative(double r, std::size_t) const override {
    const double q = (radius_ - r) * (radius_ + r);
    return r * (2.0 * radius_ * radius_ - r * r) / (q * std::sqrt(q));
  }
  std::size_t breakpoints_below(double) const override { return 0; }
  double breakpoint(std::size_t) const override { return 0.0; }
  double pole_radius() const override { return radius_; }

 private:
  double radius_;
};

class WavySlopes final : public GradedShape {
 public:
  WavySlopes(double radius, double amplitude, double wavelength)
      : radius_(radius),
        amplitude_(amplitude),
        wavenumber_(2.0 * std::numbers::pi / wavelength),
        quarter_(0.25 * wavelength) {}
  double slope(double r, std::size_t) const override {
    return r / radius_ + amplitude_ * wavenumber_ * std::sin(wavenumber_ * r);
  }
  double radial_slope_derivative(double r, std::size_t) const override {
    const double q = wavenumber_;
    return 2.0 * r / radius_ + amplitude_ * q * (std::sin(q * r) + q * r * std::cos(q * r));
  }
  // j quarter wavelengths for j = 1, 2, ... below x.
  std::size_t breakpoints_below(double x) const override {
    if (!(x > quarter_)) return 0;
    const double count = std::ceil(x / quarter_) - 1.0;
    return static_cast<std::size_t>(count);
  }
  double breakpoint(std::size_t j) const override { return static_cast<double>(j + 1) * quarter_; }

 private:
  double radius_, amplitude_, wavenumber_, quarter_;
};

class TableSlopes final : public GradedShape {
 public:
  explicit TableSlopes(const ShapePreservingCubic& shape) : shape_(shape) {}
  // Piece j is the cubic's piece j; beyond the last knot its last piece, extended.
  double slope(double r, std::size_t piece) const override {
    return shape_.slope_on(std::min(piece, shape_.size() - 2), r);
  }
  double radial_slope_derivative(double r, std::size_t piece) const override {
    const std::size_t p = std::min(piece, shape_.size() - 2);
    return shape_.slope_on(p, r) + r * shape_.curvature_on(p, r);
  }
  // The interior knots x_1 .. x_(n-2).
  std::size_t breakpoints_below(double x) const override {
    const auto& knots = shape_.knots();
    const auto end = knots.end() - 1;
    const auto it = std::lower_bound(knots.begin() + 1, end, x);
    return static_cast<std::size_t>(it - (knots.begin() + 1));
  }
  double breakpoint(std::size_t j) const override { return shape_.knots()[j + 1]; }
  double outer_radius() const override { return shape_.back(); }

 private:
  ShapePreservingCubic shape_;
};

/// acos(b / x) for 0 <= b <= x, as 2 asin(sqrt((x - b) / (2 x))): exact where b nears x.
double angle_of(double b, double x) { return 2.0 * std::asin(std::sqrt(0.5 * (x - b) / x)); }

}  // namespace

std::shared_ptr<const GradedShape> graded_sphere(double radius) {
  return std::make_shared<SphereSlopes>(radius);
}

std::shared_ptr<const GradedShape> graded_wavy(double radius, double amplitude, double wavelength) {
  return std::make_shared<WavySlopes>(radius, amplitude, wavelength);
}

std::shared_ptr<const GradedShape> graded_table(const ShapePreservingCubic& shape) {
  return std::make_shared<TableSlopes>(shape);
}

// Numerical Recipes' gaujac (Press et al., 3rd ed., section 4.6): the initial guesses its
// authors fitted, then Newton on P_n^(alpha, beta) from the recurrence; the nodes descend.
void gauss_jacobi_rule(int n, double alpha, double beta, std::vector<double>& nodes,
                       std::vector<double>& weights) {
  nodes.assign(static_cast<std::size_t>(n), 0.0);
  weights.assign(static_cast<std::size_t>(n), 0.0);
  const double ab = alpha + beta;
  const double dn = n;
  double z = 0.0;
  for (int i = 0; i < n; ++i) {
    if (i == 0) {
      const double an = alpha / dn, bn = beta / dn;
      const double r1 = (1.0 + alpha) * (2.78 / (4.0 + dn * dn) + 0.768 * an / dn);
      const double r2 = 1.0 + 1.48 * an + 0.96 * bn + 0.452 * an * an + 0.83 * an * bn;
      z = 1.0 - r1 / r2;
    } else if (i == 1) {
      const double r1 = (4.1 + alpha) / ((1.0 + alpha) * (1.0 + 0.156 * alpha));
      const double r2 = 1.0 + 0.06 * (dn - 8.0) * (1.0 + 0.12 * alpha) / dn;
      const double r3 = 1.0 + 0.012 * beta * (1.0 + 0.25 * std::abs(alpha)) / dn;
      z -= (1.0 - z) * r1 * r2 * r3;
    } else if (i == 2) {
      const double r1 = (1.67 + 0.28 * alpha) / (1.0 + 0.37 * alpha);
      const double r2 = 1.0 + 0.22 * (dn - 8.0) / dn;
      const double r3 = 1.0 + 8.0 * beta / ((6.28 + beta) * dn * dn);
      z -= (nodes[0] - z) * r1 * r2 * r3;
    } else if (i == n - 2) {
      const double r1 = (1.0 + 0.235 * beta) / (0.766 + 0.119 * beta);
      const double r2 = 1.0 / (1.0 + 0.639 * (dn - 4.0) / (1.0 + 0.71 * (dn - 4.0)));
      const double r3 = 1.0 / (1.0 + 20.0 * alpha / ((7.5 + alpha) * dn * dn));
      z += (z - nodes[static_cast<std::size_t>(n - 4)]) * r1 * r2 * r3;
    } else if (i == n - 1) {
      const double r1 = (1.0 + 0.37 * beta) / (1.67 + 0.28 * beta);
      const double r2 = 1.0 / (1.0 + 0.22 * (dn - 8.0) / dn);
      const double r3 = 1.0 / (1.0 + 8.0 * alpha / ((6.28 + alpha) * dn * dn));
      z += (z - nodes[static_cast<std::size_t>(n - 3)]) * r1 * r2 * r3;
    } else {
      const auto at = [&](int j) { return nodes[static_cast<std::size_t>(j)]; };
      z = 3.0 * at(i - 1) - 3.0 * at(i - 2) + at(i - 3);
    }
    double p1 = 0.0, p2 = 0.0, slope = 0.0, temp = 0.0;
    for (int its = 0; its < 100; ++its) {
      temp = 2.0 + ab;
      p1 = (alpha - beta + temp * z) / 2.0;
      p2 = 1.0;
      for (int j = 2; j <= n; ++j) {
        const double p3 = p2;
        p2 = p1;
        temp = 2.0 * j + ab;
        const double a = 2.0 * j * (j + ab) * (temp - 2.0);
        const double b = (temp - 1.0) * (alpha * alpha - beta * beta + temp * (temp - 2.0) * z);
        const double c = 2.0 * (j - 1.0 + alpha) * (j - 1.0 + beta) * temp;
        p1 = (b * p2 - c * p3) / a;
      }
      slope = (dn * (alpha - beta - temp * z) * p1 + 2.0 * (dn + alpha) * (dn + beta) * p2) /
              (temp * (1.0 - z * z));
      const double previous = z;
      z = previous - p1 / slope;
      if (std::abs(z - previous) <= 1e-15) break;
    }
    nodes[static_cast<std::size_t>(i)] = z;
    weights[static_cast<std::size_t>(i)] =
        std::exp(std::lgamma(alpha + dn) + std::lgamma(beta + dn) - std::lgamma(dn + 1.0) -
                 std::lgamma(dn + ab + 1.0)) *
        temp * std::pow(2.0, ab) / (slope * p2);
  }
}

GradedQuadrature::GradedQuadrature(std::shared_ptr<const GradedShape> shape,
                                   double grading_exponent)
    : shape_(std::move(shape)), grading_(grading_exponent) {
  if (!shape_) throw std::invalid_argument("the graded quadrature needs a shape");
  gauss_jacobi_rule(kGradedNodes, 0.0, grading_, jacobi_nodes_, jacobi_weights_);
  gauss_jacobi_rule(kGradedNodes, 0.0, 0.0, legendre_nodes_, legendre_weights_);
}

template <class H>
double GradedQuadrature::angular_integral(double x, const H& h) const {
  const double k = grading_;
  const double pole = shape_->pole_radius();
  // f''s pole r = P lies at s = i acosh(P / x): the Jacobi piece ends no farther out.
  const double pole_gap = std::isfinite(pole) ? std::acosh(pole / x) : 4.0;
  double total = 0.0;
  std::size_t piece = shape_->breakpoints_below(x);
  double lo = 0.0;
  for (;;) {
    const double hi =
        piece == 0 ? 0.5 * std::numbers::pi : angle_of(shape_->breakpoint(piece - 1), x);
    double s = lo;
    if (s == 0.0 && hi > 0.0) {
      // int_0^u s^k F(s) ds with F = h (sin s / s)^k smooth: (u/2)^(1+k) sum w_i F(s_i).
      const double u = std::min(hi, pole_gap);
      const double half = 0.5 * u;
      double sum = 0.0;
      for (std::size_t i = 0; i < jacobi_nodes_.size(); ++i) {
        const double si = half * (1.0 + jacobi_nodes_[i]);
        sum += jacobi_weights_[i] * h(x * std::cos(si), piece) * std::pow(std::sin(si) / si, k);
      }
      total += std::pow(half, 1.0 + k) * sum;
      s = u;
    }
    // Each piece no longer than its distance from the weight's branch point s = 0.
    while (s < hi) {
      const double next = std::min(hi, 2.0 * s);
      const double half = 0.5 * (next - s), mid = 0.5 * (next + s);
      double sum = 0.0;
      for (std::size_t i = 0; i < legendre_nodes_.size(); ++i) {
        const double si = mid + half * legendre_nodes_[i];
        sum += legendre_weights_[i] * h(x * std::cos(si), piece) * std::pow(std::sin(si), k);
      }
      total += half * sum;
      s = next;
    }
    if (piece == 0) break;
    lo = hi;
    --piece;
  }
  return total;
}

double GradedQuadrature::image(double x) const {
  x = std::abs(x);
  if (!(x < shape_->pole_radius())) return std::numeric_limits<double>::infinity();
  if (x == 0.0) return 0.0;
  return x * angular_integral(x, [this](double r, std::size_t p) { return shape_->slope(r, p); });
}

double GradedQuadrature::image_slope(double x) const {
  x = std::abs(x);
  if (!(x < shape_->pole_radius())) return std::numeric_limits<double>::infinity();
  if (x == 0.0) {
    // (r f')'(0) int_0^(pi/2) sin^k s ds = f'(0) B(1/2, (1+k)/2) / 2.
    const double k = grading_;
    return shape_->radial_slope_derivative(0.0, 0) * 0.5 *
           std::exp(std::lgamma(0.5) + std::lgamma(0.5 * (1.0 + k)) - std::lgamma(1.0 + 0.5 * k));
  }
  return angular_integral(
      x, [this](double r, std::size_t p) { return shape_->radial_slope_derivative(r, p); });
}

double GradedQuadrature::nonadhesive_force_per_constant(double a) const {
  if (!(a < shape_->pole_radius())) return std::numeric_limits<double>::infinity();
  if (!(a > 0.0)) return 0.0;
  return std::pow(a, grading_) * angular_integral(a, [this](double r, std::size_t p) {
           return r * r * shape_->slope(r, p);
         });
}

double GradedQuadrature::squared_gap_integral(double a, double d) const {
  if (!(a > 0.0)) return 0.0;
  const double k = grading_;
  const double ga = image(a);
  const double ak = std::pow(a, 1.0 + k);
  const double first_moment = ak * ga - nonadhesive_force_per_constant(a);
  // (1 + k) int_0^a x^k g^2: Gauss-Jacobi on [0, e] (weight x^k), e short of the first
  // breakpoint and of half the pole's radius; Gauss-Kronrod between breakpoints beyond.
  const std::size_t below = shape_->breakpoints_below(a);
  double e = std::min(a, 0.5 * shape_->pole_radius());
  if (below > 0) e = std::min(e, shape_->breakpoint(0));
  double sum = 0.0;
  const double half = 0.5 * e;
  for (std::size_t i = 0; i < jacobi_nodes_.size(); ++i) {
    const double g = image(half * (1.0 + jacobi_nodes_[i]));
    sum += jacobi_weights_[i] * g * g;
  }
  double squares = std::pow(half, 1.0 + k) * sum;
  // Beyond e, Gauss-Legendre pieces no longer than their distance from x = 0 (x^k's branch
  // point) nor than half their distance from the pole (g_k's singularity).
  const double pole = shape_->pole_radius();
  const auto add_pieces = [&](double lo, double hi) {
    double x0 = lo;
    while (x0 < hi) {
      const double x1 = std::min({hi, 2.0 * x0, x0 + 0.5 * (pole - x0)});
      const double half = 0.5 * (x1 - x0), mid = 0.5 * (x1 + x0);
      double piece = 0.0;
      for (std::size_t i = 0; i < legendre_nodes_.size(); ++i) {
        const double x = mid + half * legendre_nodes_[i];
        const double g = image(x);
        piece += legendre_weights_[i] * std::pow(x, k) * g * g;
      }
      squares += half * piece;
      x0 = x1;
    }
  };
  double lo = e;
  for (std::size_t j = 0; j <= below && lo < a; ++j) {
    const double hi = j < below ? std::max(lo, shape_->breakpoint(j)) : a;
    add_pieces(lo, hi);
    lo = hi;
  }
  return d * d * ak - 2.0 * d * first_moment + (1.0 + k) * squares;
}

}  // namespace mdrsim
