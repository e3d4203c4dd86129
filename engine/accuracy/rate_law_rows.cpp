// Rows of the rate law's row combined: Richardson across N/4 ... 2N springs, and rtol by
// doubling the springs until the estimates meet it.
#include "engine/accuracy/rate_law_rows.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "engine/accuracy/doubling_rows.hpp"
#include "engine/program/rate_law_row.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

/// rtol's first row.
constexpr std::int64_t kFirstRateLawSprings = 256;

RunResult rate_law_row_of(const Scene& scene, std::int64_t springs, const ObserverList& observers) {
  Scene row = scene;
  row.springs = springs;
  return run_rate_law_row(row, observers);
}

/// Whether the rows end alike (status, stages, where the contact was lost, a peak), so that
/// their values are the same quantities.
bool rate_law_rows_alike(std::span<const RunResult> rows) {
  const RunResult& c = rows.back();
  for (const RunResult* r = rows.data(); r != &c; ++r) {
    if (r->status != c.status || r->stages.size() != c.stages.size() ||
        r->critical_stage != c.critical_stage || r->peak.has_value() != c.peak.has_value()) {
      return false;
    }
  }
  return true;
}

/// The finest of four rows (N/4, N/2, N, 2N springs) with the peak tension, the stages' end
/// forces and works and the total work replaced by their values across the rows, and their
/// estimates.
DoublingCombined combine_rate_law_rows(std::span<const RunResult, 4> rows, bool extrapolate,
                                       double rtol) {
  const RunResult& coarsest = rows[0];
  const RunResult& coarse = rows[1];
  const RunResult& middle = rows[2];
  DoublingCombined out{rows[3], true};
  RunResult& r = out.result;
  double force_scale = r.peak ? std::abs(r.peak->normal_force) : 0.0;
  double work_scale = 1e-300;
  for (const StageRecord& s : r.stages) {
    force_scale = std::max(force_scale, std::abs(s.end.normal_force));
    work_scale += std::abs(s.work.normal) + std::abs(s.work.front) + std::abs(s.work.bulk);
  }
  // A stage's end force is held to rtol of the path's largest force: a stage may end at zero
  // force (JKR's zero-force state), where its relative error has no meaning.
  const double force_floor = 1e-300 + force_scale;
  if (r.peak) {
    const DoublingValue v =
        doubling_value(coarsest.peak->normal_force, coarse.peak->normal_force,
                       middle.peak->normal_force, r.peak->normal_force, extrapolate);
    r.peak->normal_force = v.value;
    r.accuracy.peak_error_estimate = v.error;
    out.met = out.met && meets_rtol(v.error, v.value, rtol, force_floor);
  }
  AxisWork total;
  AxisWork total_error;
  for (std::size_t k = 0; k < r.stages.size(); ++k) {
    StageRecord& s = r.stages[k];
    const StageRecord& sa = coarsest.stages[k];
    const StageRecord& sc = coarse.stages[k];
    const StageRecord& sm = middle.stages[k];
    const DoublingValue f = doubling_value(sa.end.normal_force, sc.end.normal_force,
                                           sm.end.normal_force, s.end.normal_force, extrapolate);
    const DoublingValue w =
        doubling_value(sa.work.normal, sc.work.normal, sm.work.normal, s.work.normal, extrapolate);
    const DoublingValue d =
        doubling_value(sa.work.front, sc.work.front, sm.work.front, s.work.front, extrapolate);
    // dissipated_by_bulk: zero on an elastic bulk, in every row.
    const DoublingValue b =
        doubling_value(sa.work.bulk, sc.work.bulk, sm.work.bulk, s.work.bulk, extrapolate);
    s.end.normal_force = f.value;
    s.normal_force_error_estimate = f.error;
    s.work.normal = w.value;
    s.work.front = d.value;
    s.work.bulk = b.value;
    AxisWork error;
    error.normal = w.error;
    error.front = d.error;
    error.bulk = b.error;
    s.work_error_estimate = error;
    out.met = out.met && meets_rtol(f.error, f.value, rtol, force_floor) &&
              meets_rtol(w.error, w.value, rtol, work_scale) &&
              meets_rtol(d.error, d.value, rtol, work_scale) &&
              meets_rtol(b.error, b.value, rtol, work_scale);
    total += s.work;
    total_error += error;
  }
  r.work = total;
  r.accuracy.work_error_estimate = total_error;
  r.accuracy.covers = {"peak_adhesion.normal_force", "stages.end.normal_force", "stages.work",
                       "work"};
  r.accuracy.rows = {coarsest.springs, coarse.springs, middle.springs, r.springs};
  return out;
}

DoublingRows rate_law_rows(const Scene& scene) {
  return {[&scene](std::int64_t springs, const ObserverList& observers) {
            return rate_law_row_of(scene, springs, observers);
          },
          rate_law_rows_alike, combine_rate_law_rows};
}

}  // namespace

RunResult run_rate_law_richardson(const Scene& scene, const ObserverList& observers) {
  return run_doubling_richardson(scene.springs, observers, rate_law_rows(scene));
}

RunResult run_rate_law_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const bool extrapolate =
      scene.discretization.extrapolation != DiscretizationOptions::Extrapolation::none;
  return run_doubling_rtol(rtol, extrapolate, kFirstRateLawSprings,
                           scene.discretization.max_row_springs, observers, rate_law_rows(scene));
}

}  // namespace mdrsim
