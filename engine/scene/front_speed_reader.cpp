// detachment.front_speed_law: the key and the scope the rate law runs in.
#include "engine/scene/front_speed_reader.hpp"

#include <fmt/format.h>

#include "engine/scene/program_reader.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

constexpr const char* kFrontSpeedScope = " (docs/rate_law.md)";

[[noreturn]] void refuse_front_speed(const std::string& at, const std::string& why) {
  throw SceneError(fmt::format("{}{}{}", at, why, kFrontSpeedScope));
}

}  // namespace

std::optional<FrontSpeedLaw> read_front_speed_law(TomlReader& t, const Scene& scene,
                                                  std::string& at) {
  auto table = t.optional_table("front_speed_law");
  if (!table) return std::nullopt;
  at = t.message_at("front_speed_law", "");
  table->check_keys({"speed", "exponent"});
  FrontSpeedLaw law;
  law.speed = table->number({.key = "speed",
                             .help = "v* [m/s] > 0: v = v* (G / dgamma - 1)^(1/n)",
                             .lower = Bound{0.0, false}});
  law.exponent = table->number({.key = "exponent",
                                .help = "n [1], 0 < n <= 1",
                                .lower = Bound{0.0, false},
                                .upper = Bound{1.0, true}});
  table->finish();
  require_timed_program(t, "front_speed_law", scene.program ? &*scene.program : nullptr);
  return law;
}

void refuse_outside_front_speed_scope(const Scene& scene, const std::string& at) {
  if (!scene.front_speed_law) return;
  const Material& m = scene.material;
  if (m.finite_range()) {
    refuse_front_speed(at, "is not yet taken with adhesive_stress or maugis_parameter");
  }
  if (m.grading.graded()) refuse_front_speed(at, "is not yet taken with material.grading");
  if (scene.friction) refuse_front_speed(at, "is not yet taken with [friction]");
  if (m.adhesion_varies()) {
    refuse_front_speed(at, "is not yet taken with a work of adhesion that varies with the radius");
  }
  if (!(m.work_of_adhesion > 0.0)) {
    refuse_front_speed(at, "needs material.work_of_adhesion > 0: its threshold toughness");
  }
  for (const Stage& stage : scene.program->stages) {
    if (stage.tangential) {
      refuse_front_speed(at, fmt::format("stage '{}': a tangential axis is not yet taken with the "
                                         "rate law",
                                         printable(stage.name)));
    }
    if (stage.normal && !is_fixed_grips(stage.normal->controller->constraint())) {
      refuse_front_speed(at, fmt::format("stage '{}': only normal fixed grips are taken with the "
                                         "rate law so far",
                                         printable(stage.name)));
    }
  }
  if (scene.plan.engine == RouteEngine::continuum) return;
  // The program row: the event method's rows, an elastic or a relaxing bulk.
  if (scene.solver.method != SolverMethod::event) {
    refuse_front_speed(at,
                       "runs on the row with solver.method = \"event\" (or on the continuum "
                       "route: solver.method = \"continuum\")");
  }
  // A press after a stage in which the front may have receded (a pull, or a hold: the front
  // recedes while G > dgamma) needs rebinding: the springs glue again at the advancing limit;
  // without it they would push back unglued, which the row's front does not follow. On a
  // relaxing bulk a let-go spring creeps free, which the row does not follow back into contact.
  if (scene.program->rebinding && !m.relaxes()) return;
  double held = 0.0;
  bool may_have_let_go = false;
  for (const Stage& stage : scene.program->stages) {
    double next = held;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::to) next = stage.normal->value;
    if (stage.normal && stage.normal->motion == StageAxis::Motion::by) {
      next = held + stage.normal->value;
    }
    const bool presses = next > held && !stage.until_separation;
    if (presses && may_have_let_go && m.relaxes()) {
      refuse_front_speed(at, fmt::format("stage '{}' may press the contact again after springs "
                                         "let go: not yet taken with material.relaxation",
                                         printable(stage.name)));
    }
    if (presses && may_have_let_go) {
      refuse_front_speed(at, fmt::format("stage '{}' may press the contact again after springs "
                                         "let go: the rate law's row needs loading.rebinding = "
                                         "true",
                                         printable(stage.name)));
    }
    if (!presses) may_have_let_go = true;
    held = next;
  }
}

}  // namespace mdrsim
