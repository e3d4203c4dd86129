// The advancing front's gluing rule: the depth at which a free spring at radius x glues, the one
// place every engine (the program's row and its sizing, the continuum route) reads it from.
#pragma once

#include "engine/base/material.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// The gap g(x) - d [m] at which the advancing front takes a free spring at radius x [m]: it
/// glues there at sqrt(2 pi x dgamma_a(x) / E*) (Material::advancing_glue_gap, 0 where
/// dgamma_a = 0: glue on touch), or presses it on touch (`glued` false: 0).
inline double advancing_limit(const Material& material, bool glued, double x) {
  return glued ? material.advancing_glue_gap(x) : 0.0;
}

/// The indentation d [m] at which the advancing front takes a free spring at radius x [m]:
/// g(x) minus the advancing limit. Every caller subtracts in this order (g - l, then any
/// further term), so that the engines agree to the bit.
inline double gluing_depth(const Profile& profile, const Material& material, bool glued, double x) {
  return profile.mdr_image(x) - advancing_limit(material, glued, x);
}

}  // namespace mdrsim
