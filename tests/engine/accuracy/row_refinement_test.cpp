// The refinement every rtol driver shares, on synthetic rows whose critical force is known:
// Q(N) = Q* + C/N + D/N^2, so the plain and extrapolated estimates and the rows needed follow
// by hand.
#include "engine/accuracy/row_refinement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace mdrsim {
namespace {

constexpr double kExact = -1.0;  ///< Q* [N]

/// A row of `springs` springs whose critical force, located between springs, is
/// Q* + c/N + d/N^2, ending in `status`.
RunResult synthetic_row(std::int64_t springs, double c, double d,
                        RunStatus status = RunStatus::instability) {
  RunResult r;
  r.status = status;
  r.springs = springs;
  const double n = static_cast<double>(springs);
  ContactSnapshot s;
  s.normal_force = kExact + c / n + d / (n * n);
  s.springs_in_contact = springs / 2;
  r.critical = s;
  r.refined_critical = s;
  return r;
}

struct Calls {
  std::vector<std::int64_t> springs;
};

RowOfSprings rows_of(double c, double d, Calls& calls) {
  return [c, d, &calls](std::int64_t springs) -> std::optional<RunResult> {
    calls.springs.push_back(springs);
    return synthetic_row(springs, c, d);
  };
}

RowSequence first_row(double c, double d) {
  return RowSequence(Target::critical, {synthetic_row(512, c, d)});
}

// The plain row forced: its error c/N meets rtol 1e-4 once c/N <= 1e-4 / 2 (the estimate is
// twice the last difference, c/N itself): c = 1 needs N >= 2e4 (2^15 = 32768 with the rows
// doubling from 512), and four rows at least.
TEST(RowRefinement, ThePlainRowMeetsRtolWhereItsEstimateSaysSo) {
  Calls calls;
  const RowRefinement r =
      refine_rows(first_row(1.0, 0.0), rows_of(1.0, 0.0, calls), 1e-4, Accuracy::Route::row,
                  std::int64_t{1} << 25, WhenRowsDisagree::restart_from_finest);
  EXPECT_TRUE(r.met);
  EXPECT_FALSE(r.gave_up);
  EXPECT_EQ(r.route, Accuracy::Route::row);
  ASSERT_FALSE(calls.springs.empty());
  EXPECT_EQ(calls.springs.back(), 32768);
  const double value = r.sequence.value(Accuracy::Route::row)->normal_force;
  const double estimate = *r.sequence.estimate(Accuracy::Route::row);
  EXPECT_LE(std::abs(value - kExact), estimate);
  EXPECT_LE(estimate, 1e-4);
}

// Richardson removes c/N exactly: with d = 0 the extrapolated rows agree to rounding after
// the fourth row, which the rule waits for; the cheaper route is Richardson.
TEST(RowRefinement, RichardsonIsTheCheaperRouteWhereTheErrorIsFirstOrder) {
  Calls calls;
  const RowRefinement r =
      refine_rows(first_row(1.0, 1.0), rows_of(1.0, 1.0, calls), 1e-6, std::nullopt,
                  std::int64_t{1} << 25, WhenRowsDisagree::restart_from_finest);
  EXPECT_TRUE(r.met);
  EXPECT_EQ(r.route, Accuracy::Route::richardson);
  EXPECT_GE(r.sequence.rows().size(), 4u);
  const double value = r.sequence.value(Accuracy::Route::richardson)->normal_force;
  EXPECT_LE(std::abs(value - kExact), *r.sequence.estimate(Accuracy::Route::richardson));
}

// The cap: no row past max_springs is run, and rtol is then not met.
TEST(RowRefinement, StopsBeforeARowPastTheCapAndSaysRtolIsNotMet) {
  Calls calls;
  const RowRefinement r =
      refine_rows(first_row(1.0, 0.0), rows_of(1.0, 0.0, calls), 1e-9, Accuracy::Route::row, 4096,
                  WhenRowsDisagree::restart_from_finest);
  EXPECT_FALSE(r.met);
  EXPECT_FALSE(r.gave_up);
  EXPECT_EQ(calls.springs, (std::vector<std::int64_t>{1024, 2048, 4096}));
}

// A row that breaks the zoom's conditions (the callable returns nothing) ends the refinement.
TEST(RowRefinement, ARowThatBreaksTheZoomEndsIt) {
  int calls = 0;
  const RowOfSprings broken = [&calls](std::int64_t springs) -> std::optional<RunResult> {
    ++calls;
    if (springs > 1024) return std::nullopt;
    return synthetic_row(springs, 1.0, 0.0);
  };
  const RowRefinement r = refine_rows(first_row(1.0, 0.0), broken, 1e-6, std::nullopt,
                                      std::int64_t{1} << 25, WhenRowsDisagree::give_up);
  EXPECT_TRUE(r.gave_up);
  EXPECT_FALSE(r.met);
  EXPECT_EQ(calls, 2);
}

// Rows that end differently: a program's zoom gives up, the shorthand's starts again from the
// finest row (which sees the most) and goes on.
TEST(RowRefinement, RowsThatEndDifferentlyRestartOrGiveUp) {
  RowSequence mixed(Target::critical, {synthetic_row(256, 1.0, 0.0, RunStatus::shear_off),
                                       synthetic_row(512, 1.0, 0.0)});
  Calls calls;
  const RowRefinement gave_up = refine_rows(mixed, rows_of(1.0, 0.0, calls), 1e-4, std::nullopt,
                                            std::int64_t{1} << 25, WhenRowsDisagree::give_up);
  EXPECT_TRUE(gave_up.gave_up);
  EXPECT_TRUE(calls.springs.empty());
  const RowRefinement restarted =
      refine_rows(mixed, rows_of(1.0, 0.0, calls), 1e-4, std::nullopt, std::int64_t{1} << 25,
                  WhenRowsDisagree::restart_from_finest);
  EXPECT_TRUE(restarted.met);
  EXPECT_EQ(restarted.sequence.rows().front().springs, 512);
}

TEST(RowRefinement, TheExtrapolationKeyForcesTheRoute) {
  DiscretizationOptions d;
  EXPECT_EQ(forced_route(d), std::nullopt);
  d.extrapolation = DiscretizationOptions::Extrapolation::none;
  EXPECT_EQ(forced_route(d), Accuracy::Route::row);
  d.extrapolation = DiscretizationOptions::Extrapolation::richardson;
  EXPECT_EQ(forced_route(d), Accuracy::Route::richardson);
}

}  // namespace
}  // namespace mdrsim
