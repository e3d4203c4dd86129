// A cascade of a program row: the spring changes at one value of the stage parameter, as the
// program loop (program_runner.cpp) records them and its parts read them.
#pragma once

#include <cstdint>
#include <optional>

#include "engine/model/contact_snapshot.hpp"
#include "engine/result/program_records.hpp"
#include "engine/scene/program.hpp"

namespace mdrsim {

/// `friction`: a spring in contact starts or stops sliding (docs/friction.md); no change of the
/// springs in contact, so no part of a jump.
enum class Change { fall_in, let_go, glue, touch, lift, friction };

/// A cascade: the changes at one value of the stage parameter after the one that was found.
struct Cascade {
  ContactSnapshot before;
  std::int64_t in_contact = 0;  ///< m before
  std::int64_t glued = 0;       ///< k before
  std::int64_t changes = 0;
  std::int64_t friction_events = 0;  ///< slips and sticks at the same parameter (no changes)
  bool second_by_shear = false;
  bool first_by_shear = false;
  std::optional<Change> first;
  /// `before` located at the fold between springs (refining rows only).
  std::optional<ContactSnapshot> refined_before;
  /// The stage parameter at `refined_before`: where the continuum jumps, which the row does
  /// at its own last spring, O(dx^2) apart.
  std::optional<double> fold_parameter;
  AxisWork work_before;  ///< the stage's work up to `before`
  /// At `before`, where the cascade may end in a flight (a held force): the stored energy,
  /// the glued surface and what the stage's changes released (StagePosition::released) [J].
  double stored_before = 0.0;
  double surface_before = 0.0;
  double released_before = 0.0;
  const Stage* stage = nullptr;  ///< the stage it happened in
  /// A shear-off cascade's fold of the let-go branch above a_s, in spacings, where one lies
  /// there (status_margin.hpp): the row cannot tell that shear-off from an instability.
  std::optional<double> fold_above_shear_off;

  /// Counts a change of the springs in contact or glued (not a fall-in, not a slip or stick);
  /// `by_shear`: a let-go broken at rest.
  void count(Change change, bool by_shear) {
    ++changes;
    if (changes == 1) {
      first_by_shear = by_shear;
      first = change;
    }
    if (changes == 2) second_by_shear = by_shear;
  }
};

}  // namespace mdrsim
