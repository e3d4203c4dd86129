// A loading program: stages that drive the held values of both axes (docs/programs.md).
#pragma once

#include <cmath>
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
  /// How long the stage lasts (docs/programs.md "Time"): `duration` [s] over the stage
  /// parameter's 0..1 (per unit of it until separation), or `speed`, the rate of the one moving
  /// held value [m/s or N/s], so that the stage lasts |change| / speed. At most one is given.
  std::optional<double> duration;
  std::optional<double> speed;
  /// Whether the stage is timed: it has a duration or a speed.
  bool timed() const { return duration.has_value() || speed.has_value(); }
};

struct Program {
  std::vector<Stage> stages;
  /// A spring that has let go glues again when pressed back (true), or only pushes (false).
  bool rebinding = false;
  /// Every stage has a duration or a speed (the reader refuses some but not all): the program
  /// runs on a clock, t = 0 at its start, and every state it reports has a time.
  bool timed() const { return !stages.empty() && stages.front().timed(); }
};

/// The seconds per unit of the stage parameter of a timed stage whose moving held value
/// changes at `rate` per unit of it (StageLine's rate of the axis that moves; 0 for a hold).
inline double seconds_per_parameter(const Stage& stage, double rate) {
  if (stage.duration) return *stage.duration;
  if (stage.speed) return std::abs(rate) / *stage.speed;
  return 0.0;
}

}  // namespace mdrsim
