// The disk check of a run's reported states: each state's disk_valid, the run's, a warning.
#pragma once

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Checks every reported state with a contact (critical point, peak, stage ends, jumps'
/// critical points and after-states) against engine/model/disk_validity: sets each state's
/// disk_valid and the run's, and warns once, naming the worst state, its radius and what
/// failed. Nothing to do for a profile that proves it (Profile::proves_one_disk).
/// Springs pressed without glue are checked for pressure in non-adhesive scenes (every spring
/// in contact is pressed there); glued springs carry tension by design.
void check_disk_states(const Scene& scene, RunResult& result);

}  // namespace mdrsim
