// Hutchinson-Suo mode-dependent toughness: Gamma(psi) = 2 pi a dgamma (1 + tan^2((1-lambda) psi)).
#pragma once

#include "detachment/criterion.hpp"

namespace mdrsim {

/// lambda = 1 is the mode-mixed criterion, lambda = 0 the normal-only one. No closed-form
/// let-go: the engine root-finds the margin, which exercises that path for user criteria.
class ModeDependentCriterion final : public DetachmentCriterion {
 public:
  ModeDependentCriterion(const InterfaceProperties& properties, double lambda);
  double margin(const BoundarySpring& spring) const override;

 private:
  InterfaceProperties p_;
  double lambda_;  ///< mode sensitivity in [0, 1]
};

}  // namespace mdrsim
