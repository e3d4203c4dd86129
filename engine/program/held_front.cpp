// The row's own control when spring N glues and when spring N + 1 would: compensated sums of
// g over the row, a bracket grown from the guess in steps of the spacing, TOMS 748 inside it.
#include "engine/program/held_front.hpp"

#include <cmath>

#include "engine/base/bracketed_root.hpp"
#include "engine/model/compensated_sum.hpp"
#include "engine/model/gluing_depth.hpp"

namespace mdrsim {

namespace {

/// The row's control at its deepest state as row_radius_reaching_held has it, on graded springs:
/// half-way between spring N's gluing and spring N + 1's, minus held.
double graded_held_excess(const GradedSprings& graded, const HeldDeepest& deepest,
                          std::int64_t springs, double a) {
  const double n = static_cast<double>(springs);
  const double dx = a / n;
  CompensatedSum images;  // sum w_i g_k(x_i)
  for (std::int64_t i = 1; i <= springs; ++i) {
    const double x = i == springs ? a : dx * static_cast<double>(i);
    images.add(graded.weight(i, x) * graded.image->image(x));
  }
  const auto depth = [&](double x) {
    return graded.image->image(x) - (deepest.glued_edge ? graded.front_limit(x) : 0.0);
  };
  const double stiffness = graded.stiffness_to(a);
  const AffineConstraint& c = deepest.constraint;
  const auto control = [&](double d) {
    return c.displacement_coefficient * d + c.force_coefficient * (stiffness * d - images.value());
  };
  return 0.5 * (control(depth(a)) + control(depth(a + dx))) - deepest.held;
}

}  // namespace

std::optional<double> row_radius_reaching_held(const Profile& profile, const Material& material,
                                               const HeldDeepest& deepest, std::int64_t springs,
                                               double guess,
                                               const std::optional<GradedSprings>& graded) {
  if (springs < 2 || !(guess > 0.0) || !std::isfinite(guess)) return std::nullopt;
  const double n = static_cast<double>(springs);
  const double e_star = material.effective_modulus;
  const AffineConstraint& c = deepest.constraint;
  // Half-way between the control at spring N's gluing and at spring N + 1's, minus held.
  const auto excess = [&](double a) {
    if (graded) return graded_held_excess(*graded, deepest, springs, a);
    const double dx = a / n;
    CompensatedSum images;
    for (std::int64_t i = 1; i < springs; ++i) {
      images.add(profile.mdr_image(dx * static_cast<double>(i)));
    }
    images.add(profile.mdr_image(a));
    const double sum = images.value();
    const double d_n = gluing_depth(profile, material, deepest.glued_edge, a);
    double d_next = d_n;
    const double x_next = a + dx;
    if (x_next <= profile.outer_radius()) {
      d_next = gluing_depth(profile, material, deepest.glued_edge, x_next);
    } else {
      // Beyond the profile's end (a sphere's radius): the step before it, continued.
      d_next = 2.0 * d_n - gluing_depth(profile, material, deepest.glued_edge, a - dx);
    }
    const auto control = [&](double d) {
      return c.displacement_coefficient * d +
             c.force_coefficient * 2.0 * e_star * dx * (n * d - sum);
    };
    return 0.5 * (control(d_n) + control(d_next)) - deepest.held;
  };
  const double spacing = guess / n;
  const double at_guess = excess(guess);
  if (!std::isfinite(at_guess)) return std::nullopt;
  if (at_guess == 0.0) return guess;
  // The control rises with the front on the stable branch a held force reaches: step away
  // from the guess against the sign until it changes.
  const double direction = at_guess > 0.0 ? -1.0 : 1.0;
  double near = guess;
  for (double step = spacing; step <= 64.0 * spacing; step *= 2.0) {
    const double far = guess + direction * step;
    if (!(far > 0.0) || far > profile.outer_radius()) return std::nullopt;
    const double at_far = excess(far);
    if (!std::isfinite(at_far)) return std::nullopt;
    if ((at_far > 0.0) != (at_guess > 0.0)) {
      const double lo = direction > 0.0 ? near : far;
      const double hi = direction > 0.0 ? far : near;
      // 40 bits: the root to 1e-12 of a, far below a spacing on any row the engine builds.
      const RootBracket b = bracket_root(excess, lo, hi, 40);
      return 0.5 * (b.lo + b.hi);
    }
    near = far;
  }
  return std::nullopt;
}

}  // namespace mdrsim
