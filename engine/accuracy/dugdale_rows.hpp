// The Maugis-Dugdale spring row under the scene's driver: one row, Richardson, or rtol.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The shorthand with finite-range adhesion on rows of the Dugdale spring row
/// (engine/pull_off/dugdale_row_run.hpp) across a_p, the contact branch's radius at the
/// preload depth, as scene.plan.driver says:
/// - one row of scene.springs;
/// - Richardson over rows of N/2, N and 2N: the critical point and the peak by RowSequence
///   (2 Q(2N) - Q(N), estimate from the differences), each stage's work and the preload state
///   likewise;
/// - rtol: rows of 512, 1024, ... (refine_rows, the extrapolation key or the cheaper route)
///   until the critical force's, the peak's and every work's estimates meet rtol, or the row
///   would pass discretization.max_row_springs (then rtol_met is false and a warning says so).
/// Observers see the finest row's events.
RunResult run_dugdale_rows(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
