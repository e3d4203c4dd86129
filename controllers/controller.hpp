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

/// Required: constraint() and held_value_key().
class AxisController {
 public:
  virtual ~AxisController() = default;

  /// Required: the constraint's coefficients.
  virtual AffineConstraint constraint() const = 0;

  /// Required: the scene key of the value it holds on the tangential axis
  /// ("displacement" [m] or "force" [N]).
  virtual std::string_view held_value_key() const = 0;
};

}  // namespace mdrsim
