// A timed program on a relaxing bulk (material.relaxation): its normal fixed-grips stages run on
// the viscoelastic row, adhesive or not, reported as a program's RunResult
// (docs/viscoelastic.md).
#pragma once

#include "engine/events/observer.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Runs scene.program (timed; normal stages under any control without adhesion, under fixed grips
/// with it: the relaxation reader's scope) on scene.springs viscoelastic springs across the
/// largest contact radius the program reaches (an elastic program's frame: g(a_max) = the
/// deepest indentation under fixed grips, the relaxed contact where a force or machine end is
/// held). Each stage's held value moves linearly in time; a stage until separation ends where
/// the last spring in contact leaves, and without glue a fixed load lowered to or past zero
/// ends where the force reaches zero, the contact lost there. Under a machine spring its
/// F^2 / (2k) is part of each
/// stage's stored energy. With work_of_adhesion > 0 the row has an adhesive edge (let-go and
/// glue on the glassy modulus, engine/model/viscoelastic_edge). Emits spring_touched,
/// spring_lifted, spring_glued, spring_detached and jump at each change and stage_end, every
/// state with its time; each stage's work and energy carry dissipated_by_bulk, and with the
/// edge surface_change and jump_losses. Status as an elastic program's: without glue the
/// contact lost at zero force is `no-instability` with no critical point; a contact lost with
/// its glue is decided by the cascade that lost the glue (`instability` with `critical`);
/// `completed` where it stays; `step-limit` (no-end) where a stage until separation does not
/// withdraw, (max-events-per-spring) where a stage's changes do not settle. Emits every event
/// but `finished`.
RunResult run_viscoelastic_program(const Scene& scene, const ObserverList& observers);

}  // namespace mdrsim
