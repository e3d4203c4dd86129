// The paper's path written with the shorthand keys, as the three-stage loading program it is
// (docs/programs.md "The shorthand as a program"), for what runs on programs only (friction).
#pragma once

#include "controllers/controller_registry.hpp"
#include "engine/scene/program.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// `preload`: fixed grips pressed to the preload depth, gluing on touch; `tangential`: the
/// normal axis under the shorthand's pull-off control, holding, the tangential one (if any)
/// ramped to its held value; `pull-off`: the normal held value lowered until separation, by
/// the preload's depth (or, for a held force, its force) per unit of the stage parameter.
Program shorthand_program(const Scene& scene, const ControllerRegistry& controllers);

}  // namespace mdrsim
