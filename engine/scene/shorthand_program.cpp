// The shorthand's three stages, built from its resolved scene.
#include "engine/scene/shorthand_program.hpp"

#include <cmath>
#include <stdexcept>

namespace mdrsim {

Program shorthand_program(const Scene& scene, const ControllerRegistry& controllers) {
  const auto* fixed_grips = controllers.find("fixed-grips");
  if (!fixed_grips) throw std::logic_error("no fixed-grips controller registered");
  Program program;
  program.rebinding = false;  // the shorthand's glue never rebinds

  Stage preload{.name = "preload"};
  preload.normal = StageAxis{.control = "fixed-grips",
                             .controller = fixed_grips->create(ParameterValues{}),
                             .motion = StageAxis::Motion::to,
                             .value = scene.preload_depth};
  program.stages.push_back(std::move(preload));

  const StageAxis normal{.control = scene.normal.control, .controller = scene.normal.controller};
  Stage tangential{.name = "tangential", .normal = normal};
  if (scene.tangential) {
    tangential.tangential = StageAxis{.control = scene.tangential->control,
                                      .controller = scene.tangential->controller,
                                      .motion = StageAxis::Motion::to,
                                      .value = scene.tangential->held_value};
  }
  program.stages.push_back(std::move(tangential));

  Stage pull_off{.name = "pull-off", .normal = normal, .until_separation = true};
  const bool force = scene.normal.controller->holds_force();
  pull_off.normal->motion = StageAxis::Motion::by;
  pull_off.normal->value = -(force ? std::abs(scene.preload_force) : scene.preload_depth);
  program.stages.push_back(std::move(pull_off));
  return program;
}

}  // namespace mdrsim
