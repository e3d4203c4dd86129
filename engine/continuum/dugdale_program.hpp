// Loading programs with finite-range adhesion (Maugis-Dugdale) on the continuum route.
#pragma once

#include <cstdint>

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// A normal loading program on the Dugdale law's one reversible set of equilibria
/// (docs/maugis.md "Programs"): separated (d below f(0) - h0, F = 0), the no-contact branch (the
/// zone's disk of radius c alone) and the contact branch (dugdale_contact_state), one curve.
/// Approach and retraction follow the same curve; the state moves along it while its control
/// rises the way the stage drives it, and jumps at a fold of the control to the first
/// equilibrium beyond, of the same control, on the curve's stable side (none under a tensile
/// fixed load past the separated end: the indenter flies off). Stages, jumps, the critical
/// point (the first jump outward, or the smooth loss of the zone), the peak and the machine's
/// work, each to `rtol`; `samples` points of the path as `sample` events. Tangential stages are
/// refused at load time (engine/scene/dugdale_reader.cpp).
RunResult run_dugdale_program(const Scene& scene, double rtol, std::int64_t samples,
                              const ObserverList& observers);

}  // namespace mdrsim
