// Checks the critical point and its dimensionless form before anything is written.
#include "apps/finite_result.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/events/result_json.hpp"
#include "engine/model/snapshot_fields.hpp"

namespace mdrsim::cli {

void require_finite(const Scene& scene, const RunResult& result) {
  const auto s = dimensionless_scales(scene);
  const auto check = [&](const char* what, const char* name, double value, double scale) {
    if (std::isfinite(value) && (!s || std::isfinite(value / scale))) return;
    throw std::runtime_error(fmt::format(
        "the run gave {}.{} = {}{}, not a finite number; the scene's values may be too "
        "extreme for double precision",
        what, name, value, s ? fmt::format(" (dimensionless scale {})", scale) : std::string()));
  };
  for (const auto& [what, snapshot] :
       {std::pair{"critical", &result.critical}, std::pair{"peak_adhesion", &result.peak}}) {
    if (!*snapshot) continue;
    for (const SnapshotField& f : kSnapshotFields) {
      check(what, f.name, (**snapshot).*f.member, s ? scale_of(*s, f.scale) : 1.0);
    }
  }
  const double force = s ? s->force : 1.0;
  if (result.tangential_strength) {
    check("result", "tangential_strength", *result.tangential_strength, force);
  }
  const Accuracy& a = result.accuracy;
  if (a.critical_error_estimate) {
    check("accuracy", "critical_error_estimate", *a.critical_error_estimate, force);
  }
  if (a.peak_error_estimate)
    check("accuracy", "peak_error_estimate", *a.peak_error_estimate, force);
}

}  // namespace mdrsim::cli
