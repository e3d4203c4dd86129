// A run-time check of what both engines assume of a detachment criterion (criterion.hpp):
// a margin non-increasing in the elongation, and a convex set of holding states.
#pragma once

#include <string_view>

#include "detachment/criterion.hpp"

namespace mdrsim {

/// Samples the criterion at radii a, a/4 and a/16 [m] on a grid of elongations and tangential
/// displacements in its own scales (the Hess elongation sqrt(2 pi a dgamma / E*) and that
/// times sqrt(E*/G*)): the margin must not rise with the elongation, and the midpoint of two
/// holding states must hold. Throws std::runtime_error naming the criterion `name` and the
/// first state that breaks either, rather than letting the engine return a wrong let-go.
/// About 6000 margins per radius.
void sample_criterion_contract(const DetachmentCriterion& criterion, std::string_view name,
                               const Material& material, double radius);

/// What a run checks, once: nothing for a criterion that proves the contract
/// (DetachmentCriterion::proves_contract: every built-in), else sample_criterion_contract.
void check_criterion_contract(const DetachmentCriterion& criterion, std::string_view name,
                              const Material& material, double radius);

}  // namespace mdrsim
