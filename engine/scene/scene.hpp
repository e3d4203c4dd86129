// A loaded scene: the parts and numbers of one pull-off run, checked and resolved.
#pragma once

#include <cstdint>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <vector>

#include "controllers/controller.hpp"
#include "detachment/criterion.hpp"
#include "engine/base/material.hpp"
#include "engine/model/friction_settings.hpp"
#include "engine/model/front_speed_law.hpp"
#include "engine/model/graded_image.hpp"
#include "engine/scene/program.hpp"
#include "engine/scene/route_plan.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// event and stepping run spring rows; continuum answers from the continuum branch, with no
/// springs (docs/continuum.md).
enum class SolverMethod { event, stepping, continuum };

/// The method's name in scenes and results: "event", "stepping" or "continuum".
constexpr const char* to_string(SolverMethod method) {
  switch (method) {
    case SolverMethod::stepping:
      return "stepping";
    case SolverMethod::continuum:
      return "continuum";
    case SolverMethod::event:
      break;
  }
  return "event";
}

struct SolverOptions {
  SolverMethod method = SolverMethod::event;
  /// Stepping increment of the normal control [m for fixed-grips and compliant, N for
  /// fixed-load]; default 1e-3 of the control value at the preload. In a loading program:
  /// the increment of the stage parameter (which runs from 0 to 1), default 1e-3.
  std::optional<double> step;
  int max_halvings = 30;
  /// Continuum route: points of the branch emitted as `sample` events, evenly in the contact
  /// radius (the command's --samples with --trajectory); 0: none. Not a scene key.
  std::int64_t samples = 0;
  std::int64_t max_steps = 100'000'000;
  /// The events (spring changes, slips and sticks) a spring row may take: at this many the
  /// run stops with step-limit (StopReason::max_events). Both row methods.
  std::int64_t max_events = 1'000'000'000'000'000;
  /// The events a program stage may take per spring of its row: a stage sweeps its row a few
  /// times at most, but stick-slip (rebinding under a shear ramp) changes the edge spring once
  /// per slip, and a large ramp slips without end; past this the run stops with step-limit
  /// (StopReason::max_events_per_spring). Both row methods.
  std::int64_t max_events_per_spring = 64;
};

/// The fewest springs a row may have for Richardson extrapolation: below it the rows' ends
/// are too coarse for their errors to follow C/N.
inline constexpr std::int64_t kMinRichardsonSprings = 64;

/// discretization.rtol of the continuum route when the scene gives none.
inline constexpr double kContinuumRtol = 1e-10;

/// How the spring row is chosen and its results combined across resolutions.
struct DiscretizationOptions {
  /// Requested relative accuracy of the critical force; picks the springs (run_scene.hpp).
  std::optional<double> rtol;
  /// `extrapolation`: not given (rtol picks the cheaper route; without rtol, none),
  /// "none" (the plain row) or "richardson" (across rows of N and 2N springs).
  enum class Extrapolation { automatic, none, richardson };
  Extrapolation extrapolation = Extrapolation::automatic;
  /// The largest row rtol may run before it gives up and says so (not a scene key: a cap
  /// for harnesses such as the fuzzer).
  std::int64_t max_row_springs = std::int64_t{1} << 25;
  bool richardson() const { return extrapolation == Extrapolation::richardson; }
};

/// One axis of the loading machine: its controller and, on the tangential axis, the value
/// it holds during the pull-off.
struct AxisLoading {
  std::string control;                               ///< the controller's registered name
  std::shared_ptr<const AxisController> controller;  ///< shared with a program built from it
  double held_value = 0.0;  ///< [m] or [N], see AxisController::held_value_key
};

struct Scene {
  std::string title;
  Material material{};
  /// A loading program ([[loading.stage]]), whose scene leaves the shorthand's fields below
  /// unset (glued_radius, preload_depth, normal, tangential); empty for the shorthand
  /// (preload, tangential, normal) but with friction, where it is the shorthand's three
  /// stages (engine/scene/shorthand_program.hpp).
  std::optional<Program> program;
  /// Written with the shorthand keys: the preload and its controls are set. With friction
  /// such a scene runs as its three-stage program too (docs/friction.md).
  bool shorthand() const { return normal.controller != nullptr; }
  std::string profile_name;
  std::shared_ptr<const Profile> profile;  ///< shared by the scene's copies
  /// "file:line:col: profile.type: ", for a refusal of the shape that only the run finds (a
  /// program's rows too coarse for a ripple: their radius is known once its pilot has run).
  std::string profile_at;
  /// "file:line:col: loading.preload: ", for a preload whose Dugdale zone only the run finds
  /// reaching past a body's edge.
  std::string preload_at;
  /// The graded image g_k of the profile where material.grading has k > 0 (docs/graded.md).
  std::optional<GradedImage> graded_image;
  double glued_radius = 0.0;   ///< radius of the contact glued at the preload [m]
  double preload_depth = 0.0;  ///< indentation at the preload [m]
  double preload_force = 0.0;  ///< normal force at the preload, without adhesion [N]
  AxisLoading normal;
  std::optional<AxisLoading> tangential;
  std::string criterion_name;
  std::shared_ptr<const DetachmentCriterion> criterion;  ///< shared by the scene's copies
  /// What lets the edges go, as the outputs name it: "maugis-dugdale" where the Dugdale law's
  /// edge conditions replace the criterion (docs/maugis.md), else the criterion's name.
  std::string detachment_law() const {
    return material.finite_range() ? "maugis-dugdale" : criterion_name;
  }
  /// detachment.front_speed_law: the receding front moves by the rate law (continuum route,
  /// docs/rate_law.md); none: it recedes quasi-statically.
  std::optional<FrontSpeedLaw> front_speed_law;
  /// [friction] where it acts (docs/friction.md); none: springs not glued push frictionlessly.
  std::optional<FrictionSettings> friction;
  std::int64_t springs = 0;  ///< springs across the glued radius (one half)
  DiscretizationOptions discretization;
  SolverOptions solver;
  /// The engine and the driver that answer the scene, decided once as it is built.
  RoutePlan plan;
  /// The scene as built: every key read with its value, defaults included and file paths
  /// absolute; valid scene input that builds this scene again (the JSON result's `scene`).
  std::shared_ptr<const nlohmann::json> resolved;
  /// Accepted but suspicious input (a run reports them with its own warnings).
  std::vector<std::string> warnings;
};

}  // namespace mdrsim
