// Which scenes the continuum route answers exactly, so that rtol with no method takes it.
#pragma once

#include <optional>
#include <string>

#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Whether rtol alone takes the continuum route (docs/continuum.md): the shorthand on a
/// profile whose branch folds once, the convex classics (Profile::always_one_disk) with any
/// criterion and controller, a shape whose JKR branch is proven to fold once
/// (Profile::image_slope_growth: power laws with n < 1 under a built-in criterion and no
/// tangential load), and the normal loading programs it answers. Tabulated and wavy
/// profiles may fold several times, and a program with a tangential stage may stop on the
/// route: those stay on the spring row unless the route is named (method = "continuum").
bool continuum_answers(const Scene& scene);

/// Why the continuum route cannot answer a loading program exactly (one line, naming the
/// stage or the table), or nothing when it can: normal-only stages under fixed grips or a
/// fixed load, without friction, on a convex classic profile whose contact radius moves
/// (docs/continuum.md "Programs").
std::optional<std::string> continuum_program_refusal(const Scene& scene);

}  // namespace mdrsim
