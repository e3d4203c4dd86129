// A first row of the shorthand tells whether its glue lets go with the indenter pressed in.
#include "engine/run/shorthand_as_program.hpp"

#include <algorithm>

#include "engine/pull_off/pull_off.hpp"

namespace mdrsim {

bool ends_pressed_in(const RunResult& result) {
  return !result.jumps.empty() && result.jumps.back().end == JumpEnd::pressed;
}

Scene as_its_program(const Scene& scene) {
  Scene as_program = scene;
  as_program.program = scene.plan.shorthand_stages;
  if (as_program.solver.method == SolverMethod::continuum) {
    as_program.solver.method = SolverMethod::event;
  }
  RoutePlan& plan = as_program.plan;
  plan.engine = RouteEngine::program_row;
  plan.reason =
      "the shorthand's glue lets go with the indenter pressed in: its three stages "
      "run as a program";
  plan.continuum_chosen_at.clear();
  plan.continuum_by_rtol = false;
  plan.shorthand_stages.reset();
  return as_program;
}

std::optional<Scene> pressed_in_on_a_first_row(const Scene& scene) {
  // The Dugdale row's glue is the zone's, which lets go with the zone pulling, not pressed in.
  if (scene.plan.engine != RouteEngine::pull_off_row || !scene.plan.shorthand_stages ||
      scene.material.finite_range()) {
    return std::nullopt;
  }
  const RunResult first = run_row(scene,
                                  {.springs = std::min(kPressedCheckSprings, scene.springs),
                                   .outer_radius = scene.glued_radius,
                                   .record_path = true},
                                  {});
  if (!ends_pressed_in(first)) return std::nullopt;
  return as_its_program(scene);
}

}  // namespace mdrsim
