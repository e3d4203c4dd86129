// The drivers of rows of doubling springs: Richardson across N/4 ... 2N, rtol by doubling.
#include "engine/accuracy/doubling_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace mdrsim {

DoublingValue doubling_value(double coarsest, double coarse, double middle, double fine,
                             bool extrapolate, int order) {
  if (!extrapolate) {
    return {fine, std::max(std::abs(fine - middle), 0.5 * std::abs(middle - coarse))};
  }
  const double factor = order == 2 ? 4.0 : 2.0;
  const auto pair = [factor](double finer_row, double coarser_row) {
    return (factor * finer_row - coarser_row) / (factor - 1.0);
  };
  const double finer = pair(fine, middle);
  const double coarser = pair(middle, coarse);
  const double coarsest_pair = pair(coarse, coarsest);
  return {finer, 2.0 * std::max(std::abs(finer - coarser), std::abs(coarser - coarsest_pair))};
}

RunResult run_doubling_richardson(std::int64_t n, const ObserverList& observers,
                                  const DoublingRows& rows) {
  const std::array<RunResult, 4> row{rows.row_of(n / 4, {}), rows.row_of(n / 2, {}),
                                     rows.row_of(n, {}), rows.row_of(2 * n, observers)};
  RunResult result;
  if (rows.alike(row)) {
    result = rows.combine(row, true, 0.0).result;
  } else {
    result = row.back();
    result.accuracy.rows = {n / 4, n / 2, n, 2 * n};
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {}, {} and {} springs end differently; the finest row is "
        "reported as it is",
        n / 4, n / 2, n, 2 * n));
  }
  result.counts = RunCounts{};
  for (const RunResult& r : row) result.counts += r.counts;
  result.accuracy.route = Accuracy::Route::richardson;
  result.accuracy.rtol_met = true;
  return result;
}

RunResult run_doubling_rtol(double rtol, bool extrapolate, std::int64_t first, std::int64_t cap,
                            const ObserverList& observers, const DoublingRows& rows) {
  std::vector<RunResult> row;  // the last four
  RunCounts counts;
  std::int64_t springs = first;
  RunResult result;
  for (;;) {
    row.push_back(rows.row_of(springs, {}));
    counts += row.back().counts;
    if (row.size() > 4) row.erase(row.begin());
    std::optional<DoublingCombined> combined;
    if (row.size() == 4 && rows.alike(row)) {
      combined = rows.combine(std::span<const RunResult, 4>(row.data(), 4), extrapolate, rtol);
      if (combined->met) {
        result = std::move(combined->result);
        result.accuracy.rtol_met = true;
        break;
      }
    }
    if (2 * springs > cap) {
      result = combined ? std::move(combined->result) : row.back();
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
  if (!observers.empty()) rows.row_of(result.springs, observers);
  result.counts = counts;
  result.accuracy.route = extrapolate ? Accuracy::Route::richardson : Accuracy::Route::row;
  return result;
}

}  // namespace mdrsim
