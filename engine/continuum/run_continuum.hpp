// The continuum route for the shorthand: the run's result from the branch, with no spring row.
#pragma once

#include <cstdint>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The shorthand's pull-off on the continuum branch (docs/continuum.md): status, critical
/// point, peak, stages, jumps and work, each to `rtol` with its estimate in `accuracy`.
/// Emits preload_reached and tangential_applied, and `samples` points of the followed branch
/// as `sample` events (none below 2); the caller emits the closing events.
RunResult run_continuum(const Scene& scene, double rtol, std::int64_t samples,
                        const ObserverList& observers);

}  // namespace mdrsim
