// Combination of a row sequence and its a posteriori error estimates.
#include "engine/accuracy/row_sequence.hpp"
#include "engine/result/rtol_rule.hpp"

#include "engine/model/snapshot_fields.hpp"

#include <algorithm>
#include <cmath>

#include "engine/accuracy/error_estimate.hpp"

namespace mdrsim {

ContactSnapshot extrapolate(const ContactSnapshot& coarse, const ContactSnapshot& fine) {
  ContactSnapshot out = fine;
  for (const auto member : kBranchQuantities) {
    out.*member = richardson_value(coarse.*member, fine.*member);
  }
  return out;
}

const ContactSnapshot* RowSequence::between_springs(std::size_t j) const {
  // Where the row's end is not smooth enough to locate between springs (a first let-go that
  // jumps at once, a peak at the glued radius), its own value converges like 1/N too.
  const RunResult& row = rows_[j];
  const bool critical = target_ == Target::critical;
  const auto& refined = critical ? row.refined_critical : row.refined_peak;
  const auto& plain = critical ? row.critical : row.peak;
  return refined ? &*refined : plain ? &*plain : nullptr;
}

bool RowSequence::usable() const {
  if (rows_.empty()) return false;
  for (std::size_t j = 0; j < rows_.size(); ++j) {
    if (!between_springs(j) || rows_[j].status != rows_.front().status) return false;
  }
  return true;
}

std::optional<ContactSnapshot> RowSequence::value(Accuracy::Route route) const {
  if (!usable()) return std::nullopt;
  const std::size_t j = rows_.size() - 1;
  if (route == Accuracy::Route::row) return *between_springs(j);
  if (j < 1) return std::nullopt;
  return extrapolate(*between_springs(j - 1), *between_springs(j));
}

std::optional<double> RowSequence::estimate(Accuracy::Route route) const {
  if (!usable()) return std::nullopt;
  const std::size_t j = rows_.size() - 1;
  const bool plain = route == Accuracy::Route::row;
  if (j < (plain ? 1U : 2U)) return std::nullopt;
  // The last three values (the last two where there are no more) of the route's sequence.
  const std::size_t first = plain ? (j >= 2 ? j - 2 : j - 1) : (j >= 3 ? j - 2 : j - 1);
  std::vector<double> values;
  for (std::size_t i = first; i <= j; ++i) values.push_back(plain ? q(i) : r(i));
  return std::max(change_estimate(values), rounding_floor(values.back()));
}

bool meets(const RowSequence& seq, Accuracy::Route route, double rtol) {
  const auto value = seq.value(route);
  const auto estimate = seq.estimate(route);
  return value && estimate && meets_rtol(*estimate, value->normal_force, rtol);
}

Accuracy::Route cheaper_route(const RowSequence& seq, double rtol) {
  using Route = Accuracy::Route;
  if (meets(seq, Route::richardson, rtol)) return Route::richardson;
  if (meets(seq, Route::row, rtol)) return Route::row;
  const auto value = seq.value(Route::row);
  const auto plain = seq.estimate(Route::row);
  const auto extrapolated = seq.estimate(Route::richardson);
  if (!value || !plain || !extrapolated) return Route::richardson;
  const double wanted = rtol * std::abs(value->normal_force);
  return std::sqrt(*extrapolated / wanted) <= *plain / wanted ? Route::richardson : Route::row;
}

}  // namespace mdrsim
