// The engine loop: preload, tangential load, then advance the chosen method to the instability.
#pragma once

#include "engine/event.hpp"
#include "engine/methods/pull_off_method.hpp"
#include "engine/observer.hpp"
#include "engine/scene.hpp"

namespace mdrsim {

struct RunResult {
  RunStatus status = RunStatus::instability;
  ContactSnapshot critical;  ///< last equilibrium before the final jump
  RunCounts counts;
  double wall_time_s = 0.0;
};

/// Runs the scene. Numerical outcomes are statuses; an exception means a faulty part.
RunResult run_pull_off(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
