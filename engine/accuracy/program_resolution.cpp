// Accuracy on programs: rows in one frame (a_max), so that they differ only in their spacing;
// each reported state from the plain finest row or from Richardson across the last three.
#include "engine/accuracy/program_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/accuracy/path_estimates.hpp"
#include "engine/accuracy/program_zoom.hpp"
#include "engine/base/text.hpp"
#include "engine/program/run_program.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

using Extrapolation = DiscretizationOptions::Extrapolation;

constexpr std::int64_t kFirstRow = 256;

/// Whether an observer wants any event a program row gives (the closing events come after).
bool wants_row_events(const ObserverList& observers) {
  for (const EventKind kind :
       {EventKind::spring_detached, EventKind::spring_glued, EventKind::spring_touched,
        EventKind::spring_lifted, EventKind::stage_end, EventKind::jump, EventKind::step_accepted,
        EventKind::step_halved, EventKind::spring_slipped, EventKind::spring_stuck}) {
    if (observers.wants(kind)) return true;
  }
  return false;
}

ProgramRowSpec resolving_row(const Scene& scene, const ProgramRowFrame& frame,
                             std::int64_t springs) {
  ProgramRowSpec spec = program_row(scene, frame, springs);
  spec.edge_forces = true;
  spec.refine = true;
  return spec;
}

/// Each stage's constraints as the row holds them: a stage that names an axis hands it to its
/// controller, one that does not keeps the one before (both fixed grips before the first).
std::vector<StageControl> program_controls(const Scene& scene) {
  std::vector<StageControl> out;
  StageControl control;
  for (const Stage& stage : scene.program->stages) {
    if (stage.normal) control.normal = stage.normal->controller->constraint();
    if (stage.tangential) control.tangential = stage.tangential->controller->constraint();
    out.push_back(control);
  }
  return out;
}

}  // namespace

RunResult run_program_richardson(const Scene& scene, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  const std::int64_t n = scene.springs;
  std::vector<RunResult> rows;
  RunCounts counts;
  for (const std::int64_t springs : {n / 2, n, 2 * n}) {
    rows.push_back(run_program_row(scene, resolving_row(scene, frame, springs),
                                   springs == 2 * n ? observers : ObserverList{}));
    counts += rows.back().counts;
  }
  RunResult result = rows.back();
  result.counts = counts;
  result.accuracy.route = Accuracy::Route::richardson;
  result.accuracy.rows = {n / 2, n, 2 * n};
  result.accuracy.outer_radius = frame.radius;
  if (!end_alike(rows[0], rows[1]) || !end_alike(rows[1], rows[2])) {
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {} and {} springs end differently ({}); the finest row is "
        "reported as it is",
        n / 2, n, 2 * n, first_difference({{n / 2, &rows[0]}, {n, &rows[1]}, {2 * n, &rows[2]}})));
    return result;
  }
  const std::vector<std::string> plain =
      write_states(result, choose_states(rows, Extrapolation::richardson, PathStates::all),
                   PathStates::all)
          .plain;
  const std::vector<WorkChoice> works_chosen =
      choose_works(rows, Extrapolation::richardson, program_controls(scene));
  write_works(result, works_chosen);
  set_covers(result, works_chosen);
  result.accuracy.route = Accuracy::Route::richardson;
  if (!plain.empty()) {
    result.warnings.push_back(fmt::format(
        "richardson: {} could not be located between springs (springs pressed outside the "
        "glued ones, a front pinned since a jump, a shear-off): the finest row's value is "
        "reported, with its plain estimate",
        join_names(plain)));
  }
  return result;
}

RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  // The first full row also tells whether the last stage's critical point can be zoomed on.
  LastStageStart start;
  std::optional<RunResult> first =
      run_program_row(scene, resolving_row(scene, frame, kFirstRow), {}, nullptr, &start);
  const RunStatus first_status = first->status;
  RunCounts counts = first->counts;
  const std::optional<ZoomedCritical> zoomed =
      zoom_program_state(scene, *first, start, rtol, Target::critical);
  if (zoomed) counts += zoomed->counts;
  // The peak likewise where it lies in the last stage's peel (the fixed-grips pull-off's -F0).
  const std::optional<ZoomedCritical> zoomed_peak =
      zoomed ? zoom_program_state(scene, *first, start, rtol, Target::peak, &*zoomed)
             : std::nullopt;
  if (zoomed_peak) counts += zoomed_peak->counts;
  // With the critical point zoomed, the path's rows stop where the shorthand's do
  // (path_estimates.hpp): past the cap its states and works carry their estimates only.
  const std::int64_t cap = zoomed ? std::min(scene.discretization.max_row_springs,
                                             std::max(kPathRowCap, 4 * zoomed->rows.back()))
                                  : scene.discretization.max_row_springs;
  PathRefinement p = refine_path(
      kFirstRow, cap,
      [&](std::int64_t n) {
        if (first && n == kFirstRow) {
          RunResult row = std::move(*first);
          first.reset();
          row.counts = {};  // counted above
          return row;
        }
        return run_program_row(scene, resolving_row(scene, frame, n), {});
      },
      scene.discretization.extrapolation,
      zoomed_peak ? PathStates::critical_and_peak_elsewhere
      : zoomed    ? PathStates::critical_elsewhere
                  : PathStates::all,
      program_controls(scene), frame.zero, rtol);
  counts += p.counts;
  const bool zoom_applies = zoomed && p.rows.back().status == first_status;
  if (zoom_applies && !p.choices.empty()) {
    take_critical(zoomed->value, zoomed->estimate, p.choices);
    if (zoomed_peak) take_peak(zoomed_peak->value, zoomed_peak->estimate, p.choices);
  }
  // The finest row again, for its events (the rows above ran without observers), where an
  // observer wants any.
  RunResult result =
      !wants_row_events(observers)
          ? std::move(p.rows.back())
          : run_program_row(scene, resolving_row(scene, frame, p.springs.back()), observers);
  result.accuracy.route = Accuracy::Route::row;
  if (!p.choices.empty() && write_states(result, p.choices, PathStates::all).extrapolated) {
    result.accuracy.route = Accuracy::Route::richardson;
  }
  if (!p.work_choices.empty()) write_works(result, p.work_choices);
  if (std::string w = set_covers(result, p.work_choices); !w.empty()) {
    result.warnings.push_back(std::move(w));
  }
  result.counts = counts;
  result.accuracy.rows = p.rows_used();
  result.accuracy.outer_radius = frame.radius;
  result.accuracy.rtol_met = p.met;
  if (zoomed && !zoom_applies) {
    result.accuracy.rtol_met = false;
    result.warnings.push_back(fmt::format(
        "the critical point's zoomed rows end '{}', the finest full row '{}': the critical point "
        "is the full rows', and rtol does not cover it",
        to_string(first_status), to_string(result.status)));
  }
  if (zoom_applies) {
    result.accuracy.critical_zoom = Accuracy::CriticalZoom{zoomed->outer_radius, zoomed->rows};
    if (result.critical) {
      result.critical = zoomed->value;
      result.accuracy.critical_error_estimate = zoomed->estimate;
    }
    if (zoomed_peak && result.peak) {
      result.peak = zoomed_peak->value;
      result.accuracy.peak_error_estimate = zoomed_peak->estimate;
      if (!zoomed_peak->met) {
        result.accuracy.rtol_met = false;
        result.warnings.push_back(fmt::format(
            "rtol = {} not met for the peak adhesive force on zoomed rows of up to {} springs: "
            "error estimate {:.3g} relative",
            rtol, zoomed_peak->rows.back(),
            zoomed_peak->estimate / std::abs(zoomed_peak->value.normal_force)));
      }
    }
    if (!zoomed->met) {
      result.accuracy.rtol_met = false;
      result.warnings.push_back(fmt::format(
          "rtol = {} not met for the critical force on zoomed rows of up to {} springs across "
          "{:.6g} m: error estimate {:.3g} relative",
          rtol, zoomed->rows.back(), zoomed->outer_radius,
          zoomed->estimate / std::abs(zoomed->value.normal_force)));
    }
    if (!p.met) {
      // As on the shorthand: the critical force (and the peak, where its own estimate meets
      // rtol) stay covered; the path's other states and works carry their estimates.
      const auto& peak_estimate = result.accuracy.peak_error_estimate;
      const bool peak_met =
          !result.peak || (peak_estimate && meets_rtol(*peak_estimate, result.peak->normal_force,
                                                       rtol, frame.zero.force));
      result.accuracy.covers = {"critical.normal_force"};
      if (result.peak && peak_met)
        result.accuracy.covers.emplace_back("peak_adhesion.normal_force");
      result.accuracy.rtol_met = zoomed->met && peak_met;
      result.warnings.push_back(fmt::format(
          "rtol = {} not met for the stages, jumps and work with full rows of up to {} springs: "
          "{}; {}",
          rtol, p.springs.back(), p.why.empty() ? "too few rows" : p.why,
          p.choices.empty() ? "they are the finest row's, without estimates"
                            : "they carry their own error estimates, which rtol does not cover"));
      return result;
    }
  }
  if (!p.met) {
    result.warnings.push_back(fmt::format(
        "rtol = {} not met with rows of up to {} springs: {}; the finest row is reported", rtol,
        p.springs.back(), p.why.empty() ? "too few rows" : p.why));
  }
  return result;
}

}  // namespace mdrsim
