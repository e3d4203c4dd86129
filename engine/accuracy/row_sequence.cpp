// Combination of a row sequence and its a posteriori error estimates.
#include "engine/accuracy/row_sequence.hpp"

#include <algorithm>
#include <cmath>

#include "engine/accuracy/error_estimate.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {

ContactSnapshot extrapolate(const ContactSnapshot& coarse, const ContactSnapshot& fine) {
  ContactSnapshot out = fine;
  for (const auto member : kBranchQuantities) {
    out.*member = richardson_value(coarse.*member, fine.*member);
  }
  return out;
}

std::vector<double> rough_radii(const Material& material) {
  std::vector<double> out;
  for (const auto& by_radius :
       {material.work_of_adhesion_by_radius, material.approach_work_of_adhesion_by_radius}) {
    if (by_radius && by_radius->table()) {
      out.insert(out.end(), by_radius->breakpoints().begin(), by_radius->breakpoints().end());
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

const ContactSnapshot* RowSequence::plain_end(std::size_t j) const {
  const RunResult& row = rows_[j];
  const auto& plain = target_ == Target::critical ? row.critical : row.peak;
  return plain ? &*plain : nullptr;
}

bool RowSequence::ends_near_rough_radius(std::size_t j) const {
  // The parabola between springs reads lambda at n - 1, n and n + 1 (a shear-off n + 2), and
  // the front pins within a spacing of a step: four spacings either side cover both.
  constexpr double kReach = 4.0;
  const ContactSnapshot* end = plain_end(j);
  if (rough_radii_.empty() || !end || end->springs_in_contact <= 0) return false;
  const double a = end->contact_radius;
  const double dx = a / static_cast<double>(end->springs_in_contact);
  // The radii are sorted: the first positive one from a - 4 dx on, in O(log) of a long table.
  auto r = std::lower_bound(rough_radii_.begin(), rough_radii_.end(), a - kReach * dx);
  while (r != rough_radii_.end() && !(*r > 0.0)) ++r;
  return r != rough_radii_.end() && std::abs(*r - a) <= kReach * dx;
}

bool RowSequence::rough() const {
  for (std::size_t j = 0; j < rows_.size(); ++j) {
    if (ends_near_rough_radius(j)) return true;
  }
  return false;
}

double RowSequence::pinned_front_bound() const {
  double slope = 0.0;
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    for (std::size_t k = i + 1; k < rows_.size(); ++k) {
      const double da = plain_end(i)->contact_radius - plain_end(k)->contact_radius;
      if (da != 0.0) slope = std::max(slope, std::abs((q(i) - q(k)) / da));
    }
  }
  const ContactSnapshot& last = *plain_end(rows_.size() - 1);
  return 2.0 * slope * last.contact_radius / static_cast<double>(last.springs_in_contact);
}

const ContactSnapshot* RowSequence::between_springs(std::size_t j) const {
  if (rough()) return plain_end(j);
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
  if (j < 1 || rough()) return std::nullopt;
  return extrapolate(*between_springs(j - 1), *between_springs(j));
}

std::optional<double> RowSequence::estimate(Accuracy::Route route) const {
  if (!usable()) return std::nullopt;
  const std::size_t j = rows_.size() - 1;
  const bool plain = route == Accuracy::Route::row;
  if (j < (plain ? 1U : 2U) || (!plain && rough())) return std::nullopt;
  // The last three values (the last two where there are no more) of the route's sequence.
  const std::size_t first = plain ? (j >= 2 ? j - 2 : j - 1) : (j >= 3 ? j - 2 : j - 1);
  std::vector<double> values;
  for (std::size_t i = first; i <= j; ++i) values.push_back(plain ? q(i) : r(i));
  const double pinned = rough() ? pinned_front_bound() : 0.0;
  return std::max(change_estimate(values) + pinned, rounding_floor(values.back()));
}

bool meets(const RowSequence& seq, Accuracy::Route route, double rtol) {
  const auto value = seq.value(route);
  const auto estimate = seq.estimate(route);
  return value && estimate && meets_rtol(*estimate, value->normal_force, rtol);
}

Accuracy::Route cheaper_route(const RowSequence& seq, double rtol) {
  using Route = Accuracy::Route;
  if (seq.rough()) return Route::row;
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
