// Hutchinson-Suo toughness, written without tan so that the margin stays finite at psi = 90 deg.
#include "detachment/mode_dependent_criterion.hpp"

#include <stdexcept>

namespace mdrsim {

ModeDependentCriterion::ModeDependentCriterion(const InterfaceProperties& properties, double lambda)
    : p_(properties), lambda_(lambda) {
  if (!(lambda >= 0.0 && lambda <= 1.0)) {
    throw std::invalid_argument("lambda must lie in [0, 1]");
  }
}

// G >= Gamma_I (1 + tan^2 x) with x = (1 - lambda) psi is G cos^2 x >= Gamma_I, since
// 1 + tan^2 = 1/cos^2; tan psi = sqrt(G*/E*) ux / |uz| is the phase angle of the spring.
double ModeDependentCriterion::margin(const BoundarySpring& s) const {
  const double normal = p_.effective_modulus * s.elongation * s.elongation;
  const double shear =
      p_.effective_shear_modulus * s.tangential_displacement * s.tangential_displacement;
  const double psi = std::atan2(std::sqrt(shear), std::sqrt(normal));
  const double c = std::cos((1.0 - lambda_) * psi);
  return 2.0 * std::numbers::pi * s.contact_radius * p_.work_of_adhesion - (normal + shear) * c * c;
}

}  // namespace mdrsim
