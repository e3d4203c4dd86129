// A stage's clock on the continuum routes, where the normal held value is the one that moves:
// each state's time from its normal control (docs/programs.md "Time").
#pragma once

#include <optional>

#include "engine/model/contact_snapshot.hpp"
#include "engine/scene/program.hpp"

namespace mdrsim {

struct ContinuumStageClock {
  double start = 0.0;                 ///< the stage's start time [s]
  double end = 0.0;                   ///< its time at parameter 1 [s]
  double control_start = 0.0;         ///< the normal held value as the stage starts
  double per_control = 0.0;           ///< seconds per unit of the normal held value (0: it holds)
  std::optional<double> control_end;  ///< where the stage ends at parameter 1

  /// The time of a state of the stage whose normal held value is `control`: a stage whose
  /// normal axis holds changes nothing before its end on these routes.
  double at(double control) const {
    if (per_control == 0.0 || (control_end && control == *control_end)) return end;
    return start + per_control * (control - control_start);
  }
  void stamp(ContactSnapshot& s) const { s.time = at(s.normal_control); }
};

/// The clock of `stage`, which starts at `start` [s] with the normal held value c0 and, where it
/// ends at parameter 1, moves it to c1; `tangential_rate` is the tangential held value's change
/// over the stage, where it moves (an untimed program's clock reads 0 throughout).
inline ContinuumStageClock continuum_stage_clock(const Stage& stage, double start, double c0,
                                                 double c1, double tangential_rate = 0.0) {
  ContinuumStageClock clock{.start = start, .end = start, .control_start = c0};
  double rate = 0.0;
  if (stage.normal && stage.normal->motion == StageAxis::Motion::to) rate = c1 - c0;
  if (stage.normal && stage.normal->motion == StageAxis::Motion::by) rate = stage.normal->value;
  // The reader leaves a stage with a speed one moving axis.
  const double per_parameter = seconds_per_parameter(stage, rate != 0.0 ? rate : tangential_rate);
  clock.end = start + per_parameter;
  if (rate != 0.0) clock.per_control = per_parameter / rate;
  if (!stage.until_separation) clock.control_end = c1;
  return clock;
}

}  // namespace mdrsim
