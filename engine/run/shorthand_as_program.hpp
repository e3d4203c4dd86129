// Where the shorthand runs as its three-stage program: a glue that lets go with the indenter
// pressed in leaves springs that push, which the pull-off loop and the continuum route do not
// follow and the program engine does (docs/programs.md "The shorthand as a program").
#pragma once

#include <cstdint>
#include <optional>

#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The springs of the row that tells where the shorthand's glue lets go: few enough that it
/// costs microseconds (a scene with fewer springs uses its own count).
inline constexpr std::int64_t kPressedCheckSprings = 256;

/// Whether a shorthand's result ends with its glue let go and the indenter pressed in: its
/// last jump's `after` is `pressed`.
bool ends_pressed_in(const RunResult& result);

/// The shorthand scene as the program of its three stages, on the event route (where rtol
/// alone had chosen the continuum route), its plan the program row's. Needs
/// scene.plan.shorthand_stages.
Scene as_its_program(const Scene& scene);

/// For a shorthand on the row routes (event or stepping) with its stages: the scene as its
/// program where a row of min(kPressedCheckSprings, springs) springs across the glued radius
/// ends pressed in; nothing otherwise (programs, the continuum route, scenes built by hand).
std::optional<Scene> pressed_in_on_a_first_row(const Scene& scene);

}  // namespace mdrsim
