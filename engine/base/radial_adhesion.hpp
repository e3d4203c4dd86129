// A work of adhesion that varies with the radius of the spring: a table or a sinusoid.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mdrsim {

/// dgamma(r) [J/m^2] (docs/scene.md "Adhesion that varies with radius"): piecewise linear
/// between the points of a table and constant beyond its ends, or mean (1 + amplitude
/// sin(2 pi r / wavelength)). A radius given twice in a table is a step: the value jumps
/// there, and the spring at that radius takes the outer value (right-continuous).
class RadialAdhesion {
 public:
  struct Table {
    std::vector<double> radii;   ///< r_i [m], from >= 0, non-decreasing, each at most twice
    std::vector<double> values;  ///< dgamma(r_i) [J/m^2], >= 0
  };
  struct Sinusoid {
    double mean;        ///< [J/m^2], >= 0
    double amplitude;   ///< [1], in [0, 1]
    double wavelength;  ///< [m], > 0
  };

  /// The form, checked: throws std::invalid_argument naming the first bad point or value
  /// (find_problem says which).
  explicit RadialAdhesion(Table table);
  explicit RadialAdhesion(Sinusoid sinusoid);

  /// dgamma(r) [J/m^2]. A table whose values are all equal gives that value to the bit.
  double at(double r) const;
  /// The value the scales (F0, a0, d0) use: the mean, or the value at r = 0 of a table.
  double scale_value() const;
  /// The largest value anywhere [J/m^2]: found once, at construction (a program asks for it at
  /// every event, and a table may hold 10^4 points).
  double largest() const { return largest_; }
  /// Whether dgamma is one value at every radius (a table of equal values, a sinusoid of
  /// amplitude 0): at() then gives it to the bit.
  bool uniform() const {
    if (const Sinusoid* s = sinusoid()) return s->amplitude == 0.0;
    const Table& t = std::get<Table>(form_);
    return std::all_of(t.values.begin(), t.values.end(), [&](double v) { return v == largest_; });
  }
  /// Radii [m] where dgamma(r) bends or jumps (a table's points; none for a sinusoid).
  const std::vector<double>& breakpoints() const;
  /// The shortest length over which dgamma(r) changes [m]: a sinusoid's wavelength, or the
  /// smallest positive gap between a table's points (infinity for a one-point table); found
  /// once, at construction.
  double finest_length() const { return finest_length_; }

  const Table* table() const { return std::get_if<Table>(&form_); }
  const Sinusoid* sinusoid() const { return std::get_if<Sinusoid>(&form_); }

  /// For messages: "the table of N points" or "mean (1 + A sin(2 pi r / lambda))".
  std::string describe() const;

 private:
  std::variant<Table, Sinusoid> form_;
  std::vector<double> breakpoints_;
  double largest_ = 0.0;                                            ///< [J/m^2]
  double finest_length_ = std::numeric_limits<double>::infinity();  ///< [m]
};

// Inline: a criterion asks at every let-go, and the parts see only headers of the vocabulary.
inline double RadialAdhesion::at(double r) const {
  if (const Sinusoid* s = sinusoid()) {
    return s->mean * (1.0 + s->amplitude * std::sin(2.0 * std::numbers::pi * r / s->wavelength));
  }
  const Table& t = std::get<Table>(form_);
  // The first point beyond r: a step's outer value holds at its radius.
  const auto beyond = std::upper_bound(t.radii.begin(), t.radii.end(), r);
  if (beyond == t.radii.begin()) return t.values.front();
  if (beyond == t.radii.end()) return t.values.back();
  const auto i = static_cast<std::size_t>(beyond - t.radii.begin());
  const double r0 = t.radii[i - 1], r1 = t.radii[i];
  const double v0 = t.values[i - 1], v1 = t.values[i];
  return v0 + (v1 - v0) * ((r - r0) / (r1 - r0));
}

inline double RadialAdhesion::scale_value() const {
  if (const Sinusoid* s = sinusoid()) return s->mean;
  return at(0.0);
}

inline const std::vector<double>& RadialAdhesion::breakpoints() const { return breakpoints_; }

/// What is wrong with a table: the column it is about ("r" or "value"), the point where one
/// is named, and the message ("r[3] = ... is below r[2] = ...", "value[1] = -0.2 at r = ...
/// is not a finite work of adhesion >= 0", "r[2] = r[3] = r[4] = ...: a radius at most twice
/// (a step)").
struct AdhesionTableProblem {
  std::string column;
  std::optional<std::size_t> point;
  std::string message;
};
std::optional<AdhesionTableProblem> find_adhesion_table_problem(const RadialAdhesion::Table& table);

/// The first radius [m] where `approach` exceeds `receding` (0 <= dgamma_a <= dgamma must hold
/// at every r): checked at both tables' points (and just inside each, for steps) and, with a
/// sinusoid, on a grid of 64 points per wavelength out to `reach` [m]; nothing when it holds.
std::optional<double> first_radius_where_approach_exceeds(const RadialAdhesion& approach,
                                                          const RadialAdhesion& receding,
                                                          double reach);

}  // namespace mdrsim
