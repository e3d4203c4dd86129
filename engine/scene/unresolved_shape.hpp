// A row too coarse for the profile's shortest feature (a wavy profile's ripple) is refused.
#pragma once

#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Throws SceneError at `scene.profile_at` (profile.type) where the finest row's spacing over
/// `radius` [m] (the contact radius the rows span, named `radius_name` in the message) is more
/// than a quarter of the profile's shortest feature: the springs cannot follow the shape, its
/// numbers would be the row's aliasing, and the disk check alone would sample every ripple.
void refuse_unresolved_shape(const Scene& scene, double radius, const char* radius_name);

}  // namespace mdrsim
