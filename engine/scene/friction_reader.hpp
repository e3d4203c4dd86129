// Reads the scene's [friction] table and refuses what the friction engine does not run.
#pragma once

#include <optional>

#include "engine/model/friction_settings.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"
#include "friction/friction_law_registry.hpp"

namespace mdrsim {

/// Reads [friction] (law and its keys, glued, shear_strength; docs/friction.md) of a scene whose
/// loading and solver are read already. Returns nullopt where friction changes nothing
/// (Coulomb's law at coefficient = 0 under glued = "unlimited": every run is the frictionless
/// one, bit for bit); fails with file, line and key on a bad value and on a combination not run.
std::optional<FrictionSettings> read_friction(TomlReader& friction, const Scene& scene,
                                              const FrictionLawRegistry& laws);

}  // namespace mdrsim
