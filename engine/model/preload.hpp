// The non-adhesive preload that glues the contact: its radius and depth from depth, force or
// radius.
#pragma once

#include <stdexcept>

#include "profiles/profile.hpp"

namespace mdrsim {

/// The state the indenter is pressed to before the pull-off (docs/model.md "The spring row"):
/// pressed in without adhesion, every spring it touches glued.
struct PreloadState {
  double glued_radius;  ///< a_g [m]
  double depth;         ///< d at the preload [m]
};

/// A preload the profile cannot reach; the message says why, without the key (the scene
/// reader adds it and the location).
class PreloadOutOfReach : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

/// Pressed to `depth` [m]: a_g from g(a_g) = d (or the fixed radius of a flat punch).
PreloadState preload_at_depth(const Profile& profile, double depth);
/// Pressed with `force` [N] on E* [Pa]: a_g from the Hertz-type force 2 E* integral_0^a
/// (g(a) - g), and the depth that carries it, F = 2 E* (a d - integral_0^a g).
PreloadState preload_at_force(const Profile& profile, double force, double effective_modulus);
/// Glued at `contact_radius` [m]: d = g(a_g).
PreloadState preload_at_radius(const Profile& profile, double contact_radius);

/// The normal force [N] of the preload, without adhesion, on E* [Pa]:
/// F = 2 E* (a_g d - integral_0^a_g g).
double preload_force(const Profile& profile, const PreloadState& preload, double effective_modulus);

}  // namespace mdrsim
