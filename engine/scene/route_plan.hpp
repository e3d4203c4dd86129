// Which engine answers a scene and which driver refines it: decided once, when the scene is
// loaded, with the reason (docs/design.md "The route").
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/scene/program.hpp"

namespace mdrsim {

struct Scene;

/// The three engines, one wing each: the shorthand's pull-off row (engine/pull_off/), a
/// program's row (engine/program/) and the continuum branch with no springs
/// (engine/continuum/).
enum class RouteEngine { pull_off_row, program_row, continuum };

/// How the rows of a row engine are chosen and combined (engine/accuracy/): one row as given,
/// Richardson across rows of N/2, N and 2N springs, or rows refined until the estimate meets
/// rtol. The continuum route is always `rtol`: its root searches and quadratures meet it.
enum class RouteDriver { one_row, richardson, rtol };

/// "pull-off row", "program row" or "continuum route".
const char* to_string(RouteEngine engine);
/// "one row", "richardson" or "rtol".
const char* to_string(RouteDriver driver);

/// Where the scene's keys sent it, and why.
struct RoutePlan {
  /// Set by plan_route: a scene built in code without it is planned by run_scene.
  bool made = false;
  RouteEngine engine = RouteEngine::pull_off_row;
  RouteDriver driver = RouteDriver::one_row;
  /// Why this engine and driver, in the scene's keys' words (one sentence, no trailing period).
  std::string reason;
  /// "file:line:col: key: " of the key that chose the continuum route (solver.method, or
  /// discretization.rtol where rtol alone took it): a path that the route finds it cannot
  /// follow as it runs is refused there.
  std::string continuum_chosen_at;
  /// rtol alone took the continuum route (no method given): a shorthand whose glue lets go
  /// with the indenter pressed in, which the route does not follow, takes the program row.
  bool continuum_by_rtol = false;
  /// The shorthand (without friction) as its three stages: where its glue lets go with the
  /// indenter pressed in, the program row runs them (engine/run/shorthand_as_program.hpp).
  std::optional<Program> shorthand_stages;

  /// One line: "ENGINE (METHOD), DRIVER: REASON".
  std::string describe(const Scene& scene) const;
};

/// Where in the scene file the keys that decide the route stand ("file:line:col: key: "),
/// for the refusals the plan makes; empty where the key is not given.
struct RouteKeys {
  std::string method_at;         ///< solver.method
  std::string rtol_at;           ///< discretization.rtol
  std::string extrapolation_at;  ///< discretization.extrapolation
  std::string friction_at;       ///< the [friction] key that makes friction act
  bool method_given = false;
};

/// The route of a built scene (every part and option read): the engine, the driver and the
/// reason, with every refusal that the keys decide, each naming both sides (the engine and
/// the profile, friction or adhesion it cannot take) at the key that chose the engine. Sets
/// scene.plan; where rtol alone takes the continuum route, scene.solver.method becomes
/// continuum. A scene built in code (no keys: every refusal without a place) keeps the method
/// it names, as if the key were given.
void plan_route(Scene& scene, const RouteKeys& keys);

}  // namespace mdrsim
