// Reads material.grading (a modulus that grows with depth, docs/graded.md) and refuses, one
// line each at its key, what the graded half-space does not yet take.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <optional>

#include "engine/base/material.hpp"
#include "engine/scene/route_plan.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// material.grading = { exponent = k, depth = z0 } of [material] `t`: 0 <= k < 1, z0 > 0, no
/// other key; C_k from E0 [Pa] and nu. None where the key is absent.
std::optional<Grading> read_grading(TomlReader& t, double youngs_modulus, double poisson_ratio);

/// Fails at material.grading where it meets effective_modulus (C_k needs nu itself).
void refuse_grading_without_poisson_ratio(TomlReader& t);

/// The graded image of the scene's profile once it is read (k > 0), from the profile's keys in
/// the resolved scene; fails at material.grading for a profile it has no closed form for.
void apply_grading(TomlReader& material, const nlohmann::json& resolved, Scene& scene);

/// The scene's other tables against a graded half-space with k > 0 (SPEC "Graded media",
/// "Scope", and what the graded branch and rows carry so far): a tangential load or stage,
/// [friction], [detachment], adhesive_stress or maugis_parameter, and a work of adhesion that
/// varies with the radius are refused. A no-op at k = 0.
void refuse_outside_grading_scope(const TomlReader& root, const TomlReader& loading,
                                  const TomlReader& material, const Scene& scene);

/// A graded scene runs on the continuum route unless solver.method = "event" or "stepping" is
/// named, which takes the graded spring row (the shorthand's or a program's): the scene and its
/// resolved form name the route, and the resolved form leaves out [detachment].
void use_graded_route(nlohmann::json& resolved, const RouteKeys& route_keys, Scene& scene);

}  // namespace mdrsim
