// A scene run as its [discretization] asks: springs chosen for rtol, Richardson across rows.
#pragma once

#include <cstdint>

#include "engine/observer.hpp"
#include "engine/pull_off.hpp"
#include "engine/scene.hpp"

namespace mdrsim {

/// Runs the scene. With `rtol` the springs come from springs_for_rtol; with `richardson`
/// the critical point is 2 Q(2N) - Q(N) of the folds of rows of N and 2N springs, which
/// removes the row's O(1/N) error (second order). Observers see the finest run only.
RunResult run_scene(const Scene& scene, const ObserverList& observers);

/// The springs for relative accuracy `rtol` of the critical normal force, from the row's
/// known convergence: the plain row's error is C/N + a quantization of at most half the
/// force change per spring at the fold, S/N; the extrapolated one's is C2/N^2. C, S and C2
/// are measured on pilot rows of 1024, 2048 (and 4096) springs, and a factor 1.15 keeps
/// the result inside rtol. Pilot events are added to `counts`.
std::int64_t springs_for_rtol(const Scene& scene, double rtol, bool richardson, RunCounts& counts);

}  // namespace mdrsim
