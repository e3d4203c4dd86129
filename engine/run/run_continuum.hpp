// The continuum route for the shorthand: the run's result from the branch, with no spring row.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The shorthand's pull-off on the continuum branch (docs/continuum.md): status, critical
/// point, peak, stages, jumps and work, each to `rtol` with its estimate in `accuracy`.
/// Emits preload_reached and tangential_applied; the caller emits the closing events.
RunResult run_continuum(const Scene& scene, double rtol, const ObserverList& observers);

}  // namespace mdrsim
