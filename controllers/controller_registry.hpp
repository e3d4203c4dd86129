// The registry of axis controllers, filled by name from a scene's loading tables.
#pragma once

#include "controllers/controller.hpp"
#include "engine/base/part_registry.hpp"

namespace mdrsim {

using ControllerRegistry = PartRegistry<AxisController>;

/// Registers fixed-grips, fixed-load and compliant.
void register_builtin_controllers(ControllerRegistry& registry);

}  // namespace mdrsim
