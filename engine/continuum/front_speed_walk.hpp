// The receding front under the rate law on the continuum branch: a(t) as one ODE while the
// normal grips move at a constant rate (docs/rate_law.md).
#pragma once

#include <optional>
#include <vector>

#include "engine/continuum/continuum_branch.hpp"
#include "engine/model/front_speed_law.hpp"

namespace mdrsim {

/// Where the walk starts: the disk of radius a at indentation d at time t, the grips moving at
/// `rate` [m/s] (0: a hold) until `end_time` [s] (infinite: until the contact is lost).
struct FrontSpeedStart {
  double radius = 0.0;       ///< [m]
  double indentation = 0.0;  ///< [m]
  double time = 0.0;         ///< [s]
  double rate = 0.0;         ///< dd/dt [m/s]
  double end_time = 0.0;     ///< [s]
};

/// One accepted step of the walk, for the trajectory's samples.
struct FrontSpeedPoint {
  double time = 0.0;         ///< [s]
  double radius = 0.0;       ///< [m]
  double indentation = 0.0;  ///< [m]
};

struct FrontSpeedWalk {
  BranchState end;                  ///< at end_time, or where the front reached a = 0 (`lost`)
  double end_time = 0.0;            ///< [s]
  bool lost = false;                ///< the front reached the axis: the contact is lost
  std::optional<BranchState> peak;  ///< the most tensile state, where F turns inside the walk
  double peak_time = 0.0;           ///< [s]
  double machine_work = 0.0;        ///< int F dd over the walk [J]
  double dissipated = 0.0;          ///< int (G - dgamma) 2 pi a |da| [J]
  /// The walk's error estimates: the difference from a walk at a ten times looser tolerance.
  double peak_error = 0.0;    ///< [N]
  double energy_error = 0.0;  ///< of machine_work and dissipated [J]
  double end_error = 0.0;     ///< of the end's indentation [m]
  long long steps = 0;        ///< accepted steps of both walks
  std::vector<FrontSpeedPoint> path;
};

/// The front's walk on `branch` (normal fixed grips, no tangential stretch, not graded) from
/// `start`: da/dt = -v(G / dgamma) with G = E* e^2 / (2 pi a), e = g(a) - d the boundary
/// stretch (0 in compression), by Runge-Kutta-Fehlberg 7(8) at a local tolerance of rtol / 100;
/// in t while the front is slow, then in a down to the axis once G can only grow (the front
/// faster than v*, the grips not pressing, 2 a g'(a) < e). The peak is the root of dF/dt =
/// 2 E* (a dd/dt - e da/dt), located by redoing the step that brackets it (TOMS 748).
FrontSpeedWalk walk_front_speed(const ContinuumBranch& branch, const FrontSpeedLaw& law,
                                const FrontSpeedStart& start, double rtol);

}  // namespace mdrsim
