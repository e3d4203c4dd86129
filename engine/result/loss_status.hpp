// How a run ends where the contact is lost: the status decided from the cascade that lost it,
// one rule for the pull-off loop (pull_off.cpp) and the program engine (program_runner.cpp).
#pragma once

#include <cstdint>

#include "engine/events/event.hpp"

namespace mdrsim {

/// A last spring carrying less than this share of the run's force scale peels off smoothly.
inline constexpr double kNegligibleForce = 1e-3;

/// The cascade that lost the contact, from the last equilibrium before it.
struct LossCascade {
  std::int64_t changes = 0;         ///< spring changes at that one value of the control
  std::int64_t springs_before = 0;  ///< springs in contact at the last equilibrium
  double force_before = 0.0;        ///< the normal force there [N]
  /// The run's force scale (ZeroScale::contact_force), decided from the scene, the same for
  /// every row of a resolution sequence and every zoom [N]. Not the row's own largest |F|: a
  /// zoomed row's is the force at its narrow top, and where the let-go stretch stays finite
  /// as a -> 0 (F ~ a near the end) its last spring carries a fixed share of it whatever the
  /// zoom, so its smooth peel would read as a jump.
  double force_scale = 0.0;
  bool first_by_shear = false;   ///< the first change broke a spring at zero stretch
  bool second_by_shear = false;  ///< the first change due after it did
  /// Every change after the first was due at the held value only up to its rounding, on a
  /// branch that fell before: the control did not turn (a tie where d is flat to the bit),
  /// as the continuum route reads a control that stops falling by no more than its rounding.
  bool flat = false;
};

/// The last spring let go on its own (one change), carrying next to no force (below
/// kNegligibleForce of the run's force scale), or the springs left went together at a held
/// value that did not turn (`flat`): the contact peeled off smoothly and nothing jumped. (A
/// last spring that still carries a finite tension jumps off; in the continuum a smooth peel
/// ends at F -> 0, which the row approaches as x_1 -> 0. Where g sinks below the rounding of
/// the let-go stretch, the row's let-go values tie and its last springs go together, while
/// the continuum's control keeps falling.)
bool peels_smoothly(const LossCascade& c);

/// Shear-off where the spring that decides broke at zero stretch (the second change of a
/// jump, the first of a single let-go), else no instability for a smooth peel, else
/// instability.
RunStatus loss_status(const LossCascade& c);

}  // namespace mdrsim
