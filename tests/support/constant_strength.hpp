// A user's own criterion whose let-go stretch stays finite as a -> 0 (a fixed strength), and
// its scene: shared by the continuum route's tests and the row's under rtol.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>

#include "detachment/criterion.hpp"
#include "engine/scene/registries.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_document.hpp"

namespace mdrsim::test {

/// A stress criterion whose threshold is a fixed strength s [N/m] instead of E* dl(a),
/// |(E* e, G* u_x)| >= s at every radius.
class ConstantStrength final : public DetachmentCriterion {
 public:
  ConstantStrength(const InterfaceProperties& p, double strength) : p_(p), strength_(strength) {}
  double margin(const BoundarySpring& b) const override {
    return strength_ - std::hypot(p_.effective_modulus * b.elongation,
                                  p_.effective_shear_modulus * b.tangential_displacement);
  }

 private:
  InterfaceProperties p_;
  double strength_;  ///< s [N/m]
};

/// The built-in parts and `constant-strength` (key `strength` [N/m]).
inline Registries with_constant_strength() {
  Registries registries = Registries::builtin();
  registries.criteria.add(
      {.name = "constant-strength",
       .summary = "a stress criterion with a fixed threshold",
       .parameters = {{.key = "strength", .help = "[N/m]", .lower = Bound{0.0, false}}},
       .create = [](const ParameterValues& v,
                    const InterfaceProperties& p) -> std::unique_ptr<DetachmentCriterion> {
         return std::make_unique<ConstantStrength>(p, v.number("strength"));
       }});
  return registries;
}

inline const std::string kParabolaProfile = "type = \"parabolic\"\nradius = 0.01\n";

/// E* = 1 MPa and the constant strength s = 1 N/m (e = s/E* = 1 um) on the parabola R = 1 cm
/// (or `profile`'s [profile] keys); `loading` is the scene's [loading] and everything after.
inline Scene constant_strength_text(const std::string& loading,
                                    const std::string& profile = kParabolaProfile) {
  const std::string text = fmt::format(
      "[material]\neffective_modulus = 1e6\nwork_of_adhesion = 0.05\n[profile]\n{}"
      "[detachment]\ncriterion = \"constant-strength\"\nstrength = 1.0\n{}",
      profile, loading);
  return SceneDocument::from_text(text, "user.toml").build(with_constant_strength());
}

/// That scene glued at 1 mm and pulled off under `normal`; `tail` closes the scene text (its
/// [solver] and [discretization]).
inline Scene constant_strength_scene(const std::string& normal, const std::string& tail,
                                     const std::string& profile = kParabolaProfile) {
  return constant_strength_text(
      fmt::format("[loading]\npreload = {{ contact_radius = 1e-3 }}\nnormal = {{ control = "
                  "\"{}\" }}\n{}",
                  normal, tail),
      profile);
}

}  // namespace mdrsim::test
