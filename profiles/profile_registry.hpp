// The registry of indenter profiles, filled by name from a scene's [profile] table.
#pragma once

#include "engine/base/part_registry.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

using ProfileRegistry = PartRegistry<Profile>;

/// Registers the built-in profiles: parabolic, sphere, cone, flat_punch, power_law, wavy,
/// tabulated.
void register_builtin_profiles(ProfileRegistry& registry);

}  // namespace mdrsim
