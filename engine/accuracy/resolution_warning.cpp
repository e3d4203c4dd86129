// The warnings of a fixed row that does not resolve what it reports.
#include "engine/accuracy/resolution_warning.hpp"

#include <fmt/format.h>

namespace mdrsim {

std::optional<std::string> unresolved_critical(const RunResult& result, const ResolvedRow& row) {
  if (!result.critical || result.critical->springs_in_contact >= kResolvedSprings ||
      result.critical->springs_in_contact >= row.springs) {
    return std::nullopt;
  }
  return fmt::format(
      "the critical point has only {} springs in contact (a = {:.6g} m of the {} {:.6g} m, {} "
      "springs): the row does not resolve it; {}",
      result.critical->springs_in_contact, result.critical->contact_radius, row.radius_name,
      row.radius, row.springs, row.remedy);
}

std::optional<std::string> unresolved_smooth_peel(const RunResult& result, const ResolvedRow& row,
                                                  bool adhesive) {
  // Without adhesion nothing can fold: a smooth peel is all there is. Without an event there
  // was no contact to peel (a fixed load pulling on nothing).
  if (result.status != RunStatus::no_instability || row.springs <= 1 || !adhesive ||
      result.counts.events == 0) {
    return std::nullopt;
  }
  return fmt::format(
      "the contact peeled off down to its last spring (a = {:.6g} m of {:.6g} m, {} springs): "
      "a fold below it is not resolved; {}",
      row.radius / static_cast<double>(row.springs), row.radius, row.springs, row.remedy);
}

std::optional<std::string> never_in_contact(const RunResult& result, const ResolvedRow& row) {
  // Only where nothing else says so: a program ending in place, never having touched.
  if (result.counts.events != 0 || result.status != RunStatus::completed) return std::nullopt;
  return fmt::format(
      "no spring of the row ({} springs across {:.6g} m) was ever in contact: nothing was "
      "loaded{}",
      row.springs, row.radius,
      row.springs < 2 ? "; a row of one spring sits at a_max, where an adhesive front glues "
                        "short of touch, and the first spring needs touch: use more springs"
                      : "");
}

}  // namespace mdrsim
