// One row of a sweep as a scene, for `mdrsim sweep` and mdrsim.sweep alike: the varied keys
// set to the row's values, and the check of every key's values before any run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/output/sweep_csv.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_document.hpp"
#include "engine/sweep/sweep_grid.hpp"

namespace mdrsim::cli {

/// Sets every varied key to its value in `values` (one per key, as SweepGrid::values gives a
/// row's) and builds the scene; a SceneError names --vary for the varied keys.
Scene build_row(SceneDocument& document, const SweepGrid& grid,
                const std::vector<VaryValue>& values, const Registries& registries);

/// Builds the grid's probe rows (SweepGrid::probe_rows: the first row with each value of each
/// key), so that a bad value fails before any run; returns the columns any of these scenes
/// has: JKR scales (the dimensionless columns), friction, a program (the work columns).
SweepColumns check_values(const SceneDocument& base, const SweepGrid& grid,
                          const Registries& registries);

/// Row `row` of the grid run to its CSV line: built, run and checked finite; the run's log
/// lines (its warnings, progress) are labelled "row R of M (key=value, ...)" (run_label.hpp),
/// R the row's index in the whole grid (a shard's rows keep theirs), the values as the CSV
/// writes them.
std::string run_row(SceneDocument& document, const SweepGrid& grid, std::uint64_t row,
                    const Registries& registries, SweepColumns columns);

}  // namespace mdrsim::cli
