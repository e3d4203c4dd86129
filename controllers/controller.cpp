// Equilibrium on one axis: the one division that solves the constraint against the response.
#include "controllers/controller.hpp"

namespace mdrsim {

// a_u u + a_F (K u - C) = h  =>  u = (h + a_F C) / (a_u + a_F K).
double displacement_under(const AffineConstraint& c, const LinearResponse& r, double held_value) {
  return (held_value + c.force_coefficient * r.offset) /
         (c.displacement_coefficient + c.force_coefficient * r.stiffness);
}

double held_value_at(const AffineConstraint& c, const LinearResponse& r, double displacement) {
  return c.displacement_coefficient * displacement +
         c.force_coefficient * (r.stiffness * displacement - r.offset);
}

}  // namespace mdrsim
