// The registry of detachment criteria, filled by name from a scene's [detachment] table.
#pragma once

#include "detachment/criterion.hpp"
#include "engine/base/part_registry.hpp"

namespace mdrsim {

using CriterionRegistry = PartRegistry<DetachmentCriterion, const InterfaceProperties&>;

/// Registers the built-in criteria of the criterion table of docs/scene.md.
void register_builtin_criteria(CriterionRegistry& registry);

}  // namespace mdrsim
