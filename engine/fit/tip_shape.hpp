// The indenter's shape for a fit: parsed from SPEC's --tip text into one of the engine's
// profiles, whose MDR image gives Hertz's force for any axisymmetric tip.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "profiles/profile.hpp"

namespace mdrsim::fit {

enum class TipKind { parabolic, sphere, cone };

/// A rigid axisymmetric tip. Hertz's force is E* g(delta), E* = E / (1 - nu^2), with
/// g(delta) = 2 integral_0^a (delta - g_mdr(x)) dx at the contact radius a where the MDR image
/// g_mdr(a) = delta (Popov & Hess; Sneddon's forms for the paraboloid, sphere and cone).
struct TipShape {
  TipKind kind = TipKind::parabolic;
  double radius = 0.0;      ///< [m] parabolic and sphere
  double half_angle = 0.0;  ///< [rad] cone
  std::string text;         ///< as the user gave it, canonical ("parabolic:radius=1e-05")
  std::shared_ptr<const Profile> profile;

  /// g(delta) [m^2]: the force per unit E* at the indentation delta >= 0 [m].
  double force_per_modulus(double delta) const;
  /// g'(delta) [m]: the contact stiffness per unit E*, 2 a(delta) for every axisymmetric tip.
  double stiffness_per_modulus(double delta) const;
  /// a(delta) [m]: the contact radius where the MDR image reaches delta.
  double contact_radius(double delta) const;
};

/// Parses `parabolic:radius=R`, `sphere:radius=R`, `cone:half_angle_deg=A`. Throws
/// SceneError with one line for anything else (a scene profile and the pyramid come later).
TipShape parse_tip(std::string_view text);

}  // namespace mdrsim::fit
