// The continuum route for loading programs on one glued disk, whose front advances and
// recedes on closed relations, with no spring row.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// A loading program on the continuum (docs/continuum.md "Programs"): the glued
/// disk of radius a at indentation d is pinned while the boundary stretch e = g(a) - d lies
/// between the advancing limit sqrt(2 pi a dgamma_a / E*) and the criterion's let-go stretch;
/// its front advances on the first and recedes on the second, and jumps where the stage's
/// control folds (jump-in at touch, jump-out at the fold). Stages, jumps, the critical point,
/// the peak and the work, each from closed relations, root searches and Gauss-Kronrod
/// quadrature to `rtol`; `samples` points of the path as `sample` events. A tangential stage
/// moves u_x on the uniformly stretched glue, which the later stages hold. Scenes the route
/// cannot answer are refused before the run (continuum_program_refusal); where the path
/// leaves the one glued disk as it runs (the glue let go by a moving shear, or broken
/// unstretched over pressed springs) it says so in `cannot_follow`, before emitting any event
/// (stage ends and samples are emitted once every stage stands): what to do then is the
/// route's (engine/run/run_scene.cpp), not the engine's.
struct ContinuumProgramRun {
  RunResult result;
  /// Why the route cannot follow the program past a stage (one line, naming it); empty: done.
  std::optional<std::string> cannot_follow;
};
ContinuumProgramRun run_continuum_program(const Scene& scene, double rtol, std::int64_t samples,
                                          const ObserverList& observers);

}  // namespace mdrsim
