// The route of a scene: one place where its keys choose the engine and the driver, and where
// every pairing of an engine with a part it cannot take is refused.
#include "engine/scene/route_plan.hpp"

#include <fmt/format.h>

#include "engine/scene/continuum_scope.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_error.hpp"
#include "engine/scene/unresolved_shape.hpp"

namespace mdrsim {
namespace {

[[noreturn]] void refuse(const std::string& at, const std::string& message) {
  throw SceneError(at + message);
}

constexpr const char* kUseEvent = "; use method = \"event\" (docs/continuum.md)";

/// The continuum route (named by solver.method) against the program, adhesion and profile it
/// cannot follow.
void refuse_continuum_pairs(const Scene& scene, const std::string& at) {
  if (const auto why = continuum_program_refusal(scene)) refuse(at, *why + kUseEvent);
  if (scene.material.adhesion_varies()) {
    refuse(at,
           "a work of adhesion that varies with the radius pins and releases the front at every "
           "change (several folds), and the continuum route follows one fold only; use method "
           "= \"event\" (docs/continuum.md)");
  }
  if (scene.profile->folds_at_every_crest() && !scene.profile->always_one_disk()) {
    refuse(at,
           "a wavy profile's branch folds again at every crest, and the continuum route follows "
           "one fold only; use method = \"event\" (docs/continuum.md)");
  }
}

std::string engine_reason(const Scene& scene, const RoutePlan& plan, bool method_given) {
  switch (plan.engine) {
    case RouteEngine::continuum:
      if (scene.material.finite_range()) {
        return "material.adhesive_stress: finite-range adhesion (Maugis-Dugdale) runs on the "
               "continuum route whatever the rtol unless solver.method = \"event\" takes the "
               "spring row";
      }
      if (scene.material.grading.graded()) {
        return "material.grading: a graded half-space runs on the continuum route unless "
               "solver.method = \"event\" takes the graded spring row (docs/graded.md)";
      }
      return method_given ? "solver.method = \"continuum\""
                          : "discretization.rtol with no solver.method, and the continuum route "
                            "answers this scene (one fold, one work of adhesion, normal stages)";
    case RouteEngine::program_row:
      return scene.shorthand() ? "[friction] on the shorthand: its three stages run as a program"
                               : "a loading program ([[loading.stage]])";
    case RouteEngine::pull_off_row:
      if (scene.material.finite_range()) {
        return "material.adhesive_stress with solver.method = \"event\": the Maugis-Dugdale "
               "spring row (docs/maugis_row.md)";
      }
      if (scene.material.grading.graded()) {
        return fmt::format(
            "material.grading with solver.method = \"{}\": the graded spring row "
            "(docs/graded.md)",
            to_string(scene.solver.method));
      }
      break;
  }
  std::string reason = "the shorthand (preload, tangential load, pull-off)";
  if (scene.discretization.rtol && !method_given &&
      scene.discretization.extrapolation == DiscretizationOptions::Extrapolation::automatic) {
    reason +=
        "; rtol stays on the row, as the continuum route may not answer it exactly "
        "(a branch that may fold more than once: a table, a ripple, a work of adhesion that "
        "varies, or a power law with n < 1 under a tangential load, a criterion of one's own or "
        "a compliant machine with 1/2 < n < 0.768)";
  }
  return reason;
}

}  // namespace

const char* to_string(RouteEngine engine) {
  switch (engine) {
    case RouteEngine::program_row:
      return "program row";
    case RouteEngine::continuum:
      return "continuum route";
    case RouteEngine::pull_off_row:
      break;
  }
  return "pull-off row";
}

const char* to_string(RouteDriver driver) {
  switch (driver) {
    case RouteDriver::richardson:
      return "richardson";
    case RouteDriver::rtol:
      return "rtol";
    case RouteDriver::one_row:
      break;
  }
  return "one row";
}

std::string RoutePlan::describe(const Scene& scene) const {
  std::string driver_text;
  const std::int64_t n = scene.springs;
  switch (driver) {
    case RouteDriver::one_row:
      driver_text = fmt::format("one row of {} springs", n);
      break;
    case RouteDriver::richardson:
      driver_text = fmt::format("richardson over rows of {}, {} and {} springs", n / 2, n, 2 * n);
      break;
    case RouteDriver::rtol:
      driver_text = fmt::format("rtol {:g}", scene.discretization.rtol.value_or(0.0));
      break;
  }
  const std::string method = engine == RouteEngine::continuum
                                 ? std::string()
                                 : fmt::format(" ({} method)", to_string(scene.solver.method));
  std::string line = fmt::format("{}{}, {}: {}", to_string(engine), method, driver_text, reason);
  if (shorthand_stages && engine == RouteEngine::pull_off_row && !scene.material.finite_range()) {
    line +=
        "; where a first row finds the glue let go with the indenter pressed in, the shorthand "
        "runs as its three stages on the program row";
  } else if (shorthand_stages && continuum_by_rtol) {
    line +=
        "; where the route ends with the glue let go and the indenter pressed in, the shorthand "
        "runs as its three stages on the program row";
  }
  return line;
}

void plan_route(Scene& scene, const RouteKeys& keys) {
  RoutePlan plan;
  plan.made = true;
  plan.shorthand_stages = std::move(scene.plan.shorthand_stages);
  // Friction is the program row's, spring by spring, on the event method only.
  if (scene.friction && scene.solver.method != SolverMethod::event) {
    refuse(keys.friction_at, "friction runs with solver.method = \"event\" only");
  }
  if (scene.solver.method == SolverMethod::continuum) {
    plan.continuum_chosen_at = keys.method_at;
    refuse_continuum_pairs(scene, keys.method_at);
  } else if (!keys.method_given && scene.discretization.rtol &&
             scene.discretization.extrapolation ==
                 DiscretizationOptions::Extrapolation::automatic &&
             continuum_answers(scene)) {
    // rtol alone: the continuum route wherever it answers the scene (docs/continuum.md
    // "Which route rtol takes"), else the row.
    scene.solver.method = SolverMethod::continuum;
    plan.continuum_chosen_at = keys.rtol_at;
    plan.continuum_by_rtol = true;
  }
  if (scene.solver.method == SolverMethod::continuum) {
    plan.engine = RouteEngine::continuum;
    plan.driver = RouteDriver::rtol;
  } else {
    plan.engine = scene.program ? RouteEngine::program_row : RouteEngine::pull_off_row;
    plan.driver = scene.discretization.rtol           ? RouteDriver::rtol
                  : scene.discretization.richardson() ? RouteDriver::richardson
                                                      : RouteDriver::one_row;
  }
  plan.reason = engine_reason(scene, plan, keys.method_given);
  // A program's rows span the largest contact, known once its pilot has run (run_program.cpp).
  if (plan.engine == RouteEngine::pull_off_row) {
    refuse_unresolved_shape(scene, scene.glued_radius, "glued");
  }
  if (scene.discretization.richardson() && scene.solver.method != SolverMethod::event) {
    refuse(keys.extrapolation_at, "richardson needs solver.method = \"event\"");
  }
  scene.plan = std::move(plan);
}

}  // namespace mdrsim
