// The size a --trajectory file will have, estimated before the run, and the warning it earns.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/scene/scene.hpp"

namespace mdrsim::cli {

/// Files above this size are announced before the run starts [bytes] (1 GB).
inline constexpr double kLargeTrajectoryBytes = 1e9;

struct TrajectoryEstimate {
  double rows = 0.0;           ///< ordinary rows written (after the stride)
  double bytes_per_row = 0.0;  ///< a typical row of this scene, as the writer formats it
  double bytes = 0.0;          ///< rows * bytes_per_row, with the header
};

/// Each spring lets go once in the shorthand's pull-off and may glue and let go once per
/// stage in a program: springs * stages events, of which every `stride`-th is written. A
/// typical row has every nonzero value at full precision (tangential columns are 0 without
/// tangential loading). An estimate of the order of the size, not a bound: steps, halvings
/// and cascades add rows, and rtol may choose more springs than the scene starts with.
TrajectoryEstimate estimate_trajectory(const Scene& scene, std::int64_t stride);

/// The warning for a trajectory estimated above kLargeTrajectoryBytes, naming the estimate
/// and --trajectory-stride; nullopt for a smaller one.
std::optional<std::string> large_trajectory_warning(const Scene& scene, std::int64_t stride);

}  // namespace mdrsim::cli
