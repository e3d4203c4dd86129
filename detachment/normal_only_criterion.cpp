// The rule of Hess alone (paper eq. 12): the tangential displacement plays no part.
#include "detachment/normal_only_criterion.hpp"

namespace mdrsim {

double NormalOnlyCriterion::margin(const BoundarySpring& s) const {
  return hess_elongation_limit(p_, s.contact_radius) - s.elongation;
}

std::optional<double> NormalOnlyCriterion::critical_elongation(double a, double) const {
  return std::sqrt(scales_.hess_squared(a));
}

}  // namespace mdrsim
