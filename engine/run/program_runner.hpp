// One row of a loading program: stages driven in their parameter, events located exactly.
#pragma once

#include <cstdint>

#include "engine/base/zero_scale.hpp"
#include "engine/events/observer.hpp"
#include "engine/model/program_row.hpp"
#include "engine/run/pull_off.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Where the contact was largest on a row: at its deepest indentation, where the front is
/// furthest out. What fixes the row of the final run.
struct LargestContact {
  std::int64_t most_springs = 0;  ///< the most springs in contact on the whole path
  std::int64_t springs = 0;       ///< springs in contact m at the deepest indentation
  double indentation = 0.0;       ///< the deepest indentation in contact [m]
  bool glued_edge = false;        ///< spring m was glued there (the advancing front), not pressed
  AffineConstraint normal_constraint{1.0, 0.0};  ///< the normal machine there
  double normal_held = 0.0;                      ///< its held value there [m or N]
};

struct ProgramRowSpec {
  double reference_radius = 0.0;       ///< a_ref: spring N sits there [m]
  std::int64_t reference_springs = 0;  ///< N
  double reference_image = 0.0;        ///< g at spring N (see ProgramRow)
  std::int64_t max_springs = 0;        ///< the row ends here: the run stops if it needs more
  bool edge_forces = false;  ///< snapshots carry the edge springs' forces (rtol's estimates)
  /// Event method: the reported states also located between springs (program_front.hpp),
  /// for extrapolation across rows.
  bool refine = false;
  /// What is zero on this row: the same for every row of a resolution sequence.
  ZeroScale zero;
};

/// Runs every stage of scene.program on one row. Emits every event but `finished`.
RunResult run_program_row(const Scene& scene, const ProgramRowSpec& row,
                          const ObserverList& observers, LargestContact* largest = nullptr);

}  // namespace mdrsim
