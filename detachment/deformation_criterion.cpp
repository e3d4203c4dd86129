// The deformation criterion (paper eq. 38) and its closed-form let-go.
#include "detachment/deformation_criterion.hpp"

namespace mdrsim {

double DeformationCriterion::margin(const BoundarySpring& s) const {
  return hess_elongation_limit(p_, s.contact_radius) -
         std::hypot(s.elongation, s.tangential_displacement);
}

std::optional<double> DeformationCriterion::critical_elongation(double a, double ux) const {
  const double squared = scales_.hess_squared(a) - ux * ux;
  return squared > 0.0 ? std::sqrt(squared) : 0.0;
}

}  // namespace mdrsim
