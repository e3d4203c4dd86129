// The preload solve: the inverse of the profile's non-adhesive depth and force, within its reach.
#include "engine/model/preload.hpp"

#include <fmt/format.h>

#include <cmath>

namespace mdrsim {
namespace {

/// The image at a profile's edge (a table's last point), infinite for an unbounded profile;
/// a sphere's image diverges at its edge instead, so any depth or force is reached inside it.
double edge_image(const Profile& profile) {
  const double edge = profile.outer_radius();
  return std::isfinite(edge) ? profile.mdr_image(edge) : INFINITY;
}

}  // namespace

PreloadState preload_at_depth(const Profile& profile, double depth) {
  const auto fixed = profile.fixed_contact_radius();
  const double reach = edge_image(profile);
  if (!fixed && depth > reach) {
    throw PreloadOutOfReach(fmt::format(
        "= {} is beyond the profile's reach: its image is g = {:.6g} m at its edge r = {} m", depth,
        reach, profile.outer_radius()));
  }
  return {fixed ? *fixed : profile.contact_radius_at_depth(depth), depth};
}

PreloadState preload_at_force(const Profile& profile, double force, double effective_modulus) {
  const double edge = profile.outer_radius();
  if (!profile.fixed_contact_radius() && std::isfinite(edge_image(profile))) {
    const double edge_force = effective_modulus * profile.nonadhesive_force_per_modulus(edge);
    if (force > edge_force) {
      throw PreloadOutOfReach(fmt::format(
          "= {} is beyond the profile's reach: {:.6g} N press it in up to its edge r = {} m", force,
          edge_force, edge));
    }
  }
  const double a = contact_radius_at_force(profile, force, effective_modulus);
  const double image_integral =
      a * profile.mdr_image(a) - 0.5 * profile.nonadhesive_force_per_modulus(a);
  return {a, (force / (2.0 * effective_modulus) + image_integral) / a};
}

PreloadState preload_at_radius(const Profile& profile, double a) {
  if (const auto fixed = profile.fixed_contact_radius();
      fixed && std::abs(a - *fixed) > 1e-12 * *fixed) {
    throw PreloadOutOfReach(
        fmt::format("= {} differs from the profile's fixed contact radius {}", a, *fixed));
  }
  if (a > profile.outer_radius()) {
    throw PreloadOutOfReach(
        fmt::format("= {} is beyond the profile's edge at {}", a, profile.outer_radius()));
  }
  if (!std::isfinite(profile.mdr_image(a))) {
    throw PreloadOutOfReach(
        fmt::format("= {} is at the profile's edge, where its image diverges", a));
  }
  return {a, profile.mdr_image(a)};
}

// integral_0^a g = a g(a) - (the non-adhesive force per modulus)/2, as in preload_at_force.
double preload_force(const Profile& profile, const PreloadState& preload,
                     double effective_modulus) {
  const double a = preload.glued_radius;
  return 2.0 * effective_modulus * a * (preload.depth - profile.mdr_image(a)) +
         effective_modulus * profile.nonadhesive_force_per_modulus(a);
}

}  // namespace mdrsim
