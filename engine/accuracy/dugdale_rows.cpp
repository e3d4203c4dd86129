// Rows of the Dugdale spring row combined as the JKR rows are: RowSequence for the critical point
// and the peak, the same rule for the stages' works and the preload state.
#include "engine/accuracy/dugdale_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/accuracy/error_estimate.hpp"
#include "engine/accuracy/row_refinement.hpp"
#include "engine/accuracy/row_sequence.hpp"
#include "engine/continuum/dugdale_path.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/pull_off/dugdale_row_run.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

constexpr std::int64_t kFirstDugdaleRow = 512;
/// Each row keeps its path for the work (40 bytes a let-go): 2^22 springs hold 170 MB, and
/// Richardson's second order meets rtol 1e-12 well before them (docs/maugis_row.md).
constexpr std::int64_t kMaxDugdaleRowSprings = std::int64_t{1} << 22;

/// a_p: the contact branch's radius at the preload depth, where the row's path starts.
double preload_radius(const Scene& scene) {
  const DugdaleLaw law = dugdale_law(scene.material);
  return DugdalePath(*scene.profile, law, scene.glued_radius, scene.preload_depth).preload_radius();
}

/// The value of the last row by `route` from the values of every row, coarsest first, and its
/// estimate (error_estimate.hpp); nothing for a single plain row.
struct Combined {
  double value;
  std::optional<double> estimate;
};
Combined combine_values(const std::vector<double>& q, Accuracy::Route route) {
  const std::size_t n = q.size();
  if (route == Accuracy::Route::row || n < 2) {
    if (n < 2) return {q.back(), std::nullopt};
    const std::vector<double> last(
        q.end() - static_cast<std::ptrdiff_t>(std::min<std::size_t>(n, 3)), q.end());
    return {q.back(), std::max(change_estimate(last), rounding_floor(q.back()))};
  }
  std::vector<double> r;
  for (std::size_t j = 1; j < n; ++j) r.push_back(richardson_value(q[j - 1], q[j]));
  if (r.size() < 2) return {r.back(), std::nullopt};
  const std::vector<double> last(
      r.end() - static_cast<std::ptrdiff_t>(std::min<std::size_t>(r.size(), 3)), r.end());
  return {r.back(), std::max(change_estimate(last), rounding_floor(r.back()))};
}

struct Outcome {
  RunResult result;
  bool met = true;
};

/// The rows' critical point, peak, preload state and works by `route` into the finest row;
/// whether their estimates meet `rtol` (none given: not asked).
Outcome combine_rows(const std::vector<RunResult>& rows, Accuracy::Route route,
                     std::optional<double> rtol) {
  Outcome out{rows.back(), true};
  RunResult& result = out.result;
  RunCounts counts;
  result.accuracy.rows.clear();
  for (const RunResult& row : rows) {
    counts += row.counts;
    result.accuracy.rows.push_back(row.springs);
  }
  result.counts = counts;
  result.accuracy.route = route;
  if (rows.size() < 2) return out;
  const bool alike = std::all_of(rows.begin(), rows.end(), [&](const RunResult& r) {
    return r.status == rows.front().status && r.stages.size() == rows.front().stages.size();
  });
  if (!alike) {
    result.warnings.push_back(fmt::format(
        "{}: the rows of {} to {} springs end differently ({} and {}); the finest row is "
        "reported as it is",
        route == Accuracy::Route::richardson ? "richardson" : "rtol", rows.front().springs,
        rows.back().springs, to_string(rows.front().status), to_string(rows.back().status)));
    out.met = false;
    return out;
  }
  const auto check = [&](std::optional<double> estimate, double value, double floor = 0.0) {
    if (rtol && !(estimate && meets_rtol(*estimate, value, *rtol, floor))) out.met = false;
  };
  // A state's force that is zero on the path (after a jump) is held to the preload's scale.
  const double floor = 1e-300 + std::abs(rows.back().stages.front().end.normal_force) * 1e-6;
  if (result.status == RunStatus::instability) {
    const RowSequence seq(Target::critical, rows);
    if (const auto value = seq.value(route)) {
      result.critical = value;
      result.accuracy.critical_error_estimate = seq.estimate(route);
      JumpRecord& jump = result.jumps.front();
      jump.critical = *value;
      jump.critical_error_estimate = result.accuracy.critical_error_estimate;
      if (jump.end != JumpEnd::state) result.stages.back().end = *value;
    }
    check(result.accuracy.critical_error_estimate, result.critical->normal_force, floor);
  }
  const RowSequence peaks(Target::peak, rows);
  if (const auto value = peaks.value(route)) {
    result.peak = value;
    result.accuracy.peak_error_estimate = peaks.estimate(route);
  }
  check(result.accuracy.peak_error_estimate, result.peak->normal_force, floor);

  // The preload's state: the row's first equilibrium, a right-point sum smooth in dx.
  std::vector<double> preload_forces;
  for (const RunResult& row : rows) preload_forces.push_back(row.stages.front().end.normal_force);
  ContactSnapshot preload = rows.back().stages.front().end;
  if (route == Accuracy::Route::richardson) {
    preload = extrapolate(rows[rows.size() - 2].stages.front().end, preload);
  }
  const Combined preload_force = combine_values(preload_forces, route);
  for (std::size_t k = 0; k + 1 < result.stages.size(); ++k) {
    result.stages[k].end = preload;
    result.stages[k].normal_force_error_estimate = preload_force.estimate;
  }

  AxisWork total;
  double total_error = 0.0;
  double magnitude = 0.0;
  for (std::size_t k = 0; k < result.stages.size(); ++k) {
    std::vector<double> works;
    for (const RunResult& row : rows) works.push_back(row.stages[k].work.normal);
    const Combined w = combine_values(works, route);
    StageRecord& stage = result.stages[k];
    stage.work.normal = w.value;
    if (w.estimate) stage.work_error_estimate = AxisWork{*w.estimate, 0.0};
    total += stage.work;
    total_error += w.estimate.value_or(0.0);
    magnitude += std::abs(w.value);
  }
  result.work = total;
  result.accuracy.work_error_estimate = AxisWork{total_error, 0.0};
  result.accuracy.covers = {"critical.normal_force", "peak_adhesion.normal_force", "work"};
  if (rtol && !meets_rtol(total_error, std::abs(total.normal), *rtol, 1e-6 * magnitude)) {
    out.met = false;
  }
  return out;
}

}  // namespace

RunResult run_dugdale_rows(const Scene& scene, const ObserverList& observers) {
  const double a_p = preload_radius(scene);
  const auto row = [&](std::int64_t springs, const ObserverList& seen) {
    return run_dugdale_row_scene(scene, springs, a_p, seen);
  };
  const std::int64_t n = scene.springs;
  switch (scene.plan.driver) {
    case RouteDriver::one_row:
      return row(n, observers);
    case RouteDriver::richardson: {
      // A row stopped at solver.max_events has no critical point to extrapolate: the first
      // such is the run's answer, as the JKR rows' pilot is.
      std::vector<RunResult> rows;
      for (const std::int64_t springs : {n / 2, n, 2 * n}) {
        rows.push_back(row(springs, springs == 2 * n ? observers : ObserverList{}));
        if (rows.back().status == RunStatus::step_limit) return rows.back();
      }
      RunResult result = combine_rows(rows, Accuracy::Route::richardson, std::nullopt).result;
      result.springs = 2 * n;
      return result;
    }
    case RouteDriver::rtol:
      break;
  }
  const double rtol = *scene.discretization.rtol;
  const std::optional<Accuracy::Route> forced = forced_route(scene.discretization);
  const std::int64_t max_springs =
      std::min(scene.discretization.max_row_springs, kMaxDugdaleRowSprings);
  std::vector<RunResult> rows{row(kFirstDugdaleRow, {})};
  Outcome outcome{rows.back(), false};
  for (;;) {
    if (rows.back().status == RunStatus::step_limit) {
      if (observers.wants(EventKind::spring_detached) ||
          observers.wants(EventKind::preload_reached)) {
        row(rows.back().springs, observers);
      }
      return rows.back();
    }
    if (rows.size() >= 4) {
      // The route predicted to meet rtol with fewer springs, as for the JKR rows.
      const Target target =
          rows.back().status == RunStatus::instability ? Target::critical : Target::peak;
      const Accuracy::Route route =
          forced ? *forced : cheaper_route(RowSequence(target, rows), rtol);
      outcome = combine_rows(rows, route, rtol);
      if (outcome.met) break;
    }
    const std::int64_t next = 2 * rows.back().springs;
    if (next > max_springs) break;
    rows.push_back(row(next, {}));
    // Rows that end otherwise than the finest (a status that changes with N) are dropped.
    if (rows.back().status != rows.front().status) rows.erase(rows.begin(), rows.end() - 1);
  }
  if (rows.size() < 4) outcome = combine_rows(rows, forced.value_or(Accuracy::Route::row), rtol);
  RunResult result = std::move(outcome.result);
  result.accuracy.rtol_met = outcome.met;
  if (!outcome.met) {
    result.warnings.push_back(fmt::format(
        "rtol {} not met on the Dugdale spring row with rows of up to {} springs across {:.6g} m: "
        "the estimates are reported as they are",
        rtol, rows.back().springs, a_p));
  }
  if (observers.wants(EventKind::spring_detached) || observers.wants(EventKind::preload_reached)) {
    row(rows.back().springs, observers);
  }
  return result;
}

}  // namespace mdrsim
