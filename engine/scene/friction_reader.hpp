// Reads the scene's [friction] table and refuses what the friction engine does not run yet.
#pragma once

#include <optional>

#include "engine/model/friction_settings.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// Reads [friction] (coefficient, glued, shear_strength; docs/friction.md) of a scene whose
/// loading and solver are read already. Returns nullopt where friction changes nothing
/// (coefficient = 0 under glued = "unlimited": every run is the frictionless one, bit for bit);
/// fails with file, line and key on a bad value and on a combination not run yet.
std::optional<FrictionSettings> read_friction(TomlReader& friction, const Scene& scene);

}  // namespace mdrsim
