// A piecewise-cubic Hermite interpolant that stays non-decreasing on non-decreasing data.
#pragma once

#include <cstddef>
#include <vector>

namespace mdrsim {

/// Cubic pieces between knots x_0 < ... < x_{n-1}, with value and slope given at each knot.
/// The slopes are limited to [0, 3 min(adjacent secants)] (Hyman's filter), which lies in
/// the Fritsch-Carlson region: non-decreasing data give a non-decreasing curve. Smooth
/// data keep their slopes, and with them the interpolant's accuracy.
class MonotoneCubic {
 public:
  /// Slopes of the not-a-knot cubic spline (exact for cubics, O(h^4) on smooth data),
  /// then limited. Needs >= 4 knots, strictly increasing, and non-decreasing values.
  static MonotoneCubic spline(std::vector<double> knots, std::vector<double> values);
  /// Given slopes (e.g. exact derivatives), limited. Needs >= 2 knots.
  static MonotoneCubic hermite(std::vector<double> knots, std::vector<double> values,
                               std::vector<double> slopes);

  std::size_t size() const { return knots_.size(); }
  const std::vector<double>& knots() const { return knots_; }
  double front() const { return knots_.front(); }
  double back() const { return knots_.back(); }

  /// The piece k with x_k <= x < x_{k+1}, clamped to the first and last pieces: O(log n).
  std::size_t piece(double x) const;

  /// On piece k (x may lie slightly outside it: the cubic is extended).
  double value_on(std::size_t k, double x) const;
  double slope_on(std::size_t k, double x) const;
  double curvature_on(std::size_t k, double x) const;

  double value(double x) const { return value_on(piece(x), x); }
  double slope(double x) const { return slope_on(piece(x), x); }
  double curvature(double x) const { return curvature_on(piece(x), x); }
  /// integral from x_0 to x of the interpolant.
  double integral(double x) const;

 private:
  /// p(s) = y + s (c1 + s (c2 + s c3)), s = (x - x_k)/h on piece k.
  struct Piece {
    double h, y, c1, c2, c3;
    double integral_before;  ///< integral from x_0 to x_k
  };
  MonotoneCubic(std::vector<double> knots, const std::vector<double>& values,
                std::vector<double> slopes);

  std::vector<double> knots_;
  std::vector<Piece> pieces_;
};

}  // namespace mdrsim
