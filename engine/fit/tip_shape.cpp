// Hertz's force laws of the tips a fit knows (Sneddon 1965), and the --tip parser.
#include "engine/fit/tip_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/scene/scene_error.hpp"

namespace mdrsim::fit {
namespace {

/// The sphere's contact radius a at indentation delta: the root of
/// delta = (a/2) ln((R+a)/(R-a)) (Sneddon's exact sphere), monotone in a on [0, R).
double sphere_contact_radius(double radius, double delta) {
  if (delta <= 0.0) return 0.0;
  double a = std::min(std::sqrt(radius * delta), 0.999 * radius);
  for (int i = 0; i < 60; ++i) {
    const double log_term = std::log((radius + a) / (radius - a));
    const double f = 0.5 * a * log_term - delta;
    const double df = 0.5 * log_term + a * radius / (radius * radius - a * a);
    double next = a - f / df;
    if (!(next > 0.0)) next = 0.5 * a;
    if (next >= radius) next = 0.5 * (a + radius);
    if (std::abs(next - a) <= 1e-15 * radius) return next;
    a = next;
  }
  return a;
}

[[noreturn]] void bad_tip(std::string_view text, std::string_view why) {
  throw SceneError(
      fmt::format("--tip: '{}' {} (known: parabolic:radius=R, sphere:radius=R, "
                  "cone:half_angle_deg=A)",
                  printable(text, 80), why));
}

}  // namespace

double TipShape::force_per_modulus(double delta) const {
  if (delta <= 0.0) return 0.0;
  switch (kind) {
    case TipKind::parabolic:
      return 4.0 / 3.0 * std::sqrt(radius) * delta * std::sqrt(delta);
    case TipKind::cone:
      return 2.0 / std::numbers::pi * std::tan(half_angle) * delta * delta;
    case TipKind::sphere: {
      const double a = sphere_contact_radius(radius, delta);
      const double log_term = std::log((radius + a) / (radius - a));
      return 0.5 * ((a * a + radius * radius) * log_term - 2.0 * a * radius);
    }
  }
  return 0.0;
}

double TipShape::stiffness_per_modulus(double delta) const {
  if (delta <= 0.0) return 0.0;
  switch (kind) {
    case TipKind::parabolic:
      return 2.0 * std::sqrt(radius * delta);
    case TipKind::cone:
      return 4.0 / std::numbers::pi * std::tan(half_angle) * delta;
    case TipKind::sphere:
      return 2.0 * sphere_contact_radius(radius, delta);
  }
  return 0.0;
}

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
  } else if (kind == "cone" && key == "half_angle_deg") {
    if (!(value > 0.0 && value < 90.0)) bad_tip(text, "needs a half angle in (0, 90) degrees");
    tip.kind = TipKind::cone;
    tip.half_angle = value * std::numbers::pi / 180.0;
    tip.text = fmt::format("cone:half_angle_deg={}", value);
  } else {
    bad_tip(text, "is not a tip");
  }
  return tip;
}

}  // namespace mdrsim::fit
