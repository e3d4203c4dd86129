// The continuum route for the shorthand with finite-range adhesion (Maugis-Dugdale): the run's
// result from the Dugdale path, with no spring row.
#pragma once

#include <cstdint>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The shorthand's pull-off on the Dugdale path (docs/maugis.md): status, critical point (the
/// last equilibrium before the first fold of the normal control), peak adhesion, the preload
/// and pull-off stages with their work, the jump, each to `rtol` with its estimate in
/// `accuracy`. Emits preload_reached and `samples` states of the path as `sample` events (none
/// below 2); the caller emits the closing events. The scene has material.finite_range() and
/// no tangential load.
RunResult run_dugdale_continuum(const Scene& scene, double rtol, std::int64_t samples,
                                const ObserverList& observers);

}  // namespace mdrsim
