// The continuum route's reach: shorthand scenes on the convex classic profiles, and normal
// loading programs on them when asked; else the row.
#include "engine/scene/continuum_scope.hpp"

#include <fmt/format.h>

#include "engine/scene/scene_error.hpp"

namespace mdrsim {

bool continuum_answers(const Scene& scene) {
  // dgamma(r) pins the front and lets it jump at every change: several folds.
  if (scene.material.adhesion_varies()) return false;
  // One fold on the branch: the shapes that are always one disk (convex classics). A table
  // or a ripple may fold several times; the row follows every jump.
  if (scene.program) {
    // A tangential stage may meet what the route stops at (a glue let go by the moving shear,
    // pressed springs after a shear-off), which rtol alone must not end in: such programs
    // take the route only when it is named, and the row otherwise.
    for (const Stage& stage : scene.program->stages) {
      if (stage.tangential) return false;
    }
    return !continuum_program_refusal(scene);
  }
  return scene.profile->always_one_disk();
}

std::optional<std::string> continuum_program_refusal(const Scene& scene) {
  if (!scene.program) return std::nullopt;
  if (scene.friction) {
    return "a loading program with [friction] needs the spring row (stick and slip spring by "
           "spring)";
  }
  if (!scene.profile->always_one_disk() || scene.profile->fixed_contact_radius()) {
    return fmt::format(
        "a loading program on profile \"{}\" is not on the continuum route (its front may "
        "fold more than once, or, for the flat punch, never moves)",
        printable(scene.profile_name));
  }
  // Each stage's direction, where the held values tell it before the run: a press after a
  // stage that may have let springs go needs rebinding (the springs glue again at the
  // advancing limit; without it they push back unglued).
  bool grips = true;
  double held = 0.0;  ///< the normal held value [m or N], where `known`
  bool known = true;
  bool may_have_let_go = false;
  bool tangential_moved = false;
  for (const Stage& stage : scene.program->stages) {
    enum class Direction { none, press, pull, unknown } direction = Direction::none;
    if (stage.normal) {
      const bool force = stage.normal->controller->holds_force();
      if (force == grips) known = false;  // a new control takes its held value from the state
      grips = !force;
      switch (stage.normal->motion) {
        case StageAxis::Motion::hold:
          break;
        case StageAxis::Motion::by:
          direction = stage.normal->value > 0.0   ? Direction::press
                      : stage.normal->value < 0.0 ? Direction::pull
                                                  : Direction::none;
          held += stage.normal->value;
          break;
        case StageAxis::Motion::to:
          direction = !known                       ? Direction::unknown
                      : stage.normal->value > held ? Direction::press
                      : stage.normal->value < held ? Direction::pull
                                                   : Direction::none;
          held = stage.normal->value;
          known = true;
          break;
      }
    }
    const bool presses = direction == Direction::press || direction == Direction::unknown;
    const bool pulls = direction == Direction::pull || direction == Direction::unknown;
    if (presses && tangential_moved) {
      return fmt::format(
          "stage '{}' may press the contact after the tangential axis moved: the springs it "
          "glues would carry another tangential stretch than the glue's, which the continuum "
          "route does not follow",
          printable(stage.name));
    }
    if (stage.tangential && stage.tangential->motion != StageAxis::Motion::hold) {
      tangential_moved = true;
    }
    if (presses && may_have_let_go && !scene.program->rebinding) {
      return fmt::format(
          "stage '{}' may press the contact again after springs let go: without "
          "loading.rebinding = true they push back unglued, which the continuum route does "
          "not follow",
          printable(stage.name));
    }
    if (pulls) may_have_let_go = true;
  }
  for (const Stage& stage : scene.program->stages) {
    if (stage.tangential) {
      if (stage.tangential->controller->drives_through_spring()) {
        return fmt::format(
            "stage '{}' drives the tangential axis through a machine spring (control = "
            "\"{}\"): the continuum route runs fixed grips and fixed loads",
            printable(stage.name), printable(stage.tangential->control));
      }
      if (stage.until_separation) {
        return fmt::format(
            "stage '{}' shears until separation: a front receding under a moving tangential "
            "load is the row's, not the continuum route's",
            printable(stage.name));
      }
      if (stage.normal && stage.normal->motion != StageAxis::Motion::hold) {
        return fmt::format(
            "stage '{}' moves the tangential axis together with the normal one: the "
            "continuum route moves one axis per stage",
            printable(stage.name));
      }
    }
    if (stage.normal && stage.normal->controller->drives_through_spring()) {
      return fmt::format(
          "stage '{}' drives through a machine spring (control = \"{}\"): the continuum "
          "route runs programs under fixed grips and fixed loads",
          printable(stage.name), printable(stage.normal->control));
    }
    if (stage.until_separation && stage.normal && stage.normal->value > 0.0) {
      return fmt::format("stage '{}' presses until separation, which never comes",
                         printable(stage.name));
    }
  }
  return std::nullopt;
}

}  // namespace mdrsim
