// Registration of the built-in profiles: one explicit call, no static self-registration.
#include <memory>

#include "profiles/parabolic_profile.hpp"
#include "profiles/profile_registry.hpp"

namespace mdrsim {

void register_builtin_profiles(ProfileRegistry& registry) {
  registry.add({.name = "parabolic",
                .summary = "f = r^2/(2R), the paper's profile (eq. 6)",
                .parameters = {{.key = "radius",
                                .help = "radius of curvature R [m]",
                                .lower = Bound{0.0, false}}},
                .create = [](const ParameterValues& p) -> std::unique_ptr<Profile> {
                  return std::make_unique<ParabolicProfile>(p.number("radius"));
                }});
}

}  // namespace mdrsim
