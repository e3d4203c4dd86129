// material.grading: the key, its constant, the profile's graded image and the scope it runs in.
#include "engine/scene/grading_reader.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <string>

#include "engine/model/graded_constants.hpp"
#include "engine/model/graded_quadrature.hpp"
#include "engine/scene/scene_error.hpp"
#include "profiles/tabulated_profile.hpp"

namespace mdrsim {
namespace {

constexpr const char* kGradedScope = " (docs/graded.md \"What it refuses\")";

double profile_number(const nlohmann::json& resolved, const char* key) {
  return resolved.at("profile").at(key).get<double>();
}

}  // namespace

std::optional<Grading> read_grading(TomlReader& t, double youngs_modulus, double poisson_ratio) {
  auto table = t.optional_table("grading");
  if (!table) return std::nullopt;
  table->check_keys({"exponent", "depth"});
  Grading g;
  g.exponent = table->number({.key = "exponent",
                              .help = "k [1], 0 <= k < 1: E(z) = E0 (z / z0)^k",
                              .lower = Bound{0.0, true},
                              .upper = Bound{1.0, false}});
  g.depth = table->number(
      {.key = "depth", .help = "z0 [m] > 0, where E = youngs_modulus", .lower = Bound{0.0, false}});
  table->finish();
  g.punch_constant = graded_punch_constant(g, youngs_modulus, poisson_ratio);
  if (!std::isfinite(g.punch_constant) || !(g.punch_constant > 0.0)) {
    t.fail_at("grading", fmt::format("gives C_k = {} Pa/m^k; expected a finite positive constant",
                                     g.punch_constant));
  }
  return g;
}

void refuse_grading_without_poisson_ratio(TomlReader& t) {
  if (!t.has("grading")) return;
  t.fail_at("grading",
            "needs youngs_modulus and poisson_ratio, not effective_modulus: the graded constant "
            "depends on nu itself (docs/graded.md)");
}

void apply_grading(TomlReader& material, const nlohmann::json& resolved, Scene& scene) {
  const Grading& g = scene.material.grading;
  if (!g.graded()) return;
  const std::string& type = scene.profile_name;
  double first = 0.0, second = 0.0;
  if (type == "parabolic" || type == "flat_punch") {
    first = profile_number(resolved, "radius");
  } else if (type == "cone") {
    first = profile_number(resolved, "slope_angle_deg");
  } else if (type == "power_law") {
    first = profile_number(resolved, "coefficient");
    second = profile_number(resolved, "exponent");
  }
  scene.graded_image = GradedImage::of_profile(type, first, second, g.exponent);
  if (scene.graded_image) return;
  // The shapes with no closed form: the image by quadrature of their slope.
  if (type == "sphere") {
    scene.graded_image =
        GradedImage::by_quadrature(graded_sphere(profile_number(resolved, "radius")), g.exponent);
  } else if (type == "wavy") {
    const double radius = profile_number(resolved, "radius");
    const double amplitude = profile_number(resolved, "amplitude");
    // A = 0 builds the parabola (profiles/register.cpp): its closed form, to the bit.
    scene.graded_image =
        amplitude == 0.0
            ? GradedImage::of_power_law(0.5 / radius, 2.0, g.exponent)
            : GradedImage::by_quadrature(
                  graded_wavy(radius, amplitude, profile_number(resolved, "wavelength")),
                  g.exponent);
  } else if (const auto* table = dynamic_cast<const TabulatedProfile*>(scene.profile.get())) {
    scene.graded_image =
        GradedImage::by_quadrature(graded_table(table->interpolated_shape()), g.exponent);
  } else {
    material.fail_at("grading",
                     fmt::format("profile.type = \"{}\" has no graded image yet (known: parabolic, "
                                 "cone, power_law, flat_punch, sphere, tabulated, wavy){}",
                                 type, kGradedScope));
  }
}

void refuse_outside_grading_scope(const TomlReader& root, const TomlReader& loading,
                                  const TomlReader& material, const Scene& scene) {
  if (!scene.material.grading.graded()) return;
  if (scene.program) {
    for (const Stage& stage : scene.program->stages) {
      if (!stage.tangential) continue;
      loading.fail_at("stage", fmt::format("stage '{}': a tangential axis is not taken with "
                                           "material.grading{}",
                                           printable(stage.name), kGradedScope));
    }
  }
  if (loading.has("tangential")) {
    loading.fail_at(
        "tangential",
        std::string("a tangential load is not taken with material.grading") + kGradedScope);
  }
  if (root.has("friction")) {
    root.fail_at("friction",
                 std::string("friction is not taken with material.grading") + kGradedScope);
  }
  for (const char* key : {"adhesive_stress", "maugis_parameter"}) {
    if (material.has(key)) {
      material.fail_at(key, std::string("finite-range adhesion is not yet taken with "
                                        "material.grading") +
                                kGradedScope);
    }
  }
  if (scene.material.approach_work_of_adhesion_by_radius &&
      material.has("approach_work_of_adhesion")) {
    material.fail_at("approach_work_of_adhesion",
                     std::string("an approach work of adhesion that varies with the radius is "
                                 "not yet taken with material.grading") +
                         kGradedScope);
  }
  if (scene.material.work_of_adhesion_by_radius) {
    material.fail_at("work_of_adhesion",
                     std::string("a work of adhesion that varies with the radius is not yet "
                                 "taken with material.grading") +
                         kGradedScope);
  }
  if (root.has("detachment")) {
    root.fail_at("detachment",
                 "no detachment criterion applies with material.grading: the boundary spring "
                 "lets go by Hess's rule on the graded springs (docs/graded.md)");
  }
}

void use_graded_route(nlohmann::json& resolved, const RouteKeys& route_keys, Scene& scene) {
  if (!scene.material.grading.graded()) return;
  // No criterion is asked (Hess's rule on the graded springs): the resolved scene leaves out
  // the default it would refuse given, so that it builds the scene again.
  resolved.erase("detachment");
  // method = "event" or "stepping" named takes the graded spring row; else the continuum route.
  if (route_keys.method_given && scene.solver.method != SolverMethod::continuum) return;
  scene.solver.method = SolverMethod::continuum;
  nlohmann::json& solver = resolved["solver"];
  if (solver.is_object()) {
    for (const char* key : {"max_events", "max_events_per_spring"}) solver.erase(key);
  }
  solver["method"] = "continuum";
}

}  // namespace mdrsim
