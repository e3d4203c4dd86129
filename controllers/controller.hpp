// What the loading machine holds fixed on one axis: an affine constraint on displacement and force.
#pragma once

#include <string_view>

namespace mdrsim {

/// The constraint a_u * u + a_F * F = held value on one axis: fixed-grips (1, 0),
/// fixed-load (0, 1), compliant (1, 1/k). Both coefficients >= 0, not both zero, so that
/// a larger held value always means a larger displacement.
struct AffineConstraint {
  double displacement_coefficient;  ///< a_u [1]
  double force_coefficient;         ///< a_F [m/N]
};

/// The contact's response on one axis while the set of attached springs is fixed:
/// F = stiffness * u - offset.
struct LinearResponse {
  double stiffness;  ///< [N/m]
  double offset;     ///< [N]
};

/// The displacement [m] at which the contact's response meets the constraint's held value.
/// a_u u + a_F (K u - C) = h  =>  u = (h + a_F C) / (a_u + a_F K). Inline: every event of
/// both engines solves it.
inline double displacement_under(const AffineConstraint& c, const LinearResponse& r,
                                 double held_value) {
  return (held_value + c.force_coefficient * r.offset) /
         (c.displacement_coefficient + c.force_coefficient * r.stiffness);
}

/// The held value that puts the axis at `displacement` [m].
inline double held_value_at(const AffineConstraint& c, const LinearResponse& r,
                            double displacement) {
  return c.displacement_coefficient * displacement +
         c.force_coefficient * (r.stiffness * displacement - r.offset);
}

/// What the engine asks of a machine axis, answered from its constraint alone (the one home of
/// these rules; AxisController answers the same for its constraint()).
/// Fixed load: a_u = 0, the held value is the force, and the indenter moves at constant force
/// as springs let go (it separates or slides away once nothing holds it).
inline bool holds_force(const AffineConstraint& c) { return c.displacement_coefficient == 0.0; }
/// Compliant: both coefficients positive, the machine end (the held value) drives the indenter
/// through a spring of stiffness 1 / a_F; the machine's work is done at that end.
inline bool drives_through_spring(const AffineConstraint& c) {
  return c.displacement_coefficient > 0.0 && c.force_coefficient > 0.0;
}
/// Fixed grips: a_F = 0, the held value is the indenter's own displacement.
inline bool is_fixed_grips(const AffineConstraint& c) { return c.force_coefficient == 0.0; }

/// Required: constraint() and held_value_key(). Optional: the questions below, which default to
/// the answers of constraint() (a controller may answer them without building it).
class AxisController {
 public:
  virtual ~AxisController() = default;

  /// Required: the constraint's coefficients.
  virtual AffineConstraint constraint() const = 0;

  /// Required: the scene key of the value it holds on the tangential axis
  /// ("displacement" [m] or "force" [N]).
  virtual std::string_view held_value_key() const = 0;
  /// The unit of that value: "m" for a displacement, "N" for a force, "SI" for another key.
  const char* held_value_unit() const {
    const std::string_view key = held_value_key();
    return key == "force" ? "N" : key == "displacement" ? "m" : "SI";
  }

  /// Optional: whether the held value is the force (fixed load).
  virtual bool holds_force() const { return mdrsim::holds_force(constraint()); }
  /// Optional: whether the machine drives the indenter through a spring (compliant).
  virtual bool drives_through_spring() const { return mdrsim::drives_through_spring(constraint()); }
  /// Optional: whether the held value is the indenter's displacement itself (fixed grips).
  virtual bool is_fixed_grips() const { return mdrsim::is_fixed_grips(constraint()); }
};

}  // namespace mdrsim
