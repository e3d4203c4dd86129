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
#include "engine/model/machine_work.hpp"

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

/// The works carried on from each stage's last equilibrium to its end located between springs
/// (the work the machine does along the branch between the two), the next stage's starting there
/// too. A row's pull-off ends at its last equilibrium, a fraction of a spacing from the fold
/// that varies with the spring count unless the fold sits at a fixed share of the glued radius
/// (a parabola glued at 2 a0 folds at spring N/2): under a fixed load the depth moves along the
/// branch there, so the work's error is F dd, a sawtooth O(dx) that Richardson does not remove
/// (the sphere's pull-off work 6.5e-6 off at 131072 springs). Carried to the located end, only
/// the smooth part of the error is left. Between the two the force is at its extremum (fixed
/// load) or the depth at its own (fixed grips): the trapezoid is good to O(dx^3).
void carry_works_to_located_ends(const Scene& scene, RunResult& row) {
  const AffineConstraint normal = scene.normal.controller->constraint();
  const bool tangential_held =
      scene.tangential && holds_force(scene.tangential->controller->constraint());
  for (std::size_t s = 0; s < row.stages.size(); ++s) {
    StageRecord& stage = row.stages[s];
    if (!stage.refined_end || stage.end.springs_in_contact == 0) continue;
    const ContactSnapshot& from = stage.end;
    const ContactSnapshot& to = *stage.refined_end;
    const AxisPoint a{from.normal_force,
                      driving_point(normal, from.normal_control, from.indentation)};
    const AxisPoint b{to.normal_force, driving_point(normal, to.normal_control, to.indentation)};
    // Under fixed grips or a compliant machine the tangential driving point does not move
    // while the normal one does (ShorthandPath::add_work).
    const AxisWork carried{
        trapezoid_work(a, b),
        tangential_held ? trapezoid_work({from.tangential_force, from.tangential_displacement},
                                         {to.tangential_force, to.tangential_displacement})
                        : 0.0};
    stage.work.normal += carried.normal;
    stage.work.tangential += carried.tangential;
    if (s + 1 < row.stages.size()) {
      row.stages[s + 1].work.normal -= carried.normal;
      row.stages[s + 1].work.tangential -= carried.tangential;
    } else if (row.work) {
      row.work->normal += carried.normal;
      row.work->tangential += carried.tangential;
    }
  }
}

/// The path's states at the critical point take the critical point's value and estimate, which
/// RowSequence resolved on its zoomed rows (a tighter one than the path's unzoomed rows give).
void take_critical(const RunResult& result, std::vector<StateChoice>& choices) {
  if (!result.critical || !result.accuracy.critical_error_estimate) return;
  take_critical(*result.critical, *result.accuracy.critical_error_estimate, choices);
}

}  // namespace

void combine_shorthand_path(std::vector<RunResult> rows, RunResult& result) {
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
  const std::vector<WorkChoice> works = choose_works(rows, Extrapolation::richardson);
  write_works(result, works);
  shorthand_covers(result, true, works, result.warnings);
}

ZeroScale shorthand_zero_scale(const Scene& scene) {
  return zero_scale(scene.material.effective_modulus, scene.glued_radius,
                    scene.profile->mdr_image(scene.glued_radius),
                    scene.material.largest_work_of_adhesion(), scene.preload_force);
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
    if (row.work) carry_works_to_located_ends(scene, row);
    return row;
  };
  const std::int64_t cap =
      std::min(scene.discretization.max_row_springs, std::max(kPathRowCap, 4 * result.springs));
  PathRefinement p = refine_path(kFirstPathRow, cap, run, scene.discretization.extrapolation,
                                 PathStates::path, zero, rtol);
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
