// The shorthand's pull-off on the continuum branch: folds, landings, the critical point, the peak.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "engine/continuum/continuum_branch.hpp"

namespace mdrsim {

/// A jump from a fold to where the branch's control value comes back down to the fold's:
/// the contact shrinks and stays.
struct ContinuumJump {
  BranchState from;
  BranchState to;
};

/// Where the pull-off of a contact glued at radius a_g ends, and what it passed on the way.
struct ContinuumPullOff {
  enum class End {
    fold,                      ///< the jump that empties the contact starts at a fold below a_g
    first_detachment,          ///< the control rises at once: the jump starts at a_g
    shear_off,                 ///< the control falls all the way to a_s, where e = 0
    shear_off_at_application,  ///< the tangential load alone breaks the glue at a_g
    smooth_peel,               ///< no fold and no a_s: the control falls to a -> 0
  };
  End end = End::smooth_peel;
  /// The last equilibrium before the jump that empties the contact (fold, first_detachment,
  /// shear_off); the smallest radius scanned for a smooth peel.
  BranchState critical;
  double critical_error = 0.0;      ///< a bound on |critical F - continuum F| [N]
  std::optional<BranchState> peak;  ///< the most tensile equilibrium from a_g to `critical`
  double peak_error = 0.0;          ///< [N]
  std::vector<ContinuumJump> partial_jumps;
  /// The stable stretches of the branch the path follows, as (from, to) radii, from > to [m].
  std::vector<std::pair<double, double>> segments;
  double tangential_strength = 0.0;  ///< shear_off_at_application: 2 G* a_g u_max [N]
};

/// Scans the branch from a_g down (geometric in a - a_s over 14 decades, `per_decade`
/// samples a decade), refines each fold as a root of the control slope, each landing as a
/// root of the control value and each stretch's peak as a root of dF/da. A control flat to the
/// rounding of its own value has not turned (a smooth peel goes on); any real rise is a fold.
ContinuumPullOff continuum_pull_off(ContinuumBranch& branch, double glued_radius,
                                    int per_decade = 4);

}  // namespace mdrsim
