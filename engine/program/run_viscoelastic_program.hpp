// A timed program on a relaxing bulk (material.relaxation): its normal fixed-grips stages run on
// the viscoelastic row, reported as a program's RunResult (docs/viscoelastic.md).
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs scene.program (timed; normal stages under any control, no adhesion: the relaxation
/// reader's scope) on scene.springs viscoelastic springs across the largest contact radius the
/// program reaches (an elastic program's frame: g(a_max) = the deepest indentation under fixed
/// grips, the relaxed contact where a force or machine end is held). Each stage's held value
/// moves linearly in time; a stage until separation ends where the last pressed spring lets go.
/// Under a machine spring its F^2 / (2k) is part of each stage's stored energy. Emits
/// spring_touched and spring_lifted at each spring's event and stage_end, every state with its
/// time; each stage's work and energy carry dissipated_by_bulk, machine_work = stored_change +
/// dissipated_by_bulk. Status as an elastic program's without glue: the contact lost at zero
/// force is `no-instability` with no critical point, `completed` where it stays, `step-limit`
/// (no-end) where a stage until separation does not withdraw. Emits every event but `finished`.
RunResult run_viscoelastic_program(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
