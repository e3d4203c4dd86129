// One Maugis-Dugdale spring row of a scene as a run's result: status, states, stages, jump, work.
#pragma once

#include <cstdint>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// The scene's shorthand (material.finite_range(), no tangential load) on a Dugdale row of
/// `springs` springs across `preload_radius`, a_p: the contact branch's radius at the preload
/// depth, to which the zone pulls the contact glued at a_g (docs/maugis.md "The path of the
/// shorthand"), so that the row's path is the continuum route's from its first state on.
/// - Stage `preload` ends at the row's first equilibrium (a = a_p, d = d_p); its work is the
///   energy the row's springs inside a_g store pressed to d_p, E* dx sum (d_p - g_i)^2 (the
///   cell across a_g by its part inside), as on the JKR row.
/// - Stage `pull-off`: the machine's work int F dd by trapezoids between the let-gos (and the
///   no-contact branch's by Gauss-Kronrod in c), to the critical point located between springs,
///   plus a compliant machine's spring energy F^2 / 2k; its end and the one jump as the
///   continuum route's.
/// `critical` and `refined_critical` are both the fold located between springs (likewise the
/// peak): rows of doubling springs converge at first order in 1/N (docs/maugis_row.md).
/// Emits preload_reached and a spring_detached per let-go; the caller emits the closing events.
RunResult run_dugdale_row_scene(const Scene& scene, std::int64_t springs, double preload_radius,
                                const ObserverList& observers);

}  // namespace mdrsim
