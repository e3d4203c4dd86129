// material.relaxation: the Prony terms and the scope the viscoelastic springs run in.
#include "engine/scene/relaxation_reader.hpp"

#include <fmt/format.h>

#include <string>

#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

constexpr std::size_t kMostPronyTerms = 64;
constexpr const char* kRelaxationScope = " (docs/viscoelastic.md \"What it refuses\")";

std::string not_yet_with_relaxation(const std::string& what) {
  return what + " is not yet taken with material.relaxation" + kRelaxationScope;
}

}  // namespace

std::optional<std::vector<PronyTerm>> read_relaxation(TomlReader& t, double plane_strain) {
  auto tables = t.optional_table_array("relaxation", kMostPronyTerms);
  if (!tables) return std::nullopt;
  // Before the routes these keys choose refuse the scene for reasons of their own.
  for (const char* key : {"adhesive_stress", "maugis_parameter"}) {
    if (t.has(key)) {
      t.fail_at(key, std::string("finite-range adhesion is not taken with material.relaxation") +
                         kRelaxationScope);
    }
  }
  if (t.has("grading")) t.fail_at("grading", not_yet_with_relaxation("a graded half-space"));
  std::vector<PronyTerm> terms;
  for (TomlReader& term : *tables) {
    term.check_keys({"modulus", "time"});
    const double modulus = term.number(
        {.key = "modulus", .help = "E_i [Pa] > 0 of the Prony term", .lower = Bound{0.0, false}});
    const double time = term.number(
        {.key = "time", .help = "tau_i [s] > 0 of the Prony term", .lower = Bound{0.0, false}});
    term.finish();
    terms.push_back({modulus * plane_strain, time});
  }
  return terms;
}

void refuse_outside_relaxation_scope(const TomlReader& loading, const TomlReader& material,
                                     const RouteKeys& route_keys, const Scene& scene) {
  if (!scene.material.relaxes()) return;
  if (!scene.program) {
    material.fail_at("relaxation",
                     std::string("needs a loading program whose stages all have a duration or "
                                 "speed; the shorthand has no clock") +
                         kRelaxationScope);
  }
  if (!scene.program->timed()) {
    material.fail_at(
        "relaxation",
        std::string("needs every loading stage to have a duration or speed") + kRelaxationScope);
  }
  // The tangential control as each stage leaves it (a stage that does not name it keeps it).
  std::string tangential_control = "fixed-grips";
  for (std::size_t i = 0; i < scene.program->stages.size(); ++i) {
    const Stage& stage = scene.program->stages[i];
    if (stage.tangential) tangential_control = stage.tangential->control;
    // u_x moves under fixed grips, or follows a held force or machine spring on a glue that
    // holds it, whatever the normal control (docs/viscoelastic.md).
    if (tangential_control != "fixed-grips" && !scene.material.adhesive()) {
      loading.fail_at("stage", not_yet_with_relaxation(fmt::format(
                                   "loading.stage.{}: a tangential \"{}\" control without "
                                   "adhesion",
                                   i + 1, tangential_control)));
    }
  }
  if (route_keys.method_given && scene.solver.method != SolverMethod::event) {
    throw SceneError(route_keys.method_at +
                     not_yet_with_relaxation("a method other than \"event\""));
  }
}

void refuse_friction_with_relaxation(const TomlReader& friction, const Scene& scene) {
  if (!scene.material.relaxes() || !scene.friction) return;
  if (scene.friction->glued == GluedShear::limited) {
    friction.fail_at("glued", not_yet_with_relaxation("glued = \"coulomb\""));
  }
  if (scene.friction->law) {
    friction.fail_at("law", not_yet_with_relaxation("a friction law other than one coefficient"));
  }
  // Slips and sticks are located along a fixed-grips drive only: under a held control the depth
  // (or u_x) creeps between events, and the sliding springs' limits with it.
  std::string normal_control = "fixed-grips";  // a stage's own, or the one before it
  for (std::size_t i = 0; i < scene.program->stages.size(); ++i) {
    const Stage& stage = scene.program->stages[i];
    if (stage.normal) normal_control = stage.normal->control;
    if (stage.tangential && stage.tangential->control != "fixed-grips") {
      friction.fail_at("coefficient", not_yet_with_relaxation(fmt::format(
                                          "friction under a tangential control other than fixed "
                                          "grips (loading.stage.{}: \"{}\")",
                                          i + 1, stage.tangential->control)));
    }
    if (normal_control != "fixed-grips") {
      friction.fail_at("coefficient", not_yet_with_relaxation(fmt::format(
                                          "friction under a normal control other than fixed grips "
                                          "(loading.stage.{}: \"{}\")",
                                          i + 1, normal_control)));
    }
  }
}

}  // namespace mdrsim
