// The registry of friction laws, filled by name from a scene's [friction] table (`law`).
#pragma once

#include "engine/base/part_registry.hpp"
#include "friction/friction_law.hpp"

namespace mdrsim {

using FrictionLawRegistry = PartRegistry<FrictionLaw>;

/// Registers the built-in friction law: "coulomb" (docs/friction.md "Friction laws").
void register_builtin_friction_laws(FrictionLawRegistry& registry);

}  // namespace mdrsim
