// rtol on a loading program: rows doubled in one frame until every stage end and every jump's
// critical point agree across rows within rtol.
#pragma once

#include "engine/events/observer.hpp"
#include "engine/run/pull_off.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs rows of 256, 512, ... springs across the program's a_max (run_program.hpp) until the
/// plain-row estimate 2 max(|Q_j - Q_j-1|, |Q_j-1 - Q_j-2| / 2) of every checked force Q (the
/// normal and tangential force at every stage's end, the normal force at every jump's
/// critical point and after it, and at the reported critical point and peak) is within
/// rtol max(|Q|, 1e-6 F_path), F_path the largest of those forces; at least four rows, and the
/// last three must end alike (status, stages, jumps). Past the row cap it reports the finest
/// row with rtol_met false and a warning. Emits the finest row's events.
RunResult run_program_rtol(const Scene& scene, double rtol, const ObserverList& observers);

}  // namespace mdrsim
