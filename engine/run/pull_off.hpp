// The engine loop: preload, tangential load, then advance the chosen method to the instability.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/events/event.hpp"
#include "engine/events/observer.hpp"
#include "engine/methods/run_counts.hpp"
#include "engine/run/program_records.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// How a run reached its reported numbers: the rows it ran and how it combined them.
struct Accuracy {
  enum class Route { row, richardson };
  Route route = Route::row;
  /// The springs of every row whose results entered the reported numbers, finest last.
  std::vector<std::int64_t> rows;
  /// The radius the reported rows span [m]: the glued radius, or less where the rows were
  /// zoomed onto the critical point (adaptive_resolution.hpp).
  double outer_radius = 0.0;
  /// An a posteriori bound on |reported - continuum| critical normal force [N], from the
  /// differences of the rows actually run; empty for a single plain row.
  std::optional<double> critical_error_estimate;
  std::optional<double> peak_error_estimate;  ///< the same for the peak adhesive force [N]
  /// Programs: the same for the total work per axis [J] (each stage's is in its record).
  std::optional<AxisWork> work_error_estimate;
  bool rtol_met = true;  ///< with rtol: every estimate of `covers` is within it
  /// The reported numbers the estimates (and rtol) cover, as JSON paths; empty: the
  /// critical and the peak normal force (the shorthand's).
  std::vector<std::string> covers;
};

struct RunResult {
  RunStatus status = RunStatus::instability;
  /// The last equilibrium before the loss of contact: present for `instability` and for a
  /// `shear-off` during the pull-off, absent where no such equilibrium exists (a shear-off
  /// as the tangential load is applied, a smooth peel, the step limit).
  std::optional<ContactSnapshot> critical;
  /// The most tensile equilibrium on the path from the preload to the critical point: what
  /// an experiment under displacement control reads as the pull-off force.
  std::optional<ContactSnapshot> peak;
  /// A shear-off as the tangential load is applied: the largest tangential force the glued
  /// contact could carry at its normal state [N].
  std::optional<double> tangential_strength;

  /// Row detail used to combine rows (run_scene.hpp): the critical point and the peak of
  /// the row's branch located between springs (fold_refinement.hpp), where the row's end is
  /// smooth enough for that; else empty.
  std::optional<ContactSnapshot> refined_critical;
  std::optional<ContactSnapshot> refined_peak;
  /// Springs in contact at the first equilibrium of the unbroken run of single let-gos that
  /// ends at the critical point: the zoom may restart anywhere in that run.
  std::int64_t stable_run_top = 0;
  /// How far above the radius where the glue shears off unstretched the row's branch folds,
  /// in spacings, where the two lie close (status_margin.hpp): the status of a row with a
  /// fold closer than kStatusSpacings may change with its resolution.
  std::optional<double> fold_above_shear_off;

  /// Loading programs: every stage's end and work, every jump, and the total work.
  std::vector<StageRecord> stages;
  std::vector<JumpRecord> jumps;
  std::optional<AxisWork> work;
  /// The run ended with a held tangential force that nothing held any more: the indenter
  /// slides away (a jump's end is JumpEnd::sliding, or the glue's last spring let go alone).
  bool sliding = false;
  /// The stage the critical point belongs to (programs); empty for the shorthand's pull-off.
  std::string critical_stage;

  Accuracy accuracy;
  std::vector<std::string> warnings;  ///< what the run cannot vouch for, one line each
  RunCounts counts;
  double wall_time_s = 0.0;
  std::int64_t springs = 0;  ///< springs of the finest row run (one half)
};

/// One row of springs: `springs` springs across `outer_radius`. A row narrower than the
/// glued radius (a zoomed row) stands for the glued contact after every spring outside it
/// has let go, which is exact for the irreversible path: those springs carry nothing.
struct RowSpec {
  std::int64_t springs = 0;
  double outer_radius = 0.0;  ///< [m]
  bool zoomed = false;        ///< outer_radius < the glued radius: emits no preload events
  /// Record the path's stages, jumps and work (shorthand_path.hpp): for the row a run reports,
  /// not for the rows it only compares (a few ns per let-go).
  bool record_path = false;
};

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
