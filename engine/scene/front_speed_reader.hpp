// Reads detachment.front_speed_law (the rate law of the receding edge) and refuses, one line
// each at its key, what the rate law does not take yet (docs/rate_law.md).
#pragma once

#include <optional>
#include <string>

#include "engine/model/front_speed_law.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// detachment.front_speed_law = { speed = v*, exponent = n } of [detachment] `t`: v* > 0 [m/s],
/// n in (0, 1], no other key; a timed program is needed (every stage with duration or speed).
/// None where the key is absent; `at` gets the key's "file:line:col: key: " for the scope's
/// refusals.
std::optional<FrontSpeedLaw> read_front_speed_law(TomlReader& t, const Scene& scene,
                                                  std::string& at);

/// The built scene against the rate law's scope, failing at `at`: the continuum route, or the
/// event method's rows with an elastic bulk (a press after a possible let-go with rebinding);
/// normal fixed-grips stages only, a constant positive work of adhesion, and not yet with
/// finite-range adhesion, grading or [friction]. A no-op without the law.
void refuse_outside_front_speed_scope(const Scene& scene, const std::string& at);

}  // namespace mdrsim
