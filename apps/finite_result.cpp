// Checks the critical point and its dimensionless form before anything is written.
#include "apps/finite_result.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/events/result_json.hpp"

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
  const double force = s ? s->force : 1.0, radius = s ? s->radius : 1.0, depth = s ? s->depth : 1.0;
  for (const auto& [what, snapshot] :
       {std::pair{"critical", &result.critical}, std::pair{"peak_adhesion", &result.peak}}) {
    if (!*snapshot) continue;
    const ContactSnapshot& c = **snapshot;
    check(what, "normal_force", c.normal_force, force);
    check(what, "tangential_force", c.tangential_force, force);
    check(what, "contact_radius", c.contact_radius, radius);
    check(what, "indentation", c.indentation, depth);
    check(what, "tangential_displacement", c.tangential_displacement, depth);
  }
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
