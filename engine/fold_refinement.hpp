// The fold of the spring model's discrete branch, located between springs.
#pragma once

#include <optional>

#include "detachment/criterion.hpp"
#include "engine/contact.hpp"

namespace mdrsim {

/// The instability of the spring row starts at the spring n_c whose let-go control value
/// lambda(n) is smallest, so the critical point jumps by one spring as the resolution
/// changes: a sawtooth of O(dx) under fixed grips, where the force still varies along the
/// branch at the fold. The branch lambda(n), Q(n) of the row's own equilibria is smooth in n,
/// so the parabola through lambda at n_c + 1, n_c and the virtual next equilibrium n_c - 1
/// locates the fold between springs, and every quantity Q is interpolated there. What is
/// left is the row's smooth O(dx) error, which extrapolation across resolutions removes.
///
/// `outer` and `critical` are the saved equilibria at n_c + 1 and n_c springs; returns
/// nothing where the branch is not smooth there (a jump just before, a shear-driven
/// let-go next, fewer than two springs).
struct RefinedFold {
  ContactSnapshot state;     ///< every quantity interpolated at the fold
  double normal_force_step;  ///< |dF/dn| at the fold: the force change per spring [N]
};

std::optional<RefinedFold> refine_fold(const Contact& contact, const DetachmentCriterion& criterion,
                                       const Contact::State& outer, const Contact::State& critical);

}  // namespace mdrsim
