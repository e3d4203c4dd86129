// The rate law of the receding edge on a program's row: the front's radius a(t) moves between
// the springs by v = v* (G / dgamma - 1)^(1/n), and the springs it passes let go
// (docs/rate_law.md "On the row").
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs scene.program (timed, normal fixed-grips stages, elastic bulk, scene.front_speed_law set)
/// on one row of scene.springs springs across the largest contact radius the program reaches.
/// The front's radius a(t) is one ODE, da/dt = -v(G / dgamma), G = E* e^2 / (2 pi a) with
/// e = g(a) - d(t) the stretch at the front, integrated by Boost.Odeint's dense-output
/// Dormand-Prince 5(4); each spring's let-go, as a passes it, is located on the step's dense
/// output. The force is the glued springs' sum 2 E* dx sum_{x_i <= a} (d - g_i); an advancing
/// front glues spring by spring at the advancing limit, as the program row does. Emits every
/// event but `finished`.
RunResult run_rate_law_row(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
