// Runs a loading program: a pilot row finds the largest contact, the final row spans it.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/run/pull_off.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs scene.program (which must be set) on scene.springs springs across the largest
/// contact radius the program reaches (SPEC "Discretization"), and emits every event but
/// `finished`.
RunResult run_program(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
