// Reads [[loading.stage]] into a Program; messages name the stage as loading.stage.N, N from 1.
#include "engine/scene/program_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// A cap that keeps a generated or corrupted file from building millions of stages.
constexpr std::size_t kMaxStages = 100'000;

/// docs: a program starts with both axes under fixed-grips holding 0.
constexpr const char* kStartControl = "fixed-grips";

constexpr const char* kEitherShorthandOrStages =
    "a scene has either the shorthand keys (preload, tangential, normal) or [[loading.stage]], "
    "not both";

constexpr const char* kClockPerStage =
    "is a key of each [[loading.stage]]: every stage of a timed program gives its own";

/// The controller an axis is under as the stages go by.
struct AxisControl {
  std::string name;
  std::shared_ptr<const AxisController> controller;
};

/// A name that reads as one word in the trajectory CSV and the JSON result.
bool is_stage_name(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_';
  });
}

/// A coefficient that is not finite (a compliant stiffness near the smallest double gives
/// 1/k = inf) makes every equilibrium of the axis NaN.
void check_finite_constraint(const TomlReader& t, const StageAxis& axis) {
  const AffineConstraint c = axis.controller->constraint();
  if (!std::isfinite(c.displacement_coefficient) || !std::isfinite(c.force_coefficient)) {
    t.fail(
        fmt::format("control = \"{}\" is degenerate with these values (constraint a_u = {}, "
                    "a_F = {} m/N)",
                    axis.control, c.displacement_coefficient, c.force_coefficient));
  }
}

/// One axis table of a stage. `current` is the axis's controller before the stage; the stage
/// leaves in it the controller it ends with.
StageAxis read_stage_axis(TomlReader& t, const ControllerRegistry& controllers,
                          bool until_separation, AxisControl& current) {
  const std::vector<std::string> motion_keys{"to", "by"};
  StageAxis axis;
  if (t.has("control")) {
    axis.control = t.name("control", controllers.names());
    check_part_keys(t, "control", axis.control, controllers, motion_keys);
    const auto* entry = controllers.find(axis.control);
    const ParameterValues values = t.read_all(entry->parameters);
    axis.controller = create_part(t, "control", [&] { return entry->create(values); });
    check_finite_constraint(t, axis);
    current = {axis.control, axis.controller};
  } else {
    check_part_keys(t, "control", current.name, controllers, motion_keys);
    // Without control the axis keeps its controller object; a parameter given alone would
    // have to make a new one, with the other parameters guessed.
    for (const ParameterSpec& spec : controllers.find(current.name)->parameters) {
      if (t.has(spec.key)) {
        t.fail_at(spec.key, fmt::format("give control = \"{}\" with it: an axis without control "
                                        "keeps its controller as it was",
                                        current.name));
      }
    }
    axis.control = current.name;
    axis.controller = current.controller;
  }
  if (t.has("to") && t.has("by")) t.fail_at("by", "give to or by, not both");
  if (until_separation && t.has("to")) {
    t.fail_range("to",
                 "is refused with until = \"separation\": by is the change per unit of the stage "
                 "parameter");
  }
  // In the controller's held unit (m or N), any sign: a stage may press, pull or shear back.
  if (const auto to = t.optional_number({.key = "to"})) {
    axis.motion = StageAxis::Motion::to;
    axis.value = *to;
  } else if (const auto by = t.optional_number({.key = "by"})) {
    axis.motion = StageAxis::Motion::by;
    axis.value = *by;
  }
  t.finish();
  return axis;
}

/// Whether the axis drives its held value: a stage until separation needs one that does.
bool moves(const std::optional<StageAxis>& axis) {
  return axis && axis->motion == StageAxis::Motion::by && axis->value != 0.0;
}

/// Whether the axis moves its held value over the stage: `to` (its change is known only as the
/// stage starts) or a non-zero `by`.
bool moves_held_value(const std::optional<StageAxis>& axis) {
  return axis && (axis->motion == StageAxis::Motion::to ||
                  (axis->motion == StageAxis::Motion::by && axis->value != 0.0));
}

/// A stage's `duration` or `speed` (docs/programs.md "Time").
void read_stage_clock(TomlReader& t, Stage& stage) {
  if (t.has("duration") && t.has("speed")) t.fail_at("speed", "give duration or speed, not both");
  stage.duration = t.optional_number(
      {.key = "duration",
       .help = "the stage's duration [s] (per unit of the stage parameter until separation), > 0",
       .lower = Bound{0.0, false}});
  stage.speed =
      t.optional_number({.key = "speed",
                         .help = "the rate of the stage's moving held value [m/s or N/s], > 0",
                         .lower = Bound{0.0, false}});
  if (!stage.speed) return;
  const bool normal = moves_held_value(stage.normal);
  const bool tangential = moves_held_value(stage.tangential);
  if (!normal && !tangential) {
    t.fail_at("speed", "needs a moving axis (to, or a non-zero by); give duration for a hold");
  }
  // Two held values, perhaps a force and a displacement, have no one rate.
  if (normal && tangential) {
    t.fail_at("speed", "needs one moving axis; give duration for a stage that moves both");
  }
}

/// The stage numbers (from 1) of the names the scene gave so far.
using StageNumbers = std::map<std::string, std::size_t, std::less<>>;

Stage read_stage(TomlReader& t, std::size_t number, const ControllerRegistry& controllers,
                 AxisControl& normal, AxisControl& tangential, StageNumbers& named) {
  t.check_keys({"name", "normal", "tangential", "until", "duration", "speed"});
  Stage stage;
  if (const auto name = t.optional_text("name")) {
    if (!is_stage_name(*name)) {
      t.fail_at("name", fmt::format("\"{}\" is not a stage name: give letters, digits, '-' and "
                                    "'_' only, at least one",
                                    printable(*name)));
    }
    // A default name "stage N" holds a space, so only names the scene gives can clash.
    if (const auto [it, fresh] = named.emplace(*name, number); !fresh) {
      t.fail_at("name", fmt::format("\"{}\" is the name of loading.stage.{} already; stage names "
                                    "must differ",
                                    *name, it->second));
    }
    stage.name = *name;
  } else {
    stage.name = fmt::format("stage {}", number);
  }
  stage.until_separation = t.name("until", {"end", "separation"}, "end") == "separation";
  if (auto axis = t.optional_table("normal")) {
    stage.normal = read_stage_axis(*axis, controllers, stage.until_separation, normal);
  }
  if (auto axis = t.optional_table("tangential")) {
    stage.tangential = read_stage_axis(*axis, controllers, stage.until_separation, tangential);
  }
  if (stage.until_separation && !moves(stage.normal) && !moves(stage.tangential)) {
    t.fail_at(
        "until",
        "\"separation\" needs a non-zero by on normal or tangential, or the stage never ends");
  }
  read_stage_clock(t, stage);
  t.finish();
  return stage;
}

}  // namespace

Program read_program(TomlReader& loading, const ControllerRegistry& controllers) {
  loading.check_keys({"stage", "rebinding"},
                     [](std::string_view key) -> std::optional<std::string> {
                       if (key == "preload" || key == "tangential" || key == "normal") {
                         return kEitherShorthandOrStages;
                       }
                       if (key == "duration" || key == "speed") return kClockPerStage;
                       return std::nullopt;
                     });
  Program program;
  const auto rebinding = loading.optional_boolean("rebinding");
  if (!rebinding) loading.record("rebinding", false);
  program.rebinding = rebinding.value_or(false);
  std::vector<TomlReader> stages = *loading.optional_table_array("stage", kMaxStages);

  const auto* start = controllers.find(kStartControl);
  if (!start) {
    throw std::logic_error("no fixed-grips controller registered: programs start with it");
  }
  const std::shared_ptr<const AxisController> fixed_grips = start->create(ParameterValues{});
  AxisControl normal{kStartControl, fixed_grips};
  AxisControl tangential{kStartControl, fixed_grips};

  StageNumbers named;
  program.stages.reserve(stages.size());
  for (std::size_t i = 0; i < stages.size(); ++i) {
    program.stages.push_back(read_stage(stages[i], i + 1, controllers, normal, tangential, named));
  }
  // A clock that stops part way would leave later states without a time.
  const auto timed = std::find_if(program.stages.begin(), program.stages.end(),
                                  [](const Stage& s) { return s.timed(); });
  if (timed != program.stages.end()) {
    for (std::size_t i = 0; i < stages.size(); ++i) {
      if (!program.stages[i].timed()) {
        stages[i].fail(fmt::format(
            "has neither duration nor speed, which loading.stage.{} gives: a timed program "
            "gives every stage one",
            (timed - program.stages.begin()) + 1));
      }
    }
  }
  return program;
}

void check_shorthand_keys(TomlReader& loading, TomlReader& material, const Material& values) {
  loading.check_keys({"preload", "tangential", "normal"},
                     [](std::string_view key) -> std::optional<std::string> {
                       if (key == "rebinding") {
                         return "applies to loading programs ([[loading.stage]]) only";
                       }
                       if (key == "duration" || key == "speed") {
                         return "applies to a stage of a loading program ([[loading.stage]]); "
                                "the shorthand has no stage to time";
                       }
                       return std::nullopt;
                     });
  if (values.approach_work_of_adhesion > 0.0 || values.approach_work_of_adhesion_by_radius) {
    material.fail_at("approach_work_of_adhesion",
                     "applies to loading programs ([[loading.stage]]) only; the shorthand's "
                     "preload glues on touch");
  }
}

void require_timed_program(const TomlReader& table, std::string_view key, const Program* program) {
  if (program && program->timed()) return;
  table.fail_at(key, fmt::format("a program whose every stage has duration or speed is needed "
                                 "with {}",
                                 table.key_path(key)));
}

}  // namespace mdrsim
