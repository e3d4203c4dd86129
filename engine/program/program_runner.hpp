// One row of a loading program: stages driven in their parameter, events located exactly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

#include "engine/base/zero_scale.hpp"
#include "engine/events/observer.hpp"
#include "engine/program/program_row.hpp"
#include "engine/result/run_result.hpp"
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

/// The last stage's start on a row, and whether a row glued afresh across a smaller radius
/// reaches that stage's critical point exactly (the zoom of program_zoom.hpp): the stage runs
/// until separation, nothing rebinds or glues in it, every spring in contact is glued (no
/// pressed springs, whose normal force the smaller row would miss) and all carry one
/// tangential offset. Then the state of a contact of radius a depends only on the held values
/// and the springs inside a, as on the shorthand's pull-off.
struct LastStageStart {
  bool zoomable = false;
  std::size_t stage = 0;  ///< its index in scene.program->stages
  MachineAxis normal;     ///< the machine at the stage's start, after its controller switch
  MachineAxis tangential;
  double offset = 0.0;       ///< the glued springs' one tangential offset s [m]
  std::int64_t springs = 0;  ///< springs glued (and in contact) at the start
  /// The most tensile normal force before the stage [N] (+inf: none): a peak below it lies
  /// in the stage.
  double peak_before = std::numeric_limits<double>::infinity();
  /// Where the stage lost `zoomable` at the end of a cascade (a spring left pressed, or glued
  /// anew): the state that cascade began at. A cascade that begins at the row's critical point
  /// loses nothing the zoom needs (a glue sheared off under compression leaves its springs
  /// pressed only after it): what follows the critical point is not zoomed.
  std::optional<ContactSnapshot> lost_after;

  /// Whether the stage kept the zoom's conditions up to `critical`, the row's critical point.
  bool zoomable_to(const ContactSnapshot& critical) const {
    return zoomable ||
           (lost_after && lost_after->springs_in_contact == critical.springs_in_contact &&
            lost_after->normal_control == critical.normal_control &&
            lost_after->tangential_displacement == critical.tangential_displacement);
  }
};

/// A row that starts at a program's last stage, glued on all its springs with one offset and
/// the machine as the stage started on a full row (LastStageStart).
struct ZoomedStart {
  std::size_t stage = 0;
  MachineAxis normal;
  MachineAxis tangential;
  double offset = 0.0;
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
  /// A zoomed row: it starts at this stage, glued across its reference radius.
  std::optional<ZoomedStart> zoomed;
};

/// Runs every stage of scene.program on one row. Emits every event but `finished`.
RunResult run_program_row(const Scene& scene, const ProgramRowSpec& row,
                          const ObserverList& observers, LargestContact* largest = nullptr,
                          LastStageStart* last_stage = nullptr);

}  // namespace mdrsim
