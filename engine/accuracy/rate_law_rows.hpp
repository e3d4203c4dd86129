// Richardson and rtol on the rate law's row: its O(1/N) error (the force's sum over the springs
// with the front between two of them) removed across rows of doubling springs.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Rows of N/4, N/2, N and 2N springs (engine/program/rate_law_row.hpp): the peak tension, each
/// stage's end force and work and the total work extrapolated from the two finer rows,
/// Q = 2 Q_2N - Q_N, each with twice the larger change of the last two extrapolations as its
/// estimate (engine/accuracy/doubling_rows.hpp). The rest (states' other fields, the critical point, the jumps, `energy`) is the
/// finest row's. Rows that end differently (status, stages, where the contact was lost) report
/// the finest row as it is, with a warning. Emits the finest row's events.
RunResult run_rate_law_richardson(const Scene& scene, const ObserverList& observers);

/// Rows of 256, 512, ... springs until every estimate above meets rtol max(|Q|, floor) (the
/// floor the path's largest force for a force, the stages' summed works for a work); with
/// extrapolation = "none" the finest row's own values with the larger of |Q_2N - Q_N| and
/// |Q_N - Q_N/2| / 2 as their estimate (its error is c / N). Past discretization.max_row_springs it reports the finest row with
/// rtol_met false and a warning. Emits the finest row's events.
RunResult run_rate_law_rtol(const Scene& scene, double rtol, const ObserverList& observers);

}  // namespace mdrsim
