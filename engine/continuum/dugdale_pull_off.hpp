// The continuum route's pull-off with finite-range adhesion (Maugis-Dugdale): the fold of the
// machine's control along the contact branch and, once the contact has closed, the zone's own.
#pragma once

#include "engine/model/dugdale_zone.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// Where a contact glued at radius a_g, unloaded, leaves its branch.
struct DugdalePullOff {
  /// The last equilibrium before the jump; with no jump, the state where the contact ends.
  DugdaleState critical;
  bool instability = true;  ///< false: the zone shrinks to nothing without a jump
};

/// Fixed load: F falls along the contact branch from a_g while dF/da > 0; the pull-off is its
/// first minimum going down, or the closing point (a = 0, c = c0) where F still falls there
/// (the no-contact branch's F = -pi sigma_0 c^2 only rises as c shrinks).
DugdalePullOff dugdale_fixed_load_pull_off(const Profile& profile, const DugdaleLaw& law,
                                           double glued_radius);

/// Fixed grips: d falls along the contact branch while dd/da > 0; the jump is at its first
/// minimum going down; where the contact closes first, d(c) = f(c) - 4 sigma_0 c/(pi E*) - h0
/// of the no-contact branch folds where f'(c) = 4 sigma_0/(pi E*), or not at all (a cone with
/// sigma_0/(E* tan(theta)) < pi/4 peels to c -> 0: no instability).
DugdalePullOff dugdale_fixed_grips_pull_off(const Profile& profile, const DugdaleLaw& law,
                                            double glued_radius);

}  // namespace mdrsim
