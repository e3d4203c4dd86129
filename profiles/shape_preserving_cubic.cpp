// Not-a-knot spline slopes by the tridiagonal solve, Hyman's limiter and Hermite pieces.
#include "profiles/shape_preserving_cubic.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mdrsim {
namespace {

/// Neumaier's compensated sum.
class Sum {
 public:
  void add(double term) {
    const double t = sum_ + term;
    compensation_ += std::abs(sum_) >= std::abs(term) ? (sum_ - t) + term : (term - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

void check_knots(const std::vector<double>& x, const std::vector<double>& y, std::size_t least) {
  if (x.size() < least) throw std::invalid_argument("too few knots for the interpolant");
  if (y.size() != x.size()) throw std::invalid_argument("one value per knot is needed");
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw std::invalid_argument("knots and values must be finite");
    }
    if (i > 0 && !(x[i] > x[i - 1])) throw std::invalid_argument("knots must increase");
  }
}

// Slopes m_i of the C2 cubic spline with not-a-knot ends (de Boor; as MATLAB's spline).
// With h_k = x_{k+1} - x_k and secants s_k, interior rows are continuity of the second
// derivative, h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i s_{i-1} + h_{i-1}
// s_i); the end rows are continuity of the third derivative at x_1 (x_{n-2}) with m_2 (m_{n-3})
// eliminated by the neighbouring interior row. Thomas' algorithm: after the first
// elimination the rows are diagonally dominant.
std::vector<double> not_a_knot_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> h(n - 1), s(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    h[k] = x[k + 1] - x[k];
    s[k] = (y[k + 1] - y[k]) / h[k];
  }
  std::vector<double> sub(n, 0.0), diag(n, 0.0), super(n, 0.0), rhs(n, 0.0);
  diag[0] = h[1];
  super[0] = h[0] + h[1];
  rhs[0] = (h[1] * s[0] * (3.0 * h[0] + 2.0 * h[1]) + h[0] * h[0] * s[1]) / (h[0] + h[1]);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    sub[i] = h[i];
    diag[i] = 2.0 * (h[i - 1] + h[i]);
    super[i] = h[i - 1];
    rhs[i] = 3.0 * (h[i] * s[i - 1] + h[i - 1] * s[i]);
  }
  const double a = h[n - 2], b = h[n - 3];
  sub[n - 1] = a + b;
  diag[n - 1] = b;
  rhs[n - 1] = (b * s[n - 2] * (3.0 * a + 2.0 * b) + a * a * s[n - 3]) / (a + b);
  for (std::size_t i = 1; i < n; ++i) {
    const double factor = sub[i] / diag[i - 1];
    diag[i] -= factor * super[i - 1];
    rhs[i] -= factor * rhs[i - 1];
  }
  std::vector<double> m(n);
  m[n - 1] = rhs[n - 1] / diag[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) m[i] = (rhs[i] - super[i] * m[i + 1]) / diag[i];
  return m;
}

}  // namespace

ShapePreservingCubic ShapePreservingCubic::spline(std::vector<double> knots,
                                                  std::vector<double> values) {
  check_knots(knots, values, 4);
  std::vector<double> slopes = not_a_knot_slopes(knots, values);
  return ShapePreservingCubic(std::move(knots), values, std::move(slopes), false);
}

ShapePreservingCubic ShapePreservingCubic::hermite(std::vector<double> knots,
                                                   std::vector<double> values,
                                                   std::vector<double> slopes) {
  check_knots(knots, values, 2);
  if (slopes.size() != knots.size()) throw std::invalid_argument("one slope per knot is needed");
  return ShapePreservingCubic(std::move(knots), values, std::move(slopes), true);
}

ShapePreservingCubic::ShapePreservingCubic(std::vector<double> knots,
                                           const std::vector<double>& values,
                                           std::vector<double> slopes, bool given_slopes)
    : knots_(std::move(knots)) {
  const std::size_t n = knots_.size();
  std::vector<double> secant(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    secant[k] = (values[k + 1] - values[k]) / (knots_[k + 1] - knots_[k]);
  }
  // Hyman's filter (1983): where the data rise (fall) on both sides of a knot, its slope is
  // held to [0, 3 min |s|] with their sign, in the Fritsch-Carlson region (alpha, beta <= 3),
  // so that each monotone run of data gives a monotone curve, and a flat secant a flat piece;
  // at a data extremum (secants of opposite signs, or one flat) the slope is 0: no overshoot.
  // Given (exact) slopes of data that rise and fall are kept: the function's own extrema lie
  // between knots, and the plain Hermite cubic follows it to O(h^4).
  const bool keep =
      given_slopes && std::any_of(secant.begin(), secant.end(), [](double v) { return v < 0.0; });
  for (std::size_t i = 0; i < n && !keep; ++i) {
    const double before = i == 0 ? secant[0] : secant[i - 1];
    const double after = i + 1 == n ? secant[n - 2] : secant[i];
    if (!(before * after > 0.0)) {
      slopes[i] = 0.0;
      continue;
    }
    const double sign = after > 0.0 ? 1.0 : -1.0;
    const double limit = std::min(std::abs(before), std::abs(after));
    const double m = std::isnan(slopes[i]) ? limit : sign * slopes[i];
    slopes[i] = sign * std::clamp(m, 0.0, 3.0 * limit);
  }
  pieces_.reserve(n - 1);
  double integral = 0.0;
  // Neumaier's sums: thousands of pieces add no more than an ulp of rounding to each.
  Sum first, first_size, square, square_size;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const double h = knots_[k + 1] - knots_[k];
    const double rise = values[k + 1] - values[k];
    const double c1 = h * slopes[k];
    const double c2 = 3.0 * rise - 2.0 * h * slopes[k] - h * slopes[k + 1];
    const double c3 = h * (slopes[k] + slopes[k + 1]) - 2.0 * rise;
    pieces_.push_back({h, values[k], c1, c2, c3, integral, first.value(), first_size.value(),
                       square.value(), square_size.value(), 1.0 / h});
    integral += h * (values[k] + c1 / 2.0 + c2 / 3.0 + c3 / 4.0);
    const double c[4] = {values[k], c1, c2, c3};
    for (int i = 0; i <= 3; ++i) {
      first.add(h * c[i] / (i + 1));
      first_size.add(h * std::abs(c[i]) / (i + 1));
      for (int j = 0; j <= 3; ++j) {
        square.add(h * c[i] * c[j] / (i + j + 1));
        square_size.add(h * std::abs(c[i] * c[j]) / (i + j + 1));
      }
    }
  }
}

std::size_t ShapePreservingCubic::piece(double x) const {
  const auto it = std::upper_bound(knots_.begin(), knots_.end(), x);
  const std::size_t after = static_cast<std::size_t>(it - knots_.begin());
  return std::clamp<std::size_t>(after, 1, pieces_.size()) - 1;
}

double ShapePreservingCubic::curvature_on(std::size_t k, double x) const {
  const Piece& p = pieces_[k];
  const double s = (x - knots_[k]) / p.h;
  return (2.0 * p.c2 + 6.0 * p.c3 * s) / (p.h * p.h);
}

double ShapePreservingCubic::integral(double x) const {
  const std::size_t k = piece(x);
  const Piece& p = pieces_[k];
  const double s = (x - knots_[k]) / p.h;
  return p.integral_before + p.h * s * (p.y + s * (p.c1 / 2.0 + s * (p.c2 / 3.0 + s * p.c3 / 4.0)));
}

ShapePreservingCubic::SquareIntegral ShapePreservingCubic::integral_of_square(double level,
                                                                              double x) const {
  if (!(x > knots_.front())) return {0.0, 0.0};
  const std::size_t last = piece(x);
  const Piece& p = pieces_[last];
  const double span = knots_[last] - knots_.front();
  SquareIntegral out{
      level * level * span - 2.0 * level * p.first_before + p.square_before,
      level * level * span + 2.0 * std::abs(level) * p.first_size_before + p.square_size_before};
  const double end = (x - knots_[last]) / p.h;
  // level - p(s) = b0 + b1 s + b2 s^2 + b3 s^3; its square's coefficient of s^m is the sum of
  // b_i b_j over i + j = m, integrated from 0 to `end` as end^(m+1) / (m+1).
  const double b[4] = {level - p.y, -p.c1, -p.c2, -p.c3};
  double power = end;
  for (int m = 0; m <= 6; ++m) {
    double coefficient = 0.0, size = 0.0;
    for (int i = std::max(0, m - 3); i <= std::min(3, m); ++i) {
      coefficient += b[i] * b[m - i];
      size += std::abs(b[i] * b[m - i]);
    }
    out.value += p.h * coefficient * power / (m + 1);
    out.magnitude += p.h * size * power / (m + 1);
    power *= end;
  }
  return out;
}

}  // namespace mdrsim
