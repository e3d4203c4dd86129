// The indenter's shape for a fit: parsed from SPEC's --tip text (or a scene file's [profile])
// into one of the engine's profiles, whose MDR image gives Hertz's force for any axisymmetric tip.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "profiles/profile.hpp"

namespace mdrsim::fit {

/// `profile`: any other profile of a scene file (flat punch, power law, wavy, tabulated).
enum class TipKind { parabolic, sphere, cone, pyramid, profile };

/// A rigid axisymmetric tip. Hertz's force is E* g(delta), E* = E / (1 - nu^2), with
/// g(delta) = 2 integral_0^a (delta - g_mdr(x)) dx at the contact radius a where the MDR image
/// g_mdr(a) = delta (Popov & Hess; Sneddon's forms for the paraboloid, sphere and cone).
struct TipShape {
  TipKind kind = TipKind::parabolic;
  double radius = 0.0;      ///< [m] parabolic and sphere
  double half_angle = 0.0;  ///< [rad] cone; pyramid: the equivalent cone's
  std::string text;         ///< as the user gave it, canonical ("parabolic:radius=1e-05")
  /// Empty for an exact tip; else what stands in for it (the pyramid's equivalent cone).
  std::string approximation;
  std::shared_ptr<const Profile> profile;

  /// g(delta) [m^2]: the force per unit E* at the indentation delta >= 0 [m].
  double force_per_modulus(double delta) const;
  /// g'(delta) [m]: the contact stiffness per unit E*, 2 a(delta) for every axisymmetric tip.
  double stiffness_per_modulus(double delta) const;
  /// a(delta) [m]: the contact radius where the MDR image reaches delta.
  double contact_radius(double delta) const;
};

/// tan of the half angle of the cone whose cross-section has the area of a four-sided pyramid's
/// at every depth: 4 d^2 tan^2(A) = pi d^2 tan^2(theta), so tan(theta) = tan(A) sqrt(4/pi), with
/// A the pyramid's half angle from the axis to the middle of a face (docs/afm.md "Tips").
double pyramid_equivalent_cone_slope(double half_angle);

/// Parses `parabolic:radius=R`, `sphere:radius=R`, `cone:half_angle_deg=A`,
/// `pyramid:half_angle_deg=A`, or a scene file (TEXT ending in `.toml`) whose [profile] is the
/// tip: read by the scene's reader and registry, the scene's other sections passed over unread,
/// any other top-level key refused. Throws SceneError with one line (file:line:col and key for
/// a bad file).
TipShape parse_tip(std::string_view text);

}  // namespace mdrsim::fit
