// A row too coarse for the profile's shortest feature (a wavy profile's ripple) is refused.
#include "engine/scene/unresolved_shape.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// The springs of a scene's finest row: rtol's largest row, Richardson's 2N, or N.
std::int64_t finest_row_springs(const Scene& scene) {
  if (scene.discretization.rtol) return scene.discretization.max_row_springs;
  if (scene.discretization.richardson()) return 2 * scene.springs;
  return scene.springs;
}

}  // namespace

void refuse_unresolved_shape(const Scene& scene, double radius, const char* radius_name) {
  const auto feature = scene.profile->shortest_feature();
  if (!feature || !(radius > 0.0)) return;
  const std::int64_t finest = finest_row_springs(scene);
  const double spacing = radius / static_cast<double>(finest);
  if (*feature >= 4.0 * spacing) return;
  throw SceneError(fmt::format(
      "{}the shape varies on {:.3g} m, less than 4 spacings of the finest row ({:.3g} m: the "
      "{} radius {:.3g} m over {} springs): the springs cannot follow it; give at least {:.3g} "
      "springs, or a longer wavelength",
      scene.profile_at, *feature, spacing, radius_name, radius, finest,
      std::ceil(4.0 * radius / *feature)));
}

}  // namespace mdrsim
