// The continuum route's reach: shorthand scenes whose branch folds once (the convex classic
// profiles, power laws by their proof), and normal loading programs on the convex classics;
// else the row.
#include "engine/scene/continuum_scope.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "detachment/criterion_registry.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// Whether the criterion lets go at Hess's e = sqrt(w a), w = 2 pi dgamma / E*, with no
/// tangential load: every built-in does (docs/scene.md's criterion table at u_x = 0); a user's
/// own criterion may not.
bool lets_go_at_hess(const Scene& scene) {
  static const CriterionRegistry builtin = [] {
    CriterionRegistry r;
    register_builtin_criteria(r);
    return r;
  }();
  return builtin.find(scene.criterion_name) != nullptr;
}

/// Whether the shorthand's branch is the JKR one (Hess's let-go, u_x = 0) and folds at most
/// once, from how sqrt(a) g'(a) grows (Profile::image_slope_growth). With e = sqrt(w a),
/// nf' = 2 a g', F' = E* (2 a g' - 3 sqrt(w a)) and beta = a_F E*, the control
/// c = a_u (g - e) + a_F E* (nf - 2 a e) has
///   c'(a) = a^(-1/2) [ sqrt(a) g'(a) (a_u + 2 beta a) - (sqrt(w)/2) (a_u + 6 beta a) ],
/// zero where P(a) = sqrt(a) g'(a) (a_u + 2 beta a) / (a_u + 6 beta a) meets sqrt(w)/2. A fold
/// (c' turning from > 0 to < 0 as a falls) is P crossing that level upwards; if ln P is
/// monotone it crosses once: rising, one fold; falling, a maximum of c (only a_g itself may
/// be unstable, and below a jump from it the branch is stable down to a -> 0). With
/// y = beta a / a_u, d ln P / d ln a = s(a) - 4 y / ((1 + 2 y)(1 + 6 y)), whose second term is
/// 0 under fixed grips (beta = 0) and a fixed load (a_u = 0) and at most 2 - sqrt 3 = 0.268 (at
/// y = 1/sqrt 12) under a compliant machine. Hence at most one fold for every E*, dgamma and
/// stiffness where s >= 0 (fixed grips, fixed load), s >= 2 - sqrt 3 (compliant) or s <= 0:
/// a power law with n <= 1/2 or n >= 1/2 (2.5 - sqrt 3 = 0.768 compliant). Between, a compliant
/// machine can fold the branch twice (tests/engine/scene/continuum_scope_test.cpp).
bool jkr_branch_folds_once(const Scene& scene) {
  if (scene.tangential && scene.tangential->held_value != 0.0) return false;
  if (!lets_go_at_hess(scene)) return false;
  const std::optional<LogSlopeRange> s = scene.profile->image_slope_growth();
  if (!s) return false;
  if (s->high <= 0.0) return true;
  const AffineConstraint normal = scene.normal.controller->constraint();
  const bool compliant = normal.displacement_coefficient != 0.0 && normal.force_coefficient != 0.0;
  const double most_the_machine_takes = compliant ? 2.0 - std::sqrt(3.0) : 0.0;
  return s->low >= most_the_machine_takes;
}

}  // namespace

bool continuum_answers(const Scene& scene) {
  // The continuum route has no relaxing bulk: rtol alone refines the viscoelastic row.
  if (scene.material.relaxes()) return false;
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
  return scene.profile->always_one_disk() || jkr_branch_folds_once(scene);
}

std::optional<std::string> continuum_program_refusal(const Scene& scene) {
  if (!scene.program) return std::nullopt;
  // The Dugdale law is one law both ways (rebinding implied); its scope is dugdale_reader's.
  if (scene.material.finite_range()) return std::nullopt;
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
