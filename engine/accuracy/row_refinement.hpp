// The refinement every rtol driver shares: rows of doubling springs, each run by a callable,
// until the sequence's estimate meets rtol. The drivers differ only in their zoom (which radius
// the rows span, how a row is glued there) and in the callable that runs a row.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "engine/accuracy/row_sequence.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// A row of `springs` springs of one driver's zoom, or nothing where the row breaks what the
/// zoom needs (a program's row that left the last stage's conditions): the refinement stops.
using RowOfSprings = std::function<std::optional<RunResult>(std::int64_t springs)>;

/// What a sequence does where its rows stop agreeing on how the contact ends (RowSequence::usable):
/// start over from its finest row, which sees the most, or give up.
enum class WhenRowsDisagree { restart_from_finest, give_up };

/// The route the scene's extrapolation key forces on the estimate: `none` the plain row,
/// `richardson` Richardson; nothing where it is not given (refine_rows then takes the cheaper).
std::optional<Accuracy::Route> forced_route(const DiscretizationOptions& discretization);

struct RowRefinement {
  RowSequence sequence;
  Accuracy::Route route = Accuracy::Route::richardson;
  bool met = false;
  bool gave_up = false;  ///< a row broke the zoom's conditions, or the rows disagreed
};

/// Adds rows of `seq.next_springs()` springs, run by `row`, until four rows or more meet rtol
/// by the forced route or the cheaper one (rtol_rule.hpp through `meets`), or the next row
/// would pass `max_springs`. Four rows before anything is accepted: each estimate then has its
/// guard term, the difference one resolution back (one lucky agreement of two rows is not
/// enough).
RowRefinement refine_rows(RowSequence seq, const RowOfSprings& row, double rtol,
                          std::optional<Accuracy::Route> forced, std::int64_t max_springs,
                          WhenRowsDisagree when_disagree);

}  // namespace mdrsim
