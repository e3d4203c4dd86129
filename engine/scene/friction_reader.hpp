// Reads the scene's [friction] table; the route plan refuses what the engines do not run with it.
#pragma once

#include <optional>
#include <string>

#include "engine/model/friction_settings.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"
#include "friction/friction_law_registry.hpp"

namespace mdrsim {

/// Reads [friction] (law and its keys, glued, shear_strength; docs/friction.md).
/// Returns nullopt where friction changes nothing
/// (Coulomb's law at coefficient = 0 under glued = "unlimited": every run is the frictionless
/// one, bit for bit); fails with file, line and key on a bad value. Which engine takes it is
/// the route plan's (route_plan.hpp).
std::optional<FrictionSettings> read_friction(TomlReader& friction,
                                              const FrictionLawRegistry& laws);

/// The key of [friction] that makes it act (glued, law or coefficient): where a route that
/// cannot take friction is refused.
std::string friction_acting_key(const FrictionSettings& settings);

}  // namespace mdrsim
