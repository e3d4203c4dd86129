// Reads material.adhesive_stress or material.maugis_parameter (finite-range adhesion,
// docs/maugis.md) and refuses, one line each at its key, what the Dugdale law does not yet take.
#pragma once

#include <optional>

#include "engine/scene/route_plan.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// The two keys as given (at most one): sigma_0 [Pa] or lambda [1], each > 0 and finite.
struct FiniteRangeKeys {
  std::optional<double> adhesive_stress;
  std::optional<double> maugis_parameter;
  bool given() const { return adhesive_stress || maugis_parameter; }
};

/// Reads both keys of [material] `t`: both given, or a value not positive and finite, fails
/// at the key.
FiniteRangeKeys read_finite_range(TomlReader& t);

/// Puts sigma_0 into scene.material once the profile is read (lambda needs the tip's radius):
/// fails at the key where the work of adhesion is 0, varies with the radius or has an
/// approach value, or where maugis_parameter meets a profile other than parabolic or sphere.
void apply_finite_range(TomlReader& material, const FiniteRangeKeys& keys, Scene& scene);

/// The scene's other tables against a finite-range adhesion (SPEC "Finite-range adhesion",
/// "Scope"): a loading program (rebinding = false named at its key), a tangential load,
/// [detachment], [friction] and a spring-row method (solver.method at `route_keys.method_at`)
/// are refused. A no-op without adhesive_stress.
void refuse_outside_dugdale_scope(const TomlReader& root, const TomlReader& loading,
                                  const RouteKeys& route_keys, const Scene& scene);

}  // namespace mdrsim
