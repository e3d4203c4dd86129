// Which scenes the continuum route answers exactly, so that rtol with no method takes it.
#pragma once

#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Whether the continuum route answers the scene exactly (docs/continuum.md): the shorthand
/// (any profile, criterion and controller). Loading programs are not on it yet; a scene it
/// cannot answer stays on the spring row.
bool continuum_answers(const Scene& scene);

}  // namespace mdrsim
