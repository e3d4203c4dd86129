// rtol on programs: the critical point of a last stage that only peels a uniformly glued
// contact, refined on rows glued afresh across a radius just outside it (the shorthand's zoom).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/accuracy/row_sequence.hpp"
#include "engine/program/program_runner.hpp"
#include "engine/program/run_program.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The critical point (or the peak) as the zoomed rows give it, with its estimate.
struct ZoomedCritical {
  ContactSnapshot value;
  double estimate;  ///< [N]
  Accuracy::Route route;
  bool met;
  double outer_radius;             ///< the zoom's radius [m]
  std::vector<std::int64_t> rows;  ///< the springs of the rows combined
  RunCounts counts;                ///< every zoomed row's
  /// The critical point's zoom only: on every row combined the peak is the critical point
  /// (a fixed load's fold is its most tensile state), so that these rows resolve the peak too.
  bool holds_peak = false;
};

/// Zooms from `coarse` (a full row with its LastStageStart) onto its critical point (or its
/// peak adhesive force, where that lies in the last stage's final run of single let-gos) and
/// refines there until rtol. nullopt where the zoom does not apply (docs/programs.md
/// "Accuracy on programs"): the last stage not zoomable, no such state, a zoom gaining less
/// than 1.5x in spacing, a zoomed row that ends otherwise than the full row (or, for the peak,
/// puts it at its own outermost spring); the caller then resolves the state on full rows.
/// For the peak, `critical` is the critical point's zoom, if any: where its rows hold the peak
/// and `coarse` has its peak at its critical point, it is the peak's zoom too (no new rows).
std::optional<ZoomedCritical> zoom_program_state(const Scene& scene, const RunResult& coarse,
                                                 const LastStageStart& start, double rtol,
                                                 Target target,
                                                 const ZoomedCritical* critical = nullptr);

}  // namespace mdrsim
