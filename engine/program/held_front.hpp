// The radius of a program's row at which spring N glues at the deepest state when a force
// (fixed load) or a machine spring (compliant) holds the normal axis there.
#pragma once

#include <cstdint>
#include <optional>

#include "controllers/controller.hpp"
#include "engine/base/material.hpp"
#include "engine/program/graded_springs.hpp"
#include "profiles/profile.hpp"

namespace mdrsim {

/// The deepest state of a program, reached on an advancing front under a normal constraint
/// that involves the force: the control a_u d + a_F F equals `held` there.
struct HeldDeepest {
  AffineConstraint constraint;
  double held;
  /// Whether the front glues (at the gap l(x) = Material::advancing_glue_gap(x)) or presses
  /// on touch (l = 0).
  bool glued_edge;
};

/// The radius a of a row of `springs` springs (spring i at i a / N) on which the row's own
/// control, N springs in contact and spring N just glued (d = g(a) - l(a), F = 2 E* dx (N d -
/// sum g_i)), and the control at which spring N + 1 would glue lie either side of `held`,
/// half-way: so the row reaches exactly N springs at its deepest (docs/programs.md,
/// "Discretization"). The continuum front `guess` [m] starts the search, which costs a few
/// sums over the row. nullopt where the control does not rise through `held` within a few
/// springs of the guess (the caller keeps the guess). On `graded` springs the row's images,
/// weights and gluing limit are theirs (F = sum w_i (d - g_k(x_i)), graded_springs.hpp).
std::optional<double> row_radius_reaching_held(
    const Profile& profile, const Material& material, const HeldDeepest& deepest,
    std::int64_t springs, double guess, const std::optional<GradedSprings>& graded = std::nullopt);

}  // namespace mdrsim
