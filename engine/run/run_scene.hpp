// A scene run as its [discretization] asks: a row, Richardson across rows, or rtol.
#pragma once

#include <cstdint>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs the scene and emits its events (observers see the finest row).
/// - `springs` alone: one row; its last equilibrium is the critical point.
/// - `springs` with `extrapolation = "richardson"`: rows of N/2, N and 2N springs; the
///   critical point is 2 Q(2N) - Q(N) of their ends located between springs
///   (fold_refinement.hpp), which removes the row's O(1/N) error, and
///   |R(2N) - R(N)| over the three rows is its error estimate.
/// - `rtol`: adaptive_resolution.hpp.
/// Warnings go to the result and to the log.
RunResult run_scene(const Scene& scene, const ObserverList& observers);

/// As above, with `samples` points of the continuum route's branch as `sample` events in
/// place of scene.solver.samples: for a caller that shares the scene, built once (Python).
RunResult run_scene(const Scene& scene, const ObserverList& observers, std::int64_t samples);

}  // namespace mdrsim
