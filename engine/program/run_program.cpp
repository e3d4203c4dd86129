// The row of a program: N springs across the largest contact radius a_max it reaches. A pilot
// row of 256 springs finds where the contact is largest; a_max is then the continuum front at
// that depth, so that a program pressing to a depth d gets the row of the shorthand's preload.
#include "engine/program/run_program.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "engine/base/bracketed_root.hpp"
#include "engine/base/hess_scale.hpp"
#include "engine/model/criterion_contract.hpp"
#include "engine/model/gluing_depth.hpp"
#include "engine/model/jkr_scales.hpp"
#include "engine/program/graded_springs.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/program_runner.hpp"
#include "engine/program/stage_motion.hpp"
#include "engine/scene/unresolved_shape.hpp"

namespace mdrsim {
namespace {

constexpr std::int64_t kPilotSprings = 256;

/// The advancing front's gap limit at x [m] (gluing_depth.hpp), Hess's rule with dgamma_a on
/// the graded springs where the half-space is graded (graded_springs.hpp).
double front_limit(const Scene& scene, bool glued_edge, double x) {
  if (const auto graded = GradedSprings::of(scene.graded_image, scene.material)) {
    return glued_edge ? graded->front_limit(x) : 0.0;
  }
  return advancing_limit(scene.material, glued_edge, x);
}

/// The depth [m] at which the front takes a free spring at x [m]: g - l (gluing_depth.hpp).
double front_depth(const Scene& scene, bool glued_edge, double x) {
  if (!scene.graded_image) return gluing_depth(*scene.profile, scene.material, glued_edge, x);
  return scene.graded_image->image(x) - front_limit(scene, glued_edge, x);
}

/// The non-adhesive contact radius [m] at depth d [m].
double radius_at_depth(const Scene& scene, double d) {
  if (scene.graded_image) return scene.graded_image->radius_at_depth(d);
  return scene.profile->contact_radius_at_depth(d);
}
/// A pilot row ends at this many times its springs: a guess that far off is rescaled.
constexpr std::int64_t kPilotReach = 64;

/// A first guess of the largest contact radius [m]: the non-adhesive radius at the deepest
/// depth or largest force the program names where the held value's unit is known statically.
double guess_radius(const Scene& scene) {
  const Profile& profile = *scene.profile;
  const double e_star = scene.material.effective_modulus;
  double radius = 0.0;
  double held = 0.0;  // the normal held value, while its unit is known
  bool known = true;
  // A program starts under fixed grips (docs: loading programs); the held value keeps its
  // meaning while the controller holds the same quantity, and the machine end of a spring is
  // no depth.
  bool holds_force = false;
  bool through_spring = false;
  for (const Stage& stage : scene.program->stages) {
    if (!stage.normal) continue;
    const StageAxis& axis = *stage.normal;
    const bool now_force = axis.controller->holds_force();
    const bool now_spring = axis.controller->drives_through_spring();
    if (now_force != holds_force || now_spring != through_spring || now_spring) known = false;
    holds_force = now_force;
    through_spring = now_spring;
    if (axis.motion == StageAxis::Motion::to) known = true;
    held = held_after(axis, held, stage.until_separation);
    if (!known || !(held > 0.0)) continue;
    try {
      double a = 0.0;
      if (scene.graded_image) {
        a = holds_force
                ? scene.graded_image->radius_at_force(held, scene.material.grading.punch_constant)
                : scene.graded_image->radius_at_depth(held);
      } else {
        a = holds_force ? contact_radius_at_force(profile, held, e_star)
                        : profile.contact_radius_at_depth(held);
      }
      if (std::isfinite(a)) radius = std::max(radius, a);
    } catch (const std::exception&) {
      // Out of the profile's reach: the pilot finds out.
    }
  }
  if (const auto fixed = profile.fixed_contact_radius()) return *fixed;
  if (radius > 0.0) return radius;
  if (const auto tip = profile.jkr_scale_radius()) {
    if (const auto jkr = JkrScales::of(*tip, e_star, scene.material.work_of_adhesion)) {
      return jkr->radius;
    }
  }
  return std::isfinite(profile.outer_radius()) ? 0.5 * profile.outer_radius() : 1e-3;
}

/// The continuum front at depth d [m]: the x where gluing_depth(x) = d for a glued edge,
/// g(x) = d for a pressed one, between the pilot's springs m and m + 1.
double front_radius(const Scene& scene, const LargestContact& largest, double spacing) {
  const Profile& profile = *scene.profile;
  if (const auto fixed = profile.fixed_contact_radius()) return *fixed;
  if (!largest.glued_edge || scene.material.glues_on_touch()) {
    return radius_at_depth(scene, largest.indentation);
  }
  const auto excess = [&](double x) { return front_depth(scene, true, x) - largest.indentation; };
  const double lo = spacing * static_cast<double>(largest.springs);
  double hi = lo + spacing;
  if (!(excess(lo) <= 0.0) || !(excess(hi) > 0.0) || !std::isfinite(excess(hi))) return lo;
  return bracketed_root(excess, lo, hi);
}

/// The frame of a front at radius a_max reached at depth d: g there, or the front value it
/// equals up to rounding, taken down by ulps until the row's own test at d (glue: g_N - d <=
/// limit, as ChangeLocator::due() has it; touch: g_N - d <= 0) holds, so that spring N is
/// reached at the deepest point (docs).
ProgramRowFrame frame_at(const Scene& scene, double a_max, double indentation, bool glued_edge) {
  const double g = program_image(scene, a_max);
  const double limit = front_limit(scene, glued_edge, a_max);
  double front = indentation + limit;
  if (!(std::abs(g - front) <= 1e-12 * std::max(std::abs(g), std::abs(front)))) {
    return {a_max, g};
  }
  // Just inside the gluing limit: a reversible front (dgamma_a = dgamma) lets spring N go
  // again where its gap reaches the same limit, and a tie at the stage's end (the criterion's
  // rounding against the limit's) must not undo it. 1e-12 of the limit moves g_N no more than
  // the rounding accepted above.
  if (glued_edge) front = indentation + limit * (1.0 - 1e-12);
  for (int i = 0; i < 64 && front - indentation > limit; ++i) {
    front = std::nextafter(front, -INFINITY);
  }
  return {a_max, front};
}

/// Samples between the touch and a root of the gluing depth that first_crossing checks.
constexpr int kCrossingSamples = 1024;

/// The first radius in (0, root] where `excess` (the gluing depth less the deepest depth,
/// negative at the centre) turns positive. Where dgamma or the profile varies with the radius
/// the gluing depth may cross d_max more than once, and a root found anywhere in the bracket
/// may be a later crossing: the approach's front stops at the first (it glues spring by spring
/// from the centre), so a row framed at a later one never reaches spring N and its front sits
/// at a different fraction of a spacing in every row (the work of the pinned turn then jumps
/// by a sawtooth that Richardson cannot remove). Samples at kCrossingSamples points of
/// [0, root]; a crossing narrower than their spacing stays unseen. For an approach work of
/// adhesion that varies with the radius (the profile's ripples are the row's to resolve).
template <class Excess>
double first_crossing(const Excess& excess, double root) {
  double lo = 0.0;
  for (int i = 1; i < kCrossingSamples; ++i) {
    const double x = root * static_cast<double>(i) / kCrossingSamples;
    if (excess(x) > 0.0) return bracketed_root(excess, lo, x);
    lo = x;
  }
  return root;
}

/// Where every normal stage holds the depth (fixed grips), the deepest depth d_max is known
/// before the run, and the front there is advancing (a depth never reached before): a_max is
/// its continuum radius, with no pilot. Nothing where a stage holds a force or pushes on
/// without end, or the front is not bracketed.
std::optional<ProgramRowFrame> frame_without_pilot(const Scene& scene) {
  double held = 0.0;
  double deepest = 0.0;
  for (const Stage& stage : scene.program->stages) {
    if (!stage.normal) continue;
    const StageAxis& axis = *stage.normal;
    if (!axis.controller->is_fixed_grips()) return std::nullopt;
    // Pushing on until separation has no deepest point.
    if (axis.motion == StageAxis::Motion::by && stage.until_separation && axis.value > 0.0) {
      return std::nullopt;
    }
    held = held_after(axis, held, stage.until_separation);
    deepest = std::max(deepest, held);
  }
  const Profile& profile = *scene.profile;
  if (!(deepest > 0.0) || profile.fixed_contact_radius()) return std::nullopt;
  // The front glues at the advancing limit (or presses on touch), as ProgramRow's front does.
  const bool glued_edge = scene.material.adhesive();
  const auto excess = [&](double x) { return front_depth(scene, glued_edge, x) - deepest; };
  double hi = 0.0;
  try {
    hi = radius_at_depth(scene, deepest);
  } catch (const std::exception&) {
    return std::nullopt;
  }
  for (int i = 0;
       i < 64 && std::isfinite(hi) && hi <= profile.outer_radius() && !(excess(hi) > 0.0); ++i) {
    hi *= 2.0;
  }
  if (!std::isfinite(hi) || hi > profile.outer_radius() || !(excess(hi) > 0.0)) {
    return std::nullopt;
  }
  // Only an approach work of adhesion that varies with the radius is looked through: on a
  // wavy profile the row's own spacing decides which ripples its front sees.
  const double root = bracketed_root(excess, 0.0, hi);
  const double a_max =
      scene.material.approach_work_of_adhesion_by_radius ? first_crossing(excess, root) : root;
  if (!(a_max > 0.0)) return std::nullopt;
  return frame_at(scene, a_max, deepest, glued_edge && !scene.material.glues_on_touch());
}

/// The continuum front [m] at which the control a_u d + a_F F reaches the held value, with
/// d = g(a) - l(a) and F = E* (2 int_0^a (g(a) - g) dx - 2 a l(a)) on the advancing branch,
/// bracketed within a few of the pilot's spacings of its front; nullopt where it is not.
std::optional<double> continuum_front_reaching_held(const Scene& scene, const HeldDeepest& held,
                                                    double pilot_front, double pilot_spacing) {
  const Profile& profile = *scene.profile;
  const double e_star = scene.material.effective_modulus;
  const auto excess = [&](double a) {
    // The gluing depth g - l (gluing_depth()), on the limit l that the force needs too.
    const double limit = front_limit(scene, held.glued_edge, a);
    if (const auto& graded = scene.graded_image) {
      // F = C_k (nf_k(a) - a^(1+k) l(a)) on the graded springs.
      const double ck = scene.material.grading.punch_constant;
      const double d = graded->image(a) - limit;
      const double force = ck * (graded->nonadhesive_force_per_constant(a) -
                                 std::pow(a, 1.0 + graded->grading_exponent()) * limit);
      return held.constraint.displacement_coefficient * d +
             held.constraint.force_coefficient * force - held.held;
    }
    const double d = profile.mdr_image(a) - limit;
    const double force = e_star * (profile.nonadhesive_force_per_modulus(a) - 2.0 * a * limit);
    return held.constraint.displacement_coefficient * d +
           held.constraint.force_coefficient * force - held.held;
  };
  const double lo = std::max(0.5 * pilot_front, pilot_front - 4.0 * pilot_spacing);
  const double hi = std::min(profile.outer_radius(), pilot_front + 4.0 * pilot_spacing);
  const double at_lo = excess(lo);
  const double at_hi = excess(hi);
  if (!(lo > 0.0) || !std::isfinite(at_lo) || !std::isfinite(at_hi) || !(at_lo < 0.0) ||
      !(at_hi > 0.0)) {
    return std::nullopt;
  }
  return bracketed_root(excess, lo, hi);
}

}  // namespace

namespace {

/// The frame's radius and image: without a pilot where the deepest depth is known, else from one.
ProgramRowFrame located_frame(const Scene& scene) {
  if (const auto frame = frame_without_pilot(scene)) return *frame;
  double radius = guess_radius(scene);
  double pilot_radius = radius;  // the radius of the pilot that found `largest`
  LargestContact largest;
  for (int attempt = 0; attempt < 6; ++attempt) {
    largest = {};
    pilot_radius = radius;
    const ProgramRowSpec pilot{.reference_radius = radius,
                               .reference_springs = kPilotSprings,
                               .reference_image = program_image(scene, radius),
                               .max_springs = kPilotSprings * kPilotReach};
    const RunResult r = run_program_row(scene, pilot, {}, &largest);
    const bool outgrew =
        r.status == RunStatus::step_limit && largest.most_springs >= pilot.max_springs;
    if (outgrew) {
      radius *= static_cast<double>(kPilotReach);
      continue;
    }
    if (largest.most_springs == 0 || largest.most_springs >= kPilotSprings / 4) break;
    radius *= static_cast<double>(largest.most_springs) / static_cast<double>(kPilotSprings);
  }
  if (largest.springs == 0) return {radius, program_image(scene, radius)};
  const double a_max = front_radius(scene, largest, pilot_radius / kPilotSprings);
  ProgramRowFrame frame = frame_at(scene, a_max, largest.indentation, largest.glued_edge);
  if (!is_fixed_grips(largest.normal_constraint) && !scene.profile->fixed_contact_radius()) {
    const HeldDeepest held{largest.normal_constraint, largest.normal_held, largest.glued_edge};
    if (const auto a =
            continuum_front_reaching_held(scene, held, a_max, pilot_radius / kPilotSprings)) {
      frame = {*a, program_image(scene, *a)};
      frame.held = held;
    }
  }
  return frame;
}

}  // namespace

double program_image(const Scene& scene, double x) {
  return scene.graded_image ? scene.graded_image->image(x) : scene.profile->mdr_image(x);
}

ZeroScale program_zero_scale(const Scene& scene, double radius, double image) {
  double held_force = 0.0;
  for (const Stage& stage : scene.program->stages) {
    if (stage.normal && stage.normal->controller->holds_force() &&
        stage.normal->motion == StageAxis::Motion::to) {
      held_force = std::max(held_force, std::abs(held_after(*stage.normal, 0.0, false)));
    }
  }
  // The graded springs' stiffness at the radius, C_k a^k / 2, stands for E* (as the
  // shorthand's graded row has it).
  const double modulus = scene.graded_image
                             ? 0.5 * scene.material.grading.punch_constant *
                                   std::pow(radius, scene.graded_image->grading_exponent())
                             : scene.material.effective_modulus;
  return zero_scale(modulus, radius, image, scene.material.largest_work_of_adhesion(), held_force);
}

ProgramRowFrame program_row_frame(const Scene& scene) {
  ProgramRowFrame frame = located_frame(scene);
  refuse_unresolved_shape(scene, frame.radius, "largest contact");
  // Once per run, at the radii it reaches: what the program's let-gos rely on.
  check_criterion_contract(*scene.criterion, scene.criterion_name, scene.material, frame.radius);
  frame.zero = program_zero_scale(scene, frame.radius, frame.image);
  return frame;
}

ProgramRowSpec program_row(const Scene& scene, const ProgramRowFrame& frame, std::int64_t springs) {
  double radius = frame.radius;
  double image = frame.image;
  if (frame.held) {
    if (const auto a = row_radius_reaching_held(
            *scene.profile, scene.material, *frame.held, springs, frame.radius,
            GradedSprings::of(scene.graded_image, scene.material))) {
      radius = *a;
      image = program_image(scene, radius);
    }
  }
  return {.reference_radius = radius,
          .reference_springs = springs,
          .reference_image = image,
          .max_springs = 2 * springs + 64,
          .zero = frame.zero};
}

RunResult run_program(const Scene& scene, const ObserverList& observers) {
  return run_program_row(scene, program_row(scene, program_row_frame(scene), scene.springs),
                         observers);
}

}  // namespace mdrsim
