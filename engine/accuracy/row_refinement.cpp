// Doubling rows until the estimate meets rtol: one loop for the shorthand's and a program's zoom.
#include "engine/accuracy/row_refinement.hpp"

#include <utility>

namespace mdrsim {

std::optional<Accuracy::Route> forced_route(const DiscretizationOptions& discretization) {
  using Extrapolation = DiscretizationOptions::Extrapolation;
  if (discretization.extrapolation == Extrapolation::none) return Accuracy::Route::row;
  if (discretization.richardson()) return Accuracy::Route::richardson;
  return std::nullopt;
}

RowRefinement refine_rows(RowSequence seq, const RowOfSprings& row, double rtol,
                          std::optional<Accuracy::Route> forced, std::int64_t max_springs,
                          WhenRowsDisagree when_disagree) {
  RowRefinement out{.sequence = seq.emptied()};
  for (;;) {
    if (!seq.usable()) {
      if (when_disagree == WhenRowsDisagree::give_up) {
        out.gave_up = true;
        break;
      }
      RowSequence restart = seq.emptied();
      restart.add(seq.last());
      seq = std::move(restart);
    }
    if (seq.rows().size() >= 4) {
      // A row ending at a step or kink of dgamma has no extrapolation (RowSequence::rough).
      out.route = seq.rough() ? Accuracy::Route::row : forced ? *forced : cheaper_route(seq, rtol);
      if (meets(seq, out.route, rtol)) {
        out.met = true;
        break;
      }
    }
    if (seq.next_springs() > max_springs) break;
    std::optional<RunResult> next = row(seq.next_springs());
    if (!next) {
      out.gave_up = true;
      break;
    }
    seq.add(std::move(*next));
  }
  out.sequence = std::move(seq);
  return out;
}

}  // namespace mdrsim
