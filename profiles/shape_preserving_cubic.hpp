// A piecewise-cubic Hermite interpolant that stays monotone wherever its data are.
#pragma once

#include <cstddef>
#include <vector>

namespace mdrsim {

/// Cubic pieces between knots x_0 < ... < x_{n-1}, with value and slope given at each knot.
/// Where the data rise (fall) on both sides of a knot its slope is limited to [0, 3 min |s|]
/// of the adjacent secants, with their sign (Hyman's filter), inside the Fritsch-Carlson
/// region: each monotone run of data gives a monotone curve, and non-decreasing data a
/// non-decreasing one. Smooth data keep their slopes, and with them the accuracy.
class ShapePreservingCubic {
 public:
  /// Slopes of the not-a-knot cubic spline (exact for cubics, O(h^4) on smooth data),
  /// then limited; 0 at a data extremum (no overshoot). Needs >= 4 knots, increasing.
  static ShapePreservingCubic spline(std::vector<double> knots, std::vector<double> values);
  /// Given slopes (e.g. exact derivatives): limited as above for non-decreasing data (the
  /// curve must not decrease), kept as given for data that rise and fall (the function's
  /// extrema lie between knots; the plain Hermite cubic is O(h^4)). Needs >= 2 knots.
  static ShapePreservingCubic hermite(std::vector<double> knots, std::vector<double> values,
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
  /// Piece k's cubic about x: p(x + u) = value + u (slope + u (half_curvature + u sixth_third)).
  struct Taylor {
    double value, slope, half_curvature, sixth_third;
  };
  Taylor taylor_on(std::size_t k, double x) const;

  double value(double x) const { return value_on(piece(x), x); }
  double slope(double x) const { return slope_on(piece(x), x); }
  double curvature(double x) const { return curvature_on(piece(x), x); }
  /// integral from x_0 to x of the interpolant.
  double integral(double x) const;

  /// integral from x_0 to x of (level - p)^2, exact on each piece, and the sum of its terms'
  /// magnitudes (what its rounding is relative to): level^2 (x_k - x_0) - 2 level int p +
  /// int p^2 over the whole pieces before x (their sums kept from construction, so that a call
  /// costs O(log n)), the piece x lies on expanded about its start.
  struct SquareIntegral {
    double value;
    double magnitude;
  };
  SquareIntegral integral_of_square(double level, double x) const;

 private:
  /// p(s) = y + s (c1 + s (c2 + s c3)), s = (x - x_k)/h on piece k.
  struct Piece {
    double h, y, c1, c2, c3;
    double integral_before;  ///< integral from x_0 to x_k
    /// From x_0 to x_k, summed with compensation: int p, int p^2, and the sums of their
    /// pieces' terms' magnitudes.
    double first_before, first_size_before, square_before, square_size_before;
    double to_s;  ///< 1 / h
  };
  ShapePreservingCubic(std::vector<double> knots, const std::vector<double>& values,
                       std::vector<double> slopes, bool given_slopes);

  std::vector<double> knots_;
  std::vector<Piece> pieces_;
};

// Inline: the pieces' hot loops (a Dugdale zone's Gauss nodes) call them once a node.
inline double ShapePreservingCubic::value_on(std::size_t k, double x) const {
  const Piece& p = pieces_[k];
  const double s = (x - knots_[k]) / p.h;
  return p.y + s * (p.c1 + s * (p.c2 + s * p.c3));
}

inline double ShapePreservingCubic::slope_on(std::size_t k, double x) const {
  const Piece& p = pieces_[k];
  const double s = (x - knots_[k]) / p.h;
  return (p.c1 + s * (2.0 * p.c2 + s * 3.0 * p.c3)) / p.h;
}

inline ShapePreservingCubic::Taylor ShapePreservingCubic::taylor_on(std::size_t k, double x) const {
  const Piece& p = pieces_[k];
  const double to_s = p.to_s;
  const double s = (x - knots_[k]) * to_s;
  return {p.y + s * (p.c1 + s * (p.c2 + s * p.c3)),
          (p.c1 + s * (2.0 * p.c2 + s * 3.0 * p.c3)) * to_s, (p.c2 + 3.0 * p.c3 * s) * to_s * to_s,
          p.c3 * to_s * to_s * to_s};
}

}  // namespace mdrsim
