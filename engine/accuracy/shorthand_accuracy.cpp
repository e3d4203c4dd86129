// The shorthand's path through the rule programs use: rows that end alike, their states and
// works chosen and written back, and what the estimates cover.
#include "engine/accuracy/shorthand_accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <utility>

#include "controllers/controller.hpp"
#include "engine/accuracy/path_estimates.hpp"
#include "engine/base/zero_scale.hpp"

namespace mdrsim {
namespace {

constexpr std::int64_t kFirstPathRow = 512;

/// The critical point's and the peak's estimates, which RowSequence made, as `covers`
/// entries; the path's with them where `path` (its works unless they diverge).
void shorthand_covers(RunResult& result, bool path, const std::vector<WorkChoice>& works,
                      std::vector<std::string>& warnings) {
  if (path) {
    if (std::string w = set_covers(result, works); !w.empty()) warnings.push_back(std::move(w));
    return;
  }
  result.accuracy.covers = {"critical.normal_force", "peak_adhesion.normal_force"};
}

/// Row detail the shorthand's rows leave implicit: its stage ends and jumps where they are
/// the critical point, located between springs as it is (fold_refinement.hpp).
void locate_at_critical(RunResult& row) {
  if (!row.critical || !row.refined_critical) return;
  const auto at_critical = [&](const ContactSnapshot& s) { return is_critical_state(row, s); };
  for (StageRecord& stage : row.stages) {
    if (!stage.refined_end && at_critical(stage.end)) stage.refined_end = row.refined_critical;
  }
  for (JumpRecord& jump : row.jumps) {
    if (!jump.refined_critical && at_critical(jump.critical)) {
      jump.refined_critical = row.refined_critical;
    }
  }
}

/// The shorthand's three stages (preload, tangential, pull-off) hold its normal and tangential
/// controllers (the preload's end, every spring pressed, is its own located end: nothing to
/// carry there).
std::vector<StageControl> shorthand_controls(const Scene& scene) {
  StageControl control{.normal = scene.normal.controller->constraint()};
  if (scene.tangential) control.tangential = scene.tangential->controller->constraint();
  return std::vector<StageControl>(3, control);
}

/// The path's states at the critical point take the critical point's value and estimate, which
/// RowSequence resolved on its zoomed rows (a tighter one than the path's unzoomed rows give).
void take_critical(const RunResult& result, std::vector<StateChoice>& choices) {
  if (!result.critical || !result.accuracy.critical_error_estimate) return;
  take_critical(*result.critical, *result.accuracy.critical_error_estimate, choices);
}

}  // namespace

void combine_shorthand_path(const Scene& scene, std::vector<RunResult> rows, RunResult& result) {
  if (rows.size() < 3 || !result.work) return;
  for (RunResult& row : rows) {
    if (!row.work) return;  // a row's work left the range of a double: nothing to combine
    locate_at_critical(row);
  }
  const std::size_t n = rows.size();
  if (!end_alike(rows[n - 3], rows[n - 2]) || !end_alike(rows[n - 2], rows[n - 1])) {
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {} and {} springs end differently along the path ({}); the "
        "stages, jumps and work are the finest row's, without estimates",
        rows[n - 3].springs, rows[n - 2].springs, rows[n - 1].springs,
        first_difference({{rows[n - 3].springs, &rows[n - 3]},
                          {rows[n - 2].springs, &rows[n - 2]},
                          {rows[n - 1].springs, &rows[n - 1]}})));
    shorthand_covers(result, false, {}, result.warnings);
    return;
  }
  using Extrapolation = DiscretizationOptions::Extrapolation;
  std::vector<StateChoice> states =
      choose_states(rows, Extrapolation::richardson, PathStates::path);
  take_critical(result, states);
  write_states(result, states, PathStates::path);
  const std::vector<WorkChoice> works =
      choose_works(rows, Extrapolation::richardson, shorthand_controls(scene));
  write_works(result, works);
  shorthand_covers(result, true, works, result.warnings);
}

void refine_shorthand_path(const Scene& scene, double rtol, RunResult& result,
                           std::vector<RunResult> ran) {
  const ZeroScale zero = shorthand_zero_scale(scene);
  const auto run = [&](std::int64_t springs) {
    const auto same = std::find_if(ran.begin(), ran.end(), [&](const RunResult& r) {
      return r.springs == springs && r.work.has_value();
    });
    RunResult row;
    if (same != ran.end()) {
      row = std::move(*same);
      row.counts = {};  // counted by the run that made it
    } else {
      row = run_row(
          scene, {.springs = springs, .outer_radius = scene.glued_radius, .record_path = true}, {});
    }
    locate_at_critical(row);
    return row;
  };
  const std::int64_t cap =
      std::min(scene.discretization.max_row_springs, std::max(kPathRowCap, 4 * result.springs));
  PathRefinement p = refine_path(kFirstPathRow, cap, run, scene.discretization.extrapolation,
                                 PathStates::path, shorthand_controls(scene), zero, rtol);
  result.counts += p.counts;
  RunResult& finest = p.rows.back();
  result.stages = std::move(finest.stages);
  result.jumps = std::move(finest.jumps);
  result.work = finest.work;
  // What the path's row said of its path (the glue letting go pressed in, a work beyond a
  // double): the rows run above recorded none.
  for (std::string& w : finest.warnings) {
    if (std::find(result.warnings.begin(), result.warnings.end(), w) == result.warnings.end()) {
      result.warnings.push_back(std::move(w));
    }
  }
  if (!result.work) return;  // the work left the range of a double: the row said so
  if (!p.choices.empty()) {
    take_critical(result, p.choices);
    write_states(result, p.choices, PathStates::path);
  }
  if (!p.work_choices.empty()) write_works(result, p.work_choices);
  std::vector<std::string> warnings;
  shorthand_covers(result, p.met, p.work_choices, warnings);
  if (!p.met) {
    warnings.push_back(fmt::format(
        "rtol = {} not met for the stages, jumps and work with rows of up to {} springs across "
        "the glued radius: {}; {}",
        rtol, p.springs.back(), p.why.empty() ? "too few rows" : p.why,
        p.choices.empty() ? "they are the finest row's, without estimates"
                          : "they carry their own error estimates, which rtol does not cover"));
  }
  result.warnings.insert(result.warnings.end(), warnings.begin(), warnings.end());
}

}  // namespace mdrsim
