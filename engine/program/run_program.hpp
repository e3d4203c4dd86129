// Runs a loading program: a pilot row finds the largest contact, the final row spans it.
#pragma once

#include <optional>

#include "engine/events/observer.hpp"
#include "engine/program/held_front.hpp"
#include "engine/program/program_runner.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Where a program's rows put their springs: spring N of any row sits at `radius`, the
/// largest contact radius the program reaches, with g there taken as `image`.
struct ProgramRowFrame {
  double radius;   ///< a_max [m]
  double image;    ///< g(a_max), or the front value it equals up to rounding [m]
  ZeroScale zero;  ///< what is zero on every row of the frame (program_zero_scale)
  /// Where a force or a machine spring holds the deepest state: each row's own radius is
  /// solved from it (held_front.hpp), `radius` being the continuum front there.
  std::optional<HeldDeepest> held;
};

/// g(x) [m] at x [m] on a program's rows: the graded image g_k where the half-space is graded.
double program_image(const Scene& scene, double x);

/// What is zero on a program's rows spanning `radius` [m] with g = `image` [m] there: the
/// scene's E*, work of adhesion and largest force a fixed-load stage holds (zero_scale.hpp).
ZeroScale program_zero_scale(const Scene& scene, double radius, double image);

/// Runs a 256-spring pilot to find a_max (the continuum front at the deepest indentation).
ProgramRowFrame program_row_frame(const Scene& scene);
/// The row of `springs` springs in that frame: spring N at the frame's radius, or where a
/// held force makes this row's own deepest state glue spring N (frame.held).
ProgramRowSpec program_row(const Scene& scene, const ProgramRowFrame& frame, std::int64_t springs);

/// Runs scene.program (which must be set) on scene.springs springs across the largest
/// contact radius the program reaches (docs/programs.md "How it runs"), and emits every event but
/// `finished`.
RunResult run_program(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
