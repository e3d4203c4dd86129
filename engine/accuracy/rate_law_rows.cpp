// Rows of the rate law's row combined: Richardson across N/4 ... 2N springs, and rtol by
// doubling the springs until the estimates meet it.
#include "engine/accuracy/rate_law_rows.hpp"

#include <fmt/format.h>
#include <array>
#include <span>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

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

/// A value of the rows of N/4, N/2, N and 2N springs, whose error is c / N plus what is left of
/// the peak's place between let-gos, which does not fall smoothly with N: extrapolated,
/// 2 Q_2N - Q_N with twice the larger change of the last two extrapolations as its estimate (the
/// last change alone can vanish by chance: at beta = 100, n = 1/2 and 1000 springs it was 2.3
/// times below the error); plain, the finest row's own with the larger of |Q_2N - Q_N| and
/// |Q_N - Q_N/2| / 2 (its error, for a pure c / N).
struct RateLawValue {
  double value = 0.0;
  double error = 0.0;
};
RateLawValue rate_law_value(double coarsest, double coarse, double middle, double fine,
                            bool extrapolate) {
  if (!extrapolate) {
    return {fine, std::max(std::abs(fine - middle), 0.5 * std::abs(middle - coarse))};
  }
  const double finer = 2.0 * fine - middle;
  const double coarser = 2.0 * middle - coarse;
  const double coarsest_pair = 2.0 * coarse - coarsest;
  return {finer, 2.0 * std::max(std::abs(finer - coarser), std::abs(coarser - coarsest_pair))};
}

struct RateLawCombined {
  RunResult result;
  bool met = true;  ///< every estimate meets rtol (of the call)
};

/// The finest of four rows (N/4, N/2, N, 2N springs) with the peak tension, the stages' end
/// forces and works and the total work replaced by their values across the rows, and their
/// estimates.
RateLawCombined combine_rate_law_rows(std::span<const RunResult, 4> rows, bool extrapolate,
                                      double rtol) {
  const RunResult& coarsest = rows[0];
  const RunResult& coarse = rows[1];
  const RunResult& middle = rows[2];
  RateLawCombined out{rows[3], true};
  RunResult& r = out.result;
  double force_scale = r.peak ? std::abs(r.peak->normal_force) : 0.0;
  double work_scale = 1e-300;
  for (const StageRecord& s : r.stages) {
    force_scale = std::max(force_scale, std::abs(s.end.normal_force));
    work_scale += std::abs(s.work.normal) + std::abs(s.work.front);
  }
  // A stage's end force is held to rtol of the path's largest force: a stage may end at zero
  // force (JKR's zero-force state), where its relative error has no meaning.
  const double force_floor = 1e-300 + force_scale;
  if (r.peak) {
    const RateLawValue v =
        rate_law_value(coarsest.peak->normal_force, coarse.peak->normal_force,
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
    const RateLawValue f = rate_law_value(sa.end.normal_force, sc.end.normal_force,
                                          sm.end.normal_force, s.end.normal_force, extrapolate);
    const RateLawValue w =
        rate_law_value(sa.work.normal, sc.work.normal, sm.work.normal, s.work.normal, extrapolate);
    const RateLawValue d =
        rate_law_value(sa.work.front, sc.work.front, sm.work.front, s.work.front, extrapolate);
    s.end.normal_force = f.value;
    s.normal_force_error_estimate = f.error;
    s.work.normal = w.value;
    s.work.front = d.value;
    AxisWork error;
    error.normal = w.error;
    error.front = d.error;
    s.work_error_estimate = error;
    out.met = out.met && meets_rtol(f.error, f.value, rtol, force_floor) &&
              meets_rtol(w.error, w.value, rtol, work_scale) &&
              meets_rtol(d.error, d.value, rtol, work_scale);
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

}  // namespace

RunResult run_rate_law_richardson(const Scene& scene, const ObserverList& observers) {
  const std::int64_t n = scene.springs;
  const std::array<RunResult, 4> rows{
      rate_law_row_of(scene, n / 4, {}), rate_law_row_of(scene, n / 2, {}),
      rate_law_row_of(scene, n, {}), rate_law_row_of(scene, 2 * n, observers)};
  RunResult result;
  if (rate_law_rows_alike(rows)) {
    result = combine_rate_law_rows(rows, true, 0.0).result;
  } else {
    result = rows.back();
    result.accuracy.rows = {n / 4, n / 2, n, 2 * n};
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {}, {} and {} springs end differently; the finest row is "
        "reported as it is",
        n / 4, n / 2, n, 2 * n));
  }
  result.counts = RunCounts{};
  for (const RunResult& row : rows) result.counts += row.counts;
  result.accuracy.route = Accuracy::Route::richardson;
  result.accuracy.rtol_met = true;
  return result;
}

RunResult run_rate_law_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const bool extrapolate =
      scene.discretization.extrapolation != DiscretizationOptions::Extrapolation::none;
  const std::int64_t cap = scene.discretization.max_row_springs;
  std::vector<RunResult> rows;  // the last four
  RunCounts counts;
  std::int64_t springs = kFirstRateLawSprings;
  RunResult result;
  for (;;) {
    rows.push_back(rate_law_row_of(scene, springs, {}));
    counts += rows.back().counts;
    if (rows.size() > 4) rows.erase(rows.begin());
    std::optional<RateLawCombined> combined;
    if (rows.size() == 4 && rate_law_rows_alike(rows)) {
      combined =
          combine_rate_law_rows(std::span<const RunResult, 4>(rows.data(), 4), extrapolate, rtol);
      if (combined->met) {
        result = std::move(combined->result);
        result.accuracy.rtol_met = true;
        break;
      }
    }
    if (2 * springs > cap) {
      result = combined ? std::move(combined->result) : rows.back();
      result.accuracy.rtol_met = false;
      result.warnings.push_back(fmt::format(
          "rtol: the rows reached {} springs without every estimate within rtol = {:.3g}; the "
          "finest rows are reported",
          springs, rtol));
      break;
    }
    springs *= 2;
  }
  // The finest row once more for its events (the rows are deterministic).
  if (!observers.empty()) rate_law_row_of(scene, result.springs, observers);
  result.counts = counts;
  result.accuracy.route = extrapolate ? Accuracy::Route::richardson : Accuracy::Route::row;
  return result;
}

}  // namespace mdrsim
