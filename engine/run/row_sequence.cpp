// Combination of a row sequence and its a posteriori error estimates.
#include "engine/run/row_sequence.hpp"

#include "engine/model/snapshot_fields.hpp"

#include <algorithm>
#include <cmath>

namespace mdrsim {
namespace {

/// No estimate is below the rounding of the sums behind a value (rows of up to 2^25 springs).
double rounding(double value) { return 1e-13 * std::abs(value); }

}  // namespace

ContactSnapshot extrapolate(const ContactSnapshot& coarse, const ContactSnapshot& fine) {
  ContactSnapshot out = fine;
  for (const auto member : kBranchQuantities) out.*member = 2.0 * fine.*member - coarse.*member;
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
  if (route == Accuracy::Route::row) {
    if (j < 1) return std::nullopt;
    double e = std::abs(q(j) - q(j - 1));
    if (j >= 2) e = std::max(e, 0.5 * std::abs(q(j - 1) - q(j - 2)));
    return std::max(2.0 * e, rounding(q(j)));
  }
  if (j < 2) return std::nullopt;
  double e = std::abs(r(j) - r(j - 1));
  if (j >= 3) e = std::max(e, 0.5 * std::abs(r(j - 1) - r(j - 2)));
  return std::max(2.0 * e, rounding(r(j)));
}

}  // namespace mdrsim
