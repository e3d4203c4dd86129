// Rows of doubling springs whose error is c / N^p: a value's extrapolation and estimate across
// four rows, and the Richardson and rtol drivers that the rate law's and the viscoelastic rows
// share.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"

namespace mdrsim {

/// A value of the rows of N/4, N/2, N and 2N springs, whose error is c / N^p (`order` p = 1 or
/// 2) plus what is left of an edge's place between springs, which does not fall smoothly with N:
/// extrapolated, (2^p Q_2N - Q_N) / (2^p - 1) with twice the larger change of the last two
/// extrapolations as its estimate (the last change alone can vanish by chance: at beta = 100,
/// n = 1/2 and 1000 springs the rate law's was 2.3 times below the error); plain, the finest
/// row's own with the larger of |Q_2N - Q_N| and |Q_N - Q_N/2| / 2 (its error, for a pure c / N).
struct DoublingValue {
  double value = 0.0;
  double error = 0.0;
};
DoublingValue doubling_value(double coarsest, double coarse, double middle, double fine,
                             bool extrapolate, int order = 1);

/// The finest of four rows with its values combined across them, and whether every estimate
/// met rtol.
struct DoublingCombined {
  RunResult result;
  bool met = true;
};

/// What a kind of row gives the drivers: one row of `springs` springs (emitting to the
/// observers), whether rows end alike (so that their values are the same quantities), and the
/// combination of four rows (N/4 ... 2N) at rtol (0: not held), extrapolated or plain.
struct DoublingRows {
  std::function<RunResult(std::int64_t springs, const ObserverList& observers)> row_of;
  std::function<bool(std::span<const RunResult> rows)> alike;
  std::function<DoublingCombined(std::span<const RunResult, 4> rows, bool extrapolate, double rtol)>
      combine;
};

/// Rows of n/4, n/2, n and 2n springs combined; rows that end differently report the finest row
/// as it is, with a warning. Emits the finest row's events.
RunResult run_doubling_richardson(std::int64_t n, const ObserverList& observers,
                                  const DoublingRows& rows);

/// Rows of `first`, 2 `first`, ... springs until the combination of the last four meets rtol;
/// past `cap` springs the finest rows with rtol_met false and a warning. The route is
/// Richardson's where `extrapolate`, else the plain row's. Emits the finest row's events.
RunResult run_doubling_rtol(double rtol, bool extrapolate, std::int64_t first, std::int64_t cap,
                            const ObserverList& observers, const DoublingRows& rows);

}  // namespace mdrsim
