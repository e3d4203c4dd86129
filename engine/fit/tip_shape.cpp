// The --tip parser (a shape and its size, or a scene file's [profile]), and Hertz's force of a
// tip from its profile's MDR image.
#include "engine/fit/tip_shape.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/scene/registries.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/scene/toml_reader.hpp"
#include "profiles/cone_profile.hpp"
#include "profiles/parabolic_profile.hpp"
#include "profiles/sphere_profile.hpp"

namespace mdrsim::fit {
namespace {

[[noreturn]] void bad_tip(std::string_view text, std::string_view why) {
  throw SceneError(
      fmt::format("--tip: '{}' {} (known: parabolic:radius=R, sphere:radius=R, "
                  "cone:half_angle_deg=A, pyramid:half_angle_deg=A, a scene file FILE.toml)",
                  printable(text, 80), why));
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

/// A scene file's [profile] as the tip. The scene's other sections are passed over unread, so a
/// scene that was run can name its tip; material.poisson_ratio among them: the fit's nu is
/// --poisson-ratio's.
TipShape scene_tip(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: cannot read the tip file ({})", printable(path), why));
  };
  if (fs::is_directory(path, ec)) fail("it is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  toml::table root_table;
  try {
    root_table = toml::parse(text.str(), path);
  } catch (const toml::parse_error& e) {
    const auto& at = e.source().begin;
    throw SceneError(fmt::format("{}:{}:{}: malformed TOML: {}", printable(path), at.line,
                                 at.column, printable(e.description(), 200)));
  }
  const fs::path base_dir =
      fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  TomlReader root(root_table, "", path, base_dir);
  const std::vector<std::string> passed_over = {
      "title", "material", "loading", "detachment", "discretization", "solver", "friction"};
  std::vector<std::string> known = passed_over;
  known.emplace_back("profile");
  root.check_keys(known);
  for (const std::string& key : passed_over) {
    if (root.has(key)) root.ignore(key);
  }
  const Registries registries = Registries::builtin();
  TomlReader profile = root.table("profile");
  const std::string name = profile.name("type", registries.profiles.names());
  check_part_keys(profile, "type", name, registries.profiles);
  if (name == "flat_punch") {
    // Its contact radius does not grow with the depth: g(delta) is not the profile's force at
    // a(delta), and the adhesive branches have no fixed-grips end.
    profile.fail_at("type",
                    "flat_punch is not a tip for a fit (its contact does not grow "
                    "with the indentation)");
  }
  const auto* entry = registries.profiles.find(name);
  const ParameterValues values = profile.read_all(entry->parameters);
  TipShape tip;
  tip.profile = create_part(profile, "type", [&] { return entry->create(values); });
  profile.finish();
  root.finish();
  // The classic shapes keep their kind, so that a scene's paraboloid fits as `parabolic:`.
  if (name == "parabolic" || name == "sphere") {
    tip.kind = name == "parabolic" ? TipKind::parabolic : TipKind::sphere;
    tip.radius = values.number("radius");
  } else if (name == "cone") {
    tip.kind = TipKind::cone;
    tip.half_angle =
        std::numbers::pi / 2.0 - values.number("slope_angle_deg") * std::numbers::pi / 180.0;
  } else {
    tip.kind = TipKind::profile;
  }
  tip.text = fmt::format("{} ({})", path, name);
  return tip;
}

}  // namespace

double pyramid_equivalent_cone_slope(double half_angle) {
  return std::tan(half_angle) * 2.0 / std::sqrt(std::numbers::pi);
}

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
  if (text.size() > 5 && text.substr(text.size() - 5) == ".toml") {
    return scene_tip(std::string(text));
  }
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
  } else if (kind == "pyramid" && key == "half_angle_deg") {
    if (!(value > 0.0 && value < 90.0)) bad_tip(text, "needs a half angle in (0, 90) degrees");
    tip.kind = TipKind::pyramid;
    tip.half_angle = std::atan(pyramid_equivalent_cone_slope(value * std::numbers::pi / 180.0));
    tip.text = fmt::format("pyramid:half_angle_deg={}", value);
    tip.approximation = fmt::format(
        "approximate: the four-sided pyramid as the cone of equal cross-section area, half angle "
        "{:.6g} deg",
        degrees(tip.half_angle));
    tip.profile = std::make_shared<ConeProfile>(90.0 - degrees(tip.half_angle));
  } else {
    bad_tip(text, "is not a tip");
  }
  return tip;
}

}  // namespace mdrsim::fit
