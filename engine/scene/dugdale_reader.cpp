// Finite-range adhesion's keys: sigma_0 from either key, and the scope it runs in.
#include "engine/scene/dugdale_reader.hpp"

#include <fmt/format.h>

#include "engine/model/dugdale_material.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

constexpr Bound kPositive{0.0, false};
constexpr const char* kMaugisScope = " (docs/maugis.md \"Scope\")";

}  // namespace

FiniteRangeKeys read_finite_range(TomlReader& t) {
  if (t.has("adhesive_stress") && t.has("maugis_parameter")) {
    t.fail_at("maugis_parameter", "give adhesive_stress or maugis_parameter, not both");
  }
  FiniteRangeKeys keys;
  keys.adhesive_stress = t.optional_number(
      {.key = "adhesive_stress",
       .help = "the Dugdale stress sigma_0 [Pa], > 0 (the range is work_of_adhesion / sigma_0)",
       .lower = kPositive});
  keys.maugis_parameter =
      t.optional_number({.key = "maugis_parameter",
                         .help = "Maugis' lambda [1], > 0 (parabolic and sphere profiles)",
                         .lower = kPositive});
  return keys;
}

void apply_finite_range(TomlReader& material, const FiniteRangeKeys& keys, Scene& scene) {
  if (!keys.given()) return;
  const char* key = keys.adhesive_stress ? "adhesive_stress" : "maugis_parameter";
  Material& m = scene.material;
  if (m.work_of_adhesion_by_radius) {
    material.fail_at("work_of_adhesion",
                     fmt::format("a work of adhesion that varies with the radius is not taken "
                                 "with {}{}",
                                 key, kMaugisScope));
  }
  if (material.has("approach_work_of_adhesion")) {
    material.fail_at("approach_work_of_adhesion",
                     fmt::format("not taken with {}: the Dugdale law is one law both ways, the "
                                 "approach included{}",
                                 key, kMaugisScope));
  }
  if (!(m.work_of_adhesion > 0.0)) {
    material.fail_at(key, "needs work_of_adhesion > 0 (the range is work_of_adhesion / sigma_0)");
  }
  if (keys.adhesive_stress) {
    m.adhesive_stress = *keys.adhesive_stress;
    return;
  }
  const auto radius = scene.profile->jkr_scale_radius();
  if ((scene.profile_name != "parabolic" && scene.profile_name != "sphere") || !radius) {
    material.fail_at("maugis_parameter",
                     fmt::format("applies to profile.type = \"parabolic\" or \"sphere\" only, not "
                                 "\"{}\"; give adhesive_stress [Pa]",
                                 scene.profile_name));
  }
  m.adhesive_stress = adhesive_stress_of_maugis_parameter(
      *keys.maugis_parameter, m.work_of_adhesion, m.effective_modulus, *radius);
  if (!std::isfinite(m.adhesive_stress) || !(m.adhesive_stress > 0.0)) {
    material.fail_at(
        "maugis_parameter",
        fmt::format("gives sigma_0 = {} Pa; expected a finite positive stress", m.adhesive_stress));
  }
}

void refuse_outside_dugdale_scope(const TomlReader& root, const TomlReader& loading,
                                  const RouteKeys& route_keys, const Scene& scene) {
  if (!scene.material.finite_range()) return;
  if (scene.program) {
    if (loading.has("rebinding") && !scene.program->rebinding) {
      loading.fail_at("rebinding",
                      std::string("not taken with material.adhesive_stress: the Dugdale zone pulls "
                                  "a spring that let go back as it nears (rebinding is implied)") +
                          kMaugisScope);
    }
    if (route_keys.method_given && scene.solver.method != SolverMethod::continuum) {
      throw SceneError(route_keys.method_at +
                       fmt::format("loading programs with material.adhesive_stress are not yet "
                                   "carried by the spring row (method = \"{}\"); use method = "
                                   "\"continuum\" (docs/maugis.md \"Programs\")",
                                   to_string(scene.solver.method)));
    }
    for (const Stage& stage : scene.program->stages) {
      if (stage.tangential) {
        loading.fail_at("stage", fmt::format("stage '{}': a tangential axis is not taken with "
                                             "material.adhesive_stress{}",
                                             stage.name, kMaugisScope));
      }
    }
  }
  if (loading.has("tangential")) {
    loading.fail_at("tangential", std::string("a tangential load is not taken with "
                                              "material.adhesive_stress") +
                                      kMaugisScope);
  }
  if (root.has("friction")) {
    root.fail_at("friction",
                 std::string("friction is not taken with material.adhesive_stress") + kMaugisScope);
  }
  if (root.has("detachment")) {
    root.fail_at("detachment",
                 "no detachment criterion applies with material.adhesive_stress: the Dugdale law's "
                 "two edge conditions decide where the contact and its zone end (docs/maugis.md)");
  }
  if (route_keys.method_given && scene.solver.method == SolverMethod::stepping) {
    throw SceneError(route_keys.method_at +
                     "material.adhesive_stress is carried by the spring row's event method, not "
                     "by stepping; use method = \"event\" or \"continuum\" (docs/maugis.md)");
  }
}

}  // namespace mdrsim
