// The engine loop: preload, tangential load, then advance the chosen method to the instability.
#pragma once

#include <cstdint>
#include <optional>

#include "controllers/controller.hpp"
#include "engine/base/zero_scale.hpp"
#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// One row of springs: `springs` springs across `outer_radius`. A row narrower than the
/// glued radius (a zoomed row) stands for the glued contact after every spring outside it
/// has let go, which is exact for the irreversible path: those springs carry nothing.
/// The machine a row starts from where it is not the shorthand's preload and tangential load:
/// a program's last stage (program_zoom.cpp), every spring glued at zero offset.
struct MachineStart {
  AffineConstraint normal;
  double normal_held;  ///< [m or N]
  AffineConstraint tangential;
  double tangential_held;  ///< [m or N]
};

struct RowSpec {
  std::int64_t springs = 0;
  double outer_radius = 0.0;  ///< [m]
  bool zoomed = false;        ///< outer_radius < the glued radius: emits no preload events
  /// Where given, the row starts from this machine instead (with `zoomed`: no path, no
  /// preload events), and the pull-off loop peels it as the held normal value falls.
  std::optional<MachineStart> start;
  /// Record the path's stages, jumps and work (shorthand_path.hpp): for the row a run reports,
  /// not for the rows it only compares (a few ns per let-go).
  bool record_path = false;
  /// What is zero in the run, and its force scale (the status's, loss_status.hpp): the
  /// shorthand's (shorthand_zero_scale) where not given; a program's last stage brings its own.
  std::optional<ZeroScale> zero;
};

/// What is zero on the shorthand's rows (zero_scale.hpp): its glued radius, its image there and
/// its preload force, as program_zero_scale gives it for a program's frame. From the scene
/// alone: every row and zoom of a run draws the same lines.
ZeroScale shorthand_zero_scale(const Scene& scene);

/// Runs one row and returns its status and row detail (critical, peak, refined points).
/// Emits every event of the row but `instability` and `finished`, which the caller emits
/// once it has combined its rows.
RunResult run_row(const Scene& scene, const RowSpec& row, const ObserverList& observers);

/// Runs the scene on one row of `springs` springs across the glued radius (scene.springs
/// when not given) and emits every event, `finished` included. Numerical outcomes are
/// statuses; an exception means a faulty part.
RunResult run_pull_off(const Scene& scene, const ObserverList& observers);
RunResult run_pull_off(const Scene& scene, std::int64_t springs, const ObserverList& observers);

/// Emits the closing events of a run (instability where there is a critical point, finished).
void emit_closing_events(const RunResult& result, const ObserverList& observers);

}  // namespace mdrsim
