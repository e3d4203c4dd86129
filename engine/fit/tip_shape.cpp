// The --tip parser, and Hertz's force of a tip from its profile's MDR image.
#include "engine/fit/tip_shape.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "engine/scene/scene_error.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/sphere_profile.hpp"

namespace mdrsim::fit {
namespace {

[[noreturn]] void bad_tip(std::string_view text, std::string_view why) {
  throw SceneError(
      fmt::format("--tip: '{}' {} (known: parabolic:radius=R, sphere:radius=R, "
                  "cone:half_angle_deg=A)",
                  printable(text, 80), why));
}

}  // namespace

double TipShape::contact_radius(double delta) const {
  if (delta <= 0.0) return 0.0;
  if (kind != TipKind::sphere) return profile->contact_radius_at_depth(delta);
  // The sphere's image x artanh(x/R) is convex and rises from 0, and sqrt(R delta) lies right of
  // its root (artanh t >= t): Newton from there falls monotonically onto it, in a few steps
  // where the profile's bracketing search takes some forty evaluations.
  double a = std::sqrt(radius * delta);
  if (!(a < radius)) return profile->contact_radius_at_depth(delta);
  for (int i = 0; i < 50; ++i) {
    const double next = a - (profile->mdr_image(a) - delta) / profile->mdr_image_slope(a);
    if (!(next < a) || next <= 0.0) break;
    a = next;
  }
  return a;
}

double TipShape::force_per_modulus(double delta) const {
  if (delta <= 0.0) return 0.0;
  return profile->nonadhesive_force_per_modulus(contact_radius(delta));
}

double TipShape::stiffness_per_modulus(double delta) const { return 2.0 * contact_radius(delta); }

TipShape parse_tip(std::string_view text) {
  const std::size_t colon = text.find(':');
  const std::string_view kind = text.substr(0, colon);
  if (colon == std::string_view::npos) bad_tip(text, "has no KEY=VALUE");
  const std::string_view rest = text.substr(colon + 1);
  const std::size_t eq = rest.find('=');
  if (eq == std::string_view::npos) bad_tip(text, "has no KEY=VALUE");
  const std::string_view key = rest.substr(0, eq);
  const std::string_view number = rest.substr(eq + 1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (number.empty() || error != std::errc{} || end != number.data() + number.size() ||
      !std::isfinite(value)) {
    bad_tip(text, "does not end in a number");
  }
  TipShape tip;
  if ((kind == "parabolic" || kind == "sphere") && key == "radius") {
    if (!(value > 0.0)) bad_tip(text, "needs a radius > 0");
    tip.kind = kind == "parabolic" ? TipKind::parabolic : TipKind::sphere;
    tip.radius = value;
    tip.text = fmt::format("{}:radius={}", kind, value);
    if (tip.kind == TipKind::parabolic) {
      tip.profile = std::make_shared<ParabolicProfile>(value);
    } else {
      tip.profile = std::make_shared<SphereProfile>(value);
    }
  } else if (kind == "cone" && key == "half_angle_deg") {
    if (!(value > 0.0 && value < 90.0)) bad_tip(text, "needs a half angle in (0, 90) degrees");
    tip.kind = TipKind::cone;
    tip.half_angle = value * std::numbers::pi / 180.0;
    tip.text = fmt::format("cone:half_angle_deg={}", value);
    // The profile's angle is the flank's with the surface.
    tip.profile = std::make_shared<ConeProfile>(90.0 - value);
  } else {
    bad_tip(text, "is not a tip");
  }
  return tip;
}

}  // namespace mdrsim::fit
