// How a run ends where the contact is lost: the status decided from the cascade that lost it,
// one rule for the pull-off loop (pull_off.cpp) and the program engine (program_runner.cpp).
#pragma once

#include <cstdint>

#include "engine/events/event.hpp"

namespace mdrsim {

/// A last spring carrying less than this share of the path's largest |F| peels off smoothly.
inline constexpr double kNegligibleForce = 1e-3;

/// The cascade that lost the contact, from the last equilibrium before it.
struct LossCascade {
  std::int64_t changes = 0;         ///< spring changes at that one value of the control
  std::int64_t springs_before = 0;  ///< springs in contact at the last equilibrium
  double force_before = 0.0;        ///< the normal force there [N]
  double largest_force = 0.0;       ///< the largest |F| on the path up to it [N]
  bool first_by_shear = false;      ///< the first change broke a spring at zero stretch
  bool second_by_shear = false;     ///< the first change due after it did
};

/// The last spring let go on its own (one change), carrying next to no force: the contact
/// peeled off smoothly to zero force and nothing jumped. (A last spring that still carries a
/// finite tension jumps off; in the continuum a smooth peel ends at F -> 0, which the row
/// approaches as x_1 -> 0.)
bool peels_smoothly(const LossCascade& c);

/// Shear-off where the spring that decides broke at zero stretch (the second change of a
/// jump, the first of a single let-go), else no instability for a smooth peel, else
/// instability.
RunStatus loss_status(const LossCascade& c);

}  // namespace mdrsim
