// Accuracy on a loading program: rtol (rows doubled in one frame until every stage end and
// every jump meets it) and Richardson with a fixed springs.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs rows of 256, 512, ... springs across the program's a_max (run_program.hpp), each
/// reported state also located between springs (program_front.hpp), until every checked force
/// is within rtol max(|Q|, 1e-6 F_path) by its estimate over the last four rows (which must
/// end alike: status, stages, jumps): the normal and tangential force at every stage's end,
/// the normal force at every jump's critical point and after it, at the reported critical
/// point and at the peak. Per state the value is Richardson's where every row located it and
/// its estimate is the smaller (extrapolation = "richardson" takes it wherever located, "none"
/// never), else the finest row's own with the plain estimate 2 max(|Q_j - Q_j-1|,
/// |Q_j-1 - Q_j-2| / 2) plus the edge spring's force. Past the row cap it reports the finest
/// row with rtol_met false and a warning. Emits the finest row's events.
RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers);

/// Richardson on a program: rows of N/2, N and 2N springs in one frame, each reported state
/// located between springs (program_front.hpp) and extrapolated from the two finer rows, its
/// estimate twice the change from the coarser pair. A state that a row cannot locate between
/// springs keeps the finest row's value and the plain estimate above, with a warning. Emits
/// the finest row's events.
RunResult run_program_richardson(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
