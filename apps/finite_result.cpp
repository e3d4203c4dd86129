// Checks the critical point and its dimensionless form before anything is written.
#include "apps/finite_result.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "engine/result_json.hpp"

namespace mdrsim::cli {

void require_finite(const Scene& scene, const RunResult& result) {
  const ContactSnapshot& c = result.critical;
  const std::pair<const char*, double> values[] = {
      {"normal_force", c.normal_force},
      {"tangential_force", c.tangential_force},
      {"contact_radius", c.contact_radius},
      {"indentation", c.indentation},
      {"tangential_displacement", c.tangential_displacement}};
  const auto s = dimensionless_scales(scene);
  const double scale[] = {s ? s->force : 1.0, s ? s->force : 1.0, s ? s->radius : 1.0,
                          s ? s->depth : 1.0, s ? s->depth : 1.0};
  for (std::size_t i = 0; i < std::size(values); ++i) {
    const auto& [name, value] = values[i];
    const bool finite = std::isfinite(value) && (!s || std::isfinite(value / scale[i]));
    if (!finite) {
      throw std::runtime_error(fmt::format(
          "the run gave critical.{} = {}{}, not a finite number; the scene's values may be too "
          "extreme for double precision",
          name, value, s ? fmt::format(" (dimensionless scale {})", scale[i]) : std::string()));
    }
  }
}

}  // namespace mdrsim::cli
