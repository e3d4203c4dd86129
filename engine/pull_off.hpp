// The engine loop: preload, tangential load, then advance the chosen method to the instability.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/event.hpp"
#include "engine/methods/pull_off_method.hpp"
#include "engine/observer.hpp"
#include "engine/scene.hpp"

namespace mdrsim {

struct RunResult {
  RunStatus status = RunStatus::instability;
  ContactSnapshot critical;  ///< last equilibrium before the final jump
  /// The fold of the row's branch between springs (fold_refinement.hpp); event method only,
  /// where the final jump starts at a smooth fold.
  std::optional<ContactSnapshot> fold;
  double fold_force_step = 0.0;  ///< |dF/dn| at the fold [N], with `fold`
  /// The springs of the rows whose results were combined (run_scene.hpp), finest last.
  std::vector<std::int64_t> resolutions;
  RunCounts counts;
  double wall_time_s = 0.0;
  std::int64_t springs = 0;  ///< springs of the row (one half)
};

/// Runs the scene on a row of `springs` springs (scene.springs when not given).
/// Numerical outcomes are statuses; an exception means a faulty part.
RunResult run_pull_off(const Scene& scene, const ObserverList& observers);
RunResult run_pull_off(const Scene& scene, std::int64_t springs, const ObserverList& observers);

}  // namespace mdrsim
