// An indenter given by points of f(r): a shape-preserving cubic through them, its MDR image.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "profiles/profile.hpp"
#include "profiles/shape_preserving_cubic.hpp"

namespace mdrsim {

/// Points (r_i, f_i) of a profile, with the CSV line of each point when read from a file.
struct ProfileTable {
  std::vector<double> radii;       ///< r_i [m]
  std::vector<double> gaps;        ///< f_i [m]
  std::vector<std::size_t> lines;  ///< line of point i in its file; empty for scene arrays
};

/// What is wrong with a table, if anything: which column ("r", "f" or "count") and point,
/// and the message. Checks: at least 4 points, as many f as r, r_0 = 0 and r increasing,
/// f_0 = 0, f >= 0, every value finite. f may decrease (a wavy or dimpled indenter).
struct TableProblem {
  std::string column;
  std::optional<std::size_t> point;
  std::string message;
};
std::optional<TableProblem> find_table_problem(const ProfileTable& table);

/// Reads a CSV table with columns r,f [m]: one point per line, an optional header line
/// "r,f", blank lines and lines starting with '#' skipped. Throws std::invalid_argument with
/// "line N: ..." for a malformed line, or naming the file when it cannot be read.
ProfileTable read_profile_table(const std::string& path);

/// f(r) between the points is the shape-preserving cubic through them (not-a-knot spline
/// slopes, Hyman-limited: exact for polynomials up to cubics, monotone on every monotone run
/// of the points, with no overshoot at an extremum). Its image g(x) is
/// eq. 4 evaluated once, at construction, on a grid that refines every table interval;
/// between grid nodes g is the cubic Hermite interpolant of the exact values and slopes.
class TabulatedProfile final : public Profile {
 public:
  /// Nodes of the image grid: every table interval split evenly into at least this many
  /// (exact g and g' at the nodes; between them the error is far below the table's own).
  static constexpr std::size_t kImageNodes = 1024;

  /// A table without problems (find_table_problem). Its image may decrease (where r f'(r)
  /// does: a plateau after a rise, a dip): a front then jumps over the dip.
  explicit TabulatedProfile(const ProfileTable& table);
  /// The profile `built`, read from the CSV `file` (source_table_file()).
  TabulatedProfile(const TabulatedProfile& built, std::string file) : TabulatedProfile(built) {
    file_ = std::move(file);
  }

  /// The profile of a table, built once per process for the last few tables seen: a sweep
  /// builds one scene per value from the same table (thread-safe).
  static std::shared_ptr<const TabulatedProfile> shared(const ProfileTable& table);

  double shape(double radius) const override;
  double mdr_image(double x) const override;
  double mdr_image_slope(double x) const override;
  /// 2 (a g(a) - integral_0^a g), the integral exact on the Hermite pieces.
  double nonadhesive_force_per_modulus(double contact_radius) const override;
  /// Exact on the image's Hermite pieces: no quadrature over its ~1000 kinks.
  std::optional<ExactIntegral> squared_gap_integral(double contact_radius,
                                                    double indentation) const override;
  /// In closed form on each of the image's Hermite pieces the zone covers (in its angle): exact
  /// to rounding where the adaptive default halves its panels at every kink of g''.
  DugdaleGap dugdale_gap(double contact_radius, double cohesive_radius,
                         double angle) const override;
  double outer_radius() const override { return shape_.back(); }
  /// Where the interpolated shape's r f'(r) never falls (checked exactly at construction: on
  /// each cubic piece (r f')' is a quadratic in r) and the image's nodes never fall (its
  /// Hermite pieces are limited to be monotone on monotone nodes): every convex table rising
  /// from the tip, a cone's, a power law's.
  bool proves_one_disk() const override { return image_never_falls_; }
  std::optional<std::string> source_table_file() const override { return file_; }

  /// Eq. 4 and its x-derivative for the interpolated f at x [m], by Gauss-Legendre
  /// quadrature after r = x sin t: g(x) = x integral_0^{pi/2} f'(x sin t) dt, whose integrand
  /// is bounded (no 1/sqrt singularity left) and polynomial in sin t on each table
  /// interval; the t-range is split at every table point below x. O(table) per call: for
  /// the grid and for tests, never per spring.
  struct ImageValue {
    double image;  ///< g [m]
    double slope;  ///< dg/dx [1]
  };
  ImageValue transform(double x) const;

  const ShapePreservingCubic& interpolated_shape() const { return shape_; }
  /// g(x) on its grid: the cubic Hermite pieces every image operation is exact on.
  const ShapePreservingCubic& interpolated_image() const { return image_; }

 private:
  ShapePreservingCubic shape_;       ///< f(r)
  ShapePreservingCubic image_;       ///< g(x) on the grid
  std::optional<std::string> file_;  ///< the CSV read, as the scene gave it; none for arrays
  bool image_never_falls_ = false;   ///< proves_one_disk()
};

}  // namespace mdrsim
