// Richardson and rtol on the viscoelastic row: its O(1/N) error (the row's sum over springs
// beside the continuum's integral) removed across rows of doubling springs.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Rows of N/4, N/2, N and 2N springs (engine/program/run_viscoelastic_program.hpp): each
/// stage's end force and time, its works (normal, dissipated_by_bulk) and energy terms, the
/// peak tension and the total work extrapolated from the two finer rows, Q = 2 Q_2N - Q_N
/// ((4 Q_2N - Q_N) / 3 for a time whose changes fall by 4, a contact lost at zero force on a
/// parabola), each with twice the larger change of the last two extrapolations as its estimate
/// (the energy terms, so that the balance still closes, and the indentations, which follow the
/// times under fixed grips, without one of their own). The critical point is combined the same
/// way (force, depth, radius, time; the stage that ended at it ends there) where every row
/// located it between springs (engine/program/viscoelastic_fold.hpp); else it sits on the same
/// spring of every row and stays the finest row's, with the stage end times of the run.
/// `accuracy.covers` names the estimated values; the rest (springs in contact, the jumps, the
/// peak's state) is the finest row's. Rows that end differently (status, stages, critical
/// point, peak) report the finest row as it is, with a warning. Emits the finest row's events.
RunResult run_viscoelastic_richardson(const Scene& scene, const ObserverList& observers);

/// Rows of 256, 512, ... springs until every estimate above meets rtol max(|Q|, floor) (the
/// floor the path's largest force for a force, the program's duration for a time, the stages'
/// summed works for a work); with extrapolation = "none" the finest row's own values with the
/// larger of |Q_2N - Q_N| and |Q_N - Q_N/2| / 2 as their estimate. The row is exact in time
/// (each spring's arms advance in closed form, events are roots to the last bits), so these
/// are the run's whole estimates, but for the rounding of the located critical point, which
/// grows with the springs: where it alone takes what rtol allows, the critical point is left
/// out of covers with a warning and the rest is held to rtol. Past
/// discretization.max_row_springs it reports the finest rows with rtol_met false and a warning.
/// Emits the finest row's events.
RunResult run_viscoelastic_rtol(const Scene& scene, double rtol, const ObserverList& observers);

}  // namespace mdrsim
