// Accuracy on programs: rows in one frame (a_max), so that they differ only in their spacing;
// each reported state from the plain finest row or from Richardson across the last three.
#include "engine/run/program_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/run/path_estimates.hpp"
#include "engine/run/run_program.hpp"

namespace mdrsim {
namespace {

using Extrapolation = DiscretizationOptions::Extrapolation;

constexpr std::int64_t kFirstRow = 256;

ProgramRowSpec resolving_row(const Scene& scene, const ProgramRowFrame& frame,
                             std::int64_t springs) {
  ProgramRowSpec spec = program_row(scene, frame, springs);
  spec.edge_forces = true;
  spec.refine = true;
  return spec;
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
  const std::vector<WorkChoice> works_chosen = choose_works(rows, Extrapolation::richardson);
  write_works(result, works_chosen);
  set_covers(result, works_chosen);
  result.accuracy.route = Accuracy::Route::richardson;
  if (!plain.empty()) {
    result.warnings.push_back(fmt::format(
        "richardson: {} could not be located between springs (springs pressed outside the "
        "glued ones, a front pinned since a jump, a shear-off): the finest row's value is "
        "reported, with its plain estimate",
        join_list(plain)));
  }
  return result;
}

RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const ProgramRowFrame frame = program_row_frame(scene);
  PathRefinement p = refine_path(
      kFirstRow, scene.discretization.max_row_springs,
      [&](std::int64_t n) { return run_program_row(scene, resolving_row(scene, frame, n), {}); },
      scene.discretization.extrapolation, PathStates::all, frame.zero, rtol);
  // The finest row again, for its events (the rows above ran without observers).
  RunResult result =
      observers.empty()
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
  result.counts = p.counts;
  result.accuracy.rows = p.rows_used();
  result.accuracy.outer_radius = frame.radius;
  result.accuracy.rtol_met = p.met;
  if (!p.met) {
    result.warnings.push_back(fmt::format(
        "rtol = {} not met with rows of up to {} springs: {}; the finest row is reported", rtol,
        p.springs.back(), p.why.empty() ? "too few rows" : p.why));
  }
  return result;
}

}  // namespace mdrsim
