// A stage's `to` and `by` given meaning in one place: how the held value of each axis moves
// over the stage parameter t, for the program loop and for the frame chosen before it.
#pragma once

#include <optional>

#include "engine/scene/program.hpp"

namespace mdrsim {

/// The held value of one axis over a stage: start + rate t; with `to` it lands exactly on
/// `end` at t = 1 (a stage that stops there).
struct AxisMotion {
  double start = 0.0;
  double rate = 0.0;
  std::optional<double> end;

  /// The held value at t (t = 1: exactly `end` where there is one and the stage stops at 1).
  double at(double t, bool until_separation) const {
    if (t == 1.0 && end && !until_separation) return *end;
    return start + rate * t;
  }
};

/// The motion `axis` gives a held value that is `start` as the stage begins: `to` moves it to
/// the value over t in [0, 1], `by` by the value per unit of t, an axis the stage does not
/// move (or name) holds it.
inline AxisMotion axis_motion(const std::optional<StageAxis>& axis, double start) {
  AxisMotion m{start, 0.0, std::nullopt};
  if (axis && axis->motion == StageAxis::Motion::to) {
    m.rate = axis->value - start;
    m.end = axis->value;
  }
  if (axis && axis->motion == StageAxis::Motion::by) m.rate = axis->value;
  return m;
}

/// The held value after a stage, known before the run: `to` its value, `by` start plus its
/// value where the stage stops at t = 1; a stage until separation runs to an end the path
/// decides, and `start` stands for it (the callers ask where the held value is known).
inline double held_after(const StageAxis& axis, double start, bool until_separation) {
  if (axis.motion == StageAxis::Motion::to) return axis.value;
  if (axis.motion == StageAxis::Motion::by && !until_separation) return start + axis.value;
  return start;
}

}  // namespace mdrsim
