// The critical stress criterion: the spring's stress vector reaches E* dl(a).
#include "detachment/stress_criterion.hpp"

namespace mdrsim {

double StressCriterion::margin(const BoundarySpring& s) const {
  return p_.effective_modulus * hess_elongation_limit(p_, s.contact_radius) -
         std::hypot(p_.effective_modulus * s.elongation,
                    p_.effective_shear_modulus * s.tangential_displacement);
}

std::optional<double> StressCriterion::critical_elongation(double a, double ux) const {
  const double shear = scales_.shear_ratio * ux;
  const double squared = scales_.hess_squared(a) - shear * shear;
  return squared > 0.0 ? std::sqrt(squared) : 0.0;
}

}  // namespace mdrsim
