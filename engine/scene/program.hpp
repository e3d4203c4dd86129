// A loading program: stages that drive the held values of both axes (docs/programs.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "controllers/controller.hpp"

namespace mdrsim {

/// One axis as a stage names it: its controller and how its held value moves over the stage.
struct StageAxis {
  std::string control;  ///< the controller's registered name
  std::shared_ptr<const AxisController> controller;
  enum class Motion { hold, to, by };
  Motion motion = Motion::hold;
  /// `to`: the held value at the end of the stage; `by`: its change over the stage (per unit
  /// of the stage parameter under until = "separation") [m or N, see held_value_key].
  double value = 0.0;
};

struct Stage {
  std::string name;  ///< "stage N" when the scene gives none
  /// An axis the stage does not name keeps its controller and held value.
  std::optional<StageAxis> normal;
  std::optional<StageAxis> tangential;
  /// The stage parameter runs past 1 until no spring is in contact.
  bool until_separation = false;
};

struct Program {
  std::vector<Stage> stages;
  /// A spring that has let go glues again when pressed back (true), or only pushes (false).
  bool rebinding = false;
};

}  // namespace mdrsim
