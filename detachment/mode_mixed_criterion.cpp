// Johnson's energy release rate criterion (paper eq. 20) and its closed-form let-go.
#include "detachment/mode_mixed_criterion.hpp"

namespace mdrsim {

double ModeMixedCriterion::margin(const BoundarySpring& s) const {
  return 2.0 * std::numbers::pi * s.contact_radius * p_.work_of_adhesion_at(s.contact_radius) -
         p_.effective_modulus * s.elongation * s.elongation -
         p_.effective_shear_modulus * s.tangential_displacement * s.tangential_displacement;
}

// Paper eq. 21: |uz| = sqrt(2 pi a dgamma / E* - G*/E* ux^2).
std::optional<double> ModeMixedCriterion::critical_elongation(double a, double ux) const {
  const double squared = scales_.hess_squared(a) - scales_.shear_ratio * ux * ux;
  return squared > 0.0 ? std::sqrt(squared) : 0.0;
}

}  // namespace mdrsim
