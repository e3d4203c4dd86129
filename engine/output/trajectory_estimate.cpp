// Rows from the springs and stages, bytes per row from a row the CSV writer formats itself.
#include "engine/output/trajectory_estimate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "engine/base/text.hpp"
#include "engine/output/trajectory_csv.hpp"

namespace mdrsim::cli {
namespace {

bool has_tangential(const Scene& scene) {
  if (!scene.program) return scene.tangential.has_value();
  return std::any_of(scene.program->stages.begin(), scene.program->stages.end(),
                     [](const Stage& s) { return s.tangential.has_value(); });
}

/// The length of one row with values of as many digits as a run's: 17 significant digits
/// and an exponent wherever the scene gives a nonzero value.
double typical_row_bytes(const Scene& scene) {
  std::ostringstream header;
  const bool cohesive = scene.material.finite_range();
  const bool time = scene.program && scene.program->timed();
  TrajectoryCsvWriter header_only(header, scene.friction.has_value(), cohesive, time);
  std::ostringstream both;
  TrajectoryCsvWriter writer(both, scene.friction.has_value(), cohesive, time);
  const double full = -1.2345678901234567e-05;
  const double tangential = has_tangential(scene) ? full : 0.0;
  Event event{.kind = EventKind::spring_detached,
              .state = {},
              .spring = scene.springs,
              .in_cascade = false};
  event.state.indentation = full;
  event.state.normal_force = full;
  event.state.contact_radius = full;
  event.state.tangential_displacement = tangential;
  event.state.tangential_force = tangential;
  event.state.springs_in_contact = scene.springs;
  if (time) event.state.time = 1.2345678901234567;
  if (scene.program && !scene.program->stages.empty()) {
    event.stage = scene.program->stages.front().name;
  }
  writer.on_event(event);
  return static_cast<double>(both.str().size() - header.str().size());
}

std::string bytes_text(double bytes) {
  if (bytes >= 1e12) return fmt::format("{:.3g} TB", bytes / 1e12);
  return fmt::format("{:.3g} GB", bytes / 1e9);
}

}  // namespace

TrajectoryEstimate estimate_trajectory(const Scene& scene, std::int64_t stride) {
  const double stages = scene.program ? static_cast<double>(scene.program->stages.size()) : 1.0;
  const double events = static_cast<double>(std::max<std::int64_t>(scene.springs, 1)) * stages;
  TrajectoryEstimate e;
  e.rows = std::ceil(events / static_cast<double>(std::max<std::int64_t>(stride, 1)));
  e.bytes_per_row = typical_row_bytes(scene);
  e.bytes = e.rows * e.bytes_per_row;
  return e;
}

std::optional<std::string> large_trajectory_warning(const Scene& scene, std::int64_t stride) {
  const TrajectoryEstimate e = estimate_trajectory(scene, stride);
  if (e.bytes <= kLargeTrajectoryBytes) return std::nullopt;
  const double wanted = std::ceil(e.bytes / (kLargeTrajectoryBytes / 10.0)) *
                        static_cast<double>(std::max<std::int64_t>(stride, 1));
  return fmt::format(
      "--trajectory: the file will be about {} ({:.3g} rows of about {:.0f} bytes: {} springs, "
      "{}, stride {}); --trajectory-stride {:.0f} writes about 100 MB",
      bytes_text(e.bytes), e.rows, e.bytes_per_row, scene.springs,
      counted(scene.program ? scene.program->stages.size() : 1, "stage"), stride, wanted);
}

}  // namespace mdrsim::cli
