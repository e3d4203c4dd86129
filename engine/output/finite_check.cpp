// Walks every snapshot and number the JSON result writes.
#include "engine/output/finite_check.hpp"

#include <fmt/format.h>

#include <cmath>

#include "engine/model/snapshot_fields.hpp"
#include "engine/output/result_json.hpp"

namespace mdrsim {

std::optional<std::string> first_not_finite(const Scene& scene, const RunResult& result) {
  const auto s = dimensionless_scales(scene);
  std::optional<std::string> bad;
  const auto check = [&](const std::string& where, double value, double scale) {
    if (bad || (std::isfinite(value) && (!s || std::isfinite(value / scale)))) return;
    bad = fmt::format("{} = {}{}", where, value,
                      s ? fmt::format(" (dimensionless scale {})", scale) : std::string());
  };
  const auto check_snapshot = [&](const std::string& what, const ContactSnapshot& snapshot) {
    for (const SnapshotField& f : kSnapshotFields) {
      check(what + "." + f.name, snapshot.*f.member, s ? scale_of(*s, f.scale) : 1.0);
    }
  };
  if (result.critical) check_snapshot("critical", *result.critical);
  if (result.peak) check_snapshot("peak_adhesion", *result.peak);
  for (const StageRecord& stage : result.stages) {
    check_snapshot(fmt::format("stage '{}'.end", stage.name), stage.end);
  }
  for (const JumpRecord& jump : result.jumps) {
    check_snapshot(fmt::format("jump in '{}'.critical", jump.stage), jump.critical);
    if (jump.end == JumpEnd::state) {
      check_snapshot(fmt::format("jump in '{}'.after", jump.stage), jump.after);
    }
  }
  const double force = s ? s->force : 1.0;
  if (result.tangential_strength) {
    check("tangential_strength", *result.tangential_strength, force);
  }
  const Accuracy& a = result.accuracy;
  if (a.critical_error_estimate) {
    check("accuracy.critical_error_estimate", *a.critical_error_estimate, force);
  }
  if (a.peak_error_estimate) check("accuracy.peak_error_estimate", *a.peak_error_estimate, force);
  if (result.work) {
    // Work has no JKR scale: SI only.
    for (const auto& [name, value] : {std::pair{"work.normal", result.work->normal},
                                      std::pair{"work.tangential", result.work->tangential}}) {
      if (!bad && !std::isfinite(value)) bad = fmt::format("{} = {}", name, value);
    }
  }
  return bad;
}

}  // namespace mdrsim
