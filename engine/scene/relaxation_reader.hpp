// Reads material.relaxation (the Prony terms of a viscoelastic bulk, docs/viscoelastic.md) and
// refuses, one line each at its key, what the viscoelastic springs do not take.
#pragma once

#include <optional>
#include <vector>

#include "engine/base/material.hpp"
#include "engine/scene/route_plan.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// material.relaxation = [ { modulus = E_i, time = tau_i }, ... ] of [material] `t`: each
/// E_i > 0 [Pa] and tau_i > 0 [s], no other key, at most 64 terms. `plane_strain` turns E_i into
/// E_i* (1 / (1 - nu^2) with youngs_modulus and poisson_ratio, 1 with effective_modulus, whose
/// terms are effective moduli already). None where the key is absent. Fails at adhesive_stress,
/// maugis_parameter or grading where the table also holds one of them.
std::optional<std::vector<PronyTerm>> read_relaxation(TomlReader& t, double plane_strain);

/// The scene's other keys against a relaxing bulk (SPEC "Time and viscoelastic media", "Scope",
/// and what the program row carries so far): the shorthand, a program without a clock,
/// a tangential stage, a fixed-load stage until separation or lowered to or below
/// zero force, adhesion with other than fixed-grips normal stages (one line of its own) and a
/// method other than event are refused, before the routes those keys choose. A no-op without
/// the key.
void refuse_outside_relaxation_scope(const TomlReader& loading, const TomlReader& material,
                                     const RouteKeys& route_keys, const Scene& scene);

/// [friction] `friction` against a relaxing bulk: glued = "coulomb" (and so shear_strength)
/// and a law other than one coefficient are refused at their key (pressed springs stick and
/// slide at mu f_z, glued ones hold any stretch). A no-op without relaxation or friction.
void refuse_friction_with_relaxation(const TomlReader& friction, const Scene& scene);

}  // namespace mdrsim
