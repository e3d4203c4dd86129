// What a run reports: its status, critical point, peak, program records, accuracy and counts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/events/event.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/result/program_records.hpp"
#include "engine/result/run_counts.hpp"
#include "engine/result/stop_reason.hpp"

namespace mdrsim {

/// How a run reached its reported numbers: the rows it ran and how it combined them.
struct Accuracy {
  /// row: one spring row; richardson: extrapolated across rows; continuum: no springs, the
  /// continuum branch's root searches (docs/continuum.md).
  enum class Route { row, richardson, continuum };
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
  /// Programs under rtol whose critical point was refined on zoomed rows of its own
  /// (program_zoom.hpp): their radius [m] and springs; `rows` and `outer_radius` are the path's.
  struct CriticalZoom {
    double outer_radius = 0.0;
    std::vector<std::int64_t> rows;
  };
  std::optional<CriticalZoom> critical_zoom;
  /// The reported numbers the estimates (and rtol) cover, as JSON paths; empty: the
  /// critical and the peak normal force (the shorthand's).
  std::vector<std::string> covers;
};

struct RunResult {
  RunStatus status = RunStatus::instability;
  /// Why the run stopped: present exactly when `status` is step_limit.
  std::optional<StopReason> stop_reason;
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
  /// How far the rounding of the row's own numbers can move each field of refined_critical
  /// where that grows with the springs (a viscoelastic row's fold, viscoelastic_fold.hpp);
  /// else every field 0.
  ContactSnapshot refined_critical_rounding{};
  /// Springs in contact at the first equilibrium of the unbroken run of single let-gos that
  /// ends at the critical point: the zoom may restart anywhere in that run.
  std::int64_t stable_run_top = 0;
  /// How far above the radius where the glue shears off unstretched the row's branch folds,
  /// in spacings, where the two lie close (status_margin.hpp): the status of a row with a
  /// fold closer than kStatusSpacings may change with its resolution.
  std::optional<double> fold_above_shear_off;
  /// Every reported state is one contact disk (ContactSnapshot::disk_valid).
  bool disk_valid = true;

  /// Loading programs: every stage's end and work, every jump, and the total work.
  std::vector<StageRecord> stages;
  std::vector<JumpRecord> jumps;
  std::optional<AxisWork> work;
  /// The sum of the stages' energy balances (program rows).
  std::optional<EnergyBalance> energy;
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

/// Ends a run at a limit: status step_limit, and why.
inline void stop_at_limit(RunResult& r, StopReason why) {
  r.status = RunStatus::step_limit;
  r.stop_reason = why;
}

}  // namespace mdrsim
