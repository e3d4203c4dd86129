// The monotone cubic: exact on cubics, fourth order on smooth data, never decreasing on steps.
#include "profiles/shape_preserving_cubic.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

using mdrsim::ShapePreservingCubic;

namespace {

std::vector<double> sample(const std::vector<double>& x, double (*fn)(double)) {
  std::vector<double> y;
  for (const double v : x) y.push_back(fn(v));
  return y;
}

double cubic(double x) { return 0.5 + x + 0.3 * x * x + x * x * x; }

}  // namespace

// The not-a-knot spline reproduces any cubic, on uneven knots too; its slopes here stay
// inside the limiter's box, so the limited curve is the cubic itself (to rounding).
TEST(ShapePreservingCubic, SplineIsExactOnACubic) {
  const std::vector<double> x{0.0, 0.1, 0.35, 0.4, 0.9, 1.3, 2.0};
  const ShapePreservingCubic c = ShapePreservingCubic::spline(x, sample(x, cubic));
  for (double v = 0.0; v <= 2.0; v += 0.01) {
    EXPECT_NEAR(c.value(v), cubic(v), 1e-13);
    EXPECT_NEAR(c.slope(v), 1.0 + 0.6 * v + 3.0 * v * v, 1e-12);
    EXPECT_NEAR(c.curvature(v), 0.6 + 6.0 * v, 1e-10);
    EXPECT_NEAR(c.integral(v), 0.5 * v + 0.5 * v * v + 0.1 * v * v * v + 0.25 * v * v * v * v,
                1e-13);
  }
}

// On smooth data the error falls like h^4: the order estimated from two halvings, as
// log2 of successive error ratios, lies within 0.3 of 4.
TEST(ShapePreservingCubic, SplineIsFourthOrderOnSmoothData) {
  const auto smooth = [](double x) { return std::exp(x); };
  double errors[3];
  int i = 0;
  for (const int n : {20, 40, 80}) {
    std::vector<double> x, y;
    for (int k = 0; k <= n; ++k) {
      x.push_back(static_cast<double>(k) / n);
      y.push_back(smooth(x.back()));
    }
    const ShapePreservingCubic c = ShapePreservingCubic::spline(x, y);
    double worst = 0.0;
    for (int k = 0; k < 1000; ++k) {
      const double v = (k + 0.5) / 1000.0;
      worst = std::max(worst, std::abs(c.value(v) - smooth(v)));
    }
    errors[i++] = worst;
  }
  EXPECT_NEAR(std::log2(errors[0] / errors[1]), 4.0, 0.3);
  EXPECT_NEAR(std::log2(errors[1] / errors[2]), 4.0, 0.3);
}

// A step: the spline's slopes would overshoot above 1 and dip below 0 next to it; limited,
// the curve never decreases and stays inside the data's range.
TEST(ShapePreservingCubic, StepsStayMonotone) {
  const std::vector<double> x{0, 1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<double> y{0, 0, 0, 0, 1, 1, 1, 1, 1};
  const ShapePreservingCubic c = ShapePreservingCubic::spline(x, y);
  double last = -1.0;
  for (double v = 0.0; v <= 8.0; v += 1e-3) {
    const double value = c.value(v);
    EXPECT_GE(value, last) << "at " << v;
    EXPECT_GE(value, 0.0);
    EXPECT_LE(value, 1.0);
    last = value;
  }
  EXPECT_EQ(c.value(1.5), 0.0);  // flat secants give flat pieces
  EXPECT_EQ(c.slope(6.5), 0.0);
}

// Given slopes outside the Fritsch-Carlson box are limited: slope 10 on secants of 1.
TEST(ShapePreservingCubic, GivenSlopesAreLimited) {
  const ShapePreservingCubic c =
      ShapePreservingCubic::hermite({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}, {10, -5, 1});
  EXPECT_EQ(c.slope(0.0), 3.0);
  EXPECT_EQ(c.slope(1.0), 0.0);
  double last = -1.0;
  for (double v = 0.0; v <= 2.0; v += 1e-3) {
    EXPECT_GE(c.value(v), last);
    last = c.value(v);
  }
}

// Data that rise and fall: each monotone run of data gives a monotone curve within its
// values, and at a data extremum the spline is flat (no overshoot above the highest point).
TEST(ShapePreservingCubic, RisingAndFallingDataKeepTheirShape) {
  const std::vector<double> x{0, 1, 2, 3, 4, 5, 6, 7};
  const std::vector<double> y{0, 1, 3, 2, 0.5, 0.4, 1, 4};
  const ShapePreservingCubic c = ShapePreservingCubic::spline(x, y);
  EXPECT_EQ(c.slope(2.0), 0.0);  // the data's maximum
  EXPECT_EQ(c.slope(5.0), 0.0);  // the data's minimum
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double lo = std::min(y[k], y[k + 1]), hi = std::max(y[k], y[k + 1]);
    double last = y[k];
    for (double v = x[k]; v <= x[k + 1]; v += 1e-3) {
      const double value = c.value(v);
      EXPECT_GE(value, lo - 1e-15) << "at " << v;
      EXPECT_LE(value, hi + 1e-15) << "at " << v;
      EXPECT_GE((value - last) * (y[k + 1] - y[k]), -1e-15) << "at " << v;
      last = value;
    }
  }
}

// Exact slopes of sin at knots 0.25 apart, across its maximum at pi/2 (between the knots 1.5
// and 1.75): data that rise and fall keep their given slopes (a limit of 3 min |s| = 0.162
// at 1.75 would cut the exact 0.178), so the curve follows sin to the Hermite cubic's error
// h^4 max|sin| / 384 = 1.017e-5.
TEST(ShapePreservingCubic, GivenSlopesAreKeptAtAnExtremum) {
  std::vector<double> x, y, m;
  for (int i = 0; i <= 12; ++i) {
    x.push_back(0.25 * i);
    y.push_back(std::sin(x.back()));
    m.push_back(std::cos(x.back()));
  }
  const ShapePreservingCubic c = ShapePreservingCubic::hermite(x, y, m);
  EXPECT_EQ(c.slope(1.5), std::cos(1.5));
  EXPECT_EQ(c.slope(1.75), std::cos(1.75));
  for (double v = 0.0; v <= 3.0; v += 1e-3) EXPECT_NEAR(c.value(v), std::sin(v), 1.02e-5) << v;
}

TEST(ShapePreservingCubic, RefusesBadKnots) {
  EXPECT_THROW(ShapePreservingCubic::spline({0, 1, 2}, {0, 1, 2}), std::invalid_argument);
  EXPECT_THROW(ShapePreservingCubic::spline({0, 1, 1, 2}, {0, 1, 2, 3}), std::invalid_argument);
  EXPECT_THROW(ShapePreservingCubic::hermite({0, 1}, {0, 1}, {0}), std::invalid_argument);
}

// int (level - p)^2 over 3000 uneven pieces of a rising and falling cubic q (kept as given:
// the Hermite pieces are q itself) against the polynomial's own integral, in long double
// (its rounding near 1e-19 relative): within 1e-15 of the terms' magnitudes, what the
// continuum work reports as its rounding, at levels above, inside and below q's range and at
// x on a knot, between knots and at the last one.
TEST(ShapePreservingCubic, IntegralOfSquareOverManyPieces) {
  const auto q = [](long double x) { return 0.3L + x * (2.0L + x * (-3.0L + x)); };
  const auto dq = [](long double x) { return 2.0L + x * (-6.0L + 3.0L * x); };
  std::vector<double> x, y, s;
  for (int k = 0; k <= 3000; ++k) {
    const double t = static_cast<double>(k) / 3000.0;
    x.push_back(2.5 * t * (1.0 + 0.3 * std::sin(3.0 * t)) / 1.3);
    y.push_back(static_cast<double>(q(x.back())));
    s.push_back(static_cast<double>(dq(x.back())));
  }
  const ShapePreservingCubic p = ShapePreservingCubic::hermite(x, y, s);
  for (const double level : {2.0, 0.5, 0.3, -0.4}) {
    for (const double at : {x[1234], 0.5 * (x[2000] + x[2001]), x.back()}) {
      // int_0^X (level - q)^2 dx by its antiderivative, q's coefficients (0.3 - level, 2, -3, 1).
      const long double c[4] = {0.3L - level, 2.0L, -3.0L, 1.0L};
      long double want = 0.0L;
      for (int i = 0; i <= 3; ++i) {
        for (int j = 0; j <= 3; ++j)
          want += c[i] * c[j] * std::pow(static_cast<long double>(at), i + j + 1) / (i + j + 1);
      }
      const ShapePreservingCubic::SquareIntegral got = p.integral_of_square(level, at);
      EXPECT_LE(std::abs(got.value - static_cast<double>(want)), 1e-15 * got.magnitude)
          << "level " << level << ", x " << at;
      EXPECT_GE(got.magnitude, std::abs(got.value));
    }
  }
}
