// Which scenes the continuum route answers exactly, so that rtol with no method takes it.
#pragma once

#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Whether rtol alone takes the continuum route (docs/continuum.md): the shorthand (any
/// criterion and controller) on a profile whose branch folds once, the convex classics
/// (Profile::always_one_disk). Loading programs are not on it yet, and tabulated and wavy
/// profiles may fold several times: those stay on the spring row.
bool continuum_answers(const Scene& scene);

}  // namespace mdrsim
