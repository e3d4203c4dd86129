// The pull-off loop: tracks equilibria and cascades, so that the row's end is told by physics.
#include "engine/pull_off/pull_off.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>

#include "controllers/builtin_controllers.hpp"
#include "engine/base/engine_logger.hpp"
#include "engine/events/cascade_buffer.hpp"
#include "engine/events/progress_log.hpp"
#include "engine/model/boundary_let_go.hpp"
#include "engine/model/fold_refinement.hpp"
#include "engine/pull_off/event_method.hpp"
#include "engine/pull_off/shorthand_path.hpp"
#include "engine/pull_off/stepping_method.hpp"
#include "engine/pull_off/tangential_strength.hpp"
#include "engine/result/loss_status.hpp"
#include "engine/result/lost_contact.hpp"
#include "engine/result/status_margin.hpp"

namespace mdrsim {
namespace {

/// The default stepping increment: 1e-3 of the control's scale, the larger of its value at
/// the preload and where the first spring lets go; both are 0 for one unstretched spring
/// under fixed load, where the glued contact's own scale (E* a_g^2 or a_g) stands in.
double default_step(const Contact& contact, const DetachmentCriterion& criterion) {
  double scale = std::abs(contact.normal_control());
  const BoundaryLetGo first = locate_boundary_let_go(contact, criterion);
  if (first.let_go.kind == LetGo::Kind::at_elongation) {
    scale = std::max(scale, std::abs(first.normal_control));
  }
  if (!(scale > 0.0)) {
    const double a = contact.foundation().glued_radius();
    scale = std::abs(contact.normal_control_at(a)) + contact.material().effective_modulus * a * a;
  }
  return 1e-3 * scale;
}

std::unique_ptr<PullOffMethod> make_method(const SolverOptions& solver, const Contact& contact,
                                           const DetachmentCriterion& criterion) {
  if (solver.method == SolverMethod::event) return std::make_unique<EventMethod>();
  const double step = solver.step ? *solver.step : default_step(contact, criterion);
  return std::make_unique<SteppingMethod>(step, solver.max_halvings);
}

/// The equilibria of the path as they come, O(1) memory: the last three of the unbroken run
/// of single let-gos, and the most tensile one with its neighbours. A state is copied once, into
/// a ring of three; the peak is copied out only when the path has passed it (while the force
/// still falls every equilibrium is the peak, and a copy each would stall the loop).
class EquilibriumTrack {
 public:
  explicit EquilibriumTrack(const Contact& contact) : contact_(&contact) {}

  /// A new equilibrium; `after_jump` when more than one spring left since the previous one.
  void add(const Contact::State& state, bool after_jump) {
    if (after_jump || count_ == 0) {
      run_length_ = 0;
      run_top_ = state.springs_in_contact;
    }
    head_ = head_ == 2 ? 0 : head_ + 1;
    ring_[head_] = state;
    ++run_length_;
    ++count_;
    const double force = contact_->normal_force_of(state);
    last_force_ = force;
    if (count_ == 1 || force < peak_force_) {
      peak_force_ = force;
      peak_has_outer_ = run_length_ >= 2;
      peak_is_last_ = true;
    } else if (peak_is_last_) {
      // The first equilibrium past the peak: the peak and its outer neighbour are still in
      // the ring, and this one is its inner neighbour unless a jump came between.
      peak_ = recent(1);
      peak_outer_.reset();
      if (peak_has_outer_) peak_outer_ = recent(2);
      peak_inner_.reset();
      if (!after_jump) peak_inner_ = state;
      peak_is_last_ = false;
    }
  }

  bool empty() const { return count_ == 0; }
  std::int64_t size() const { return count_; }  ///< equilibria so far
  const Contact::State& last() const { return recent(0); }
  /// The k-th equilibrium before the last in the unbroken run (k = 1, 2), if there is one.
  std::optional<Contact::State> before_last(int k) const {
    if (run_length_ <= k) return std::nullopt;
    return recent(k);
  }
  std::int64_t run_top() const { return run_top_; }
  double last_force() const { return last_force_; }  ///< [N]
  const Contact::State& peak() const { return peak_is_last_ ? recent(0) : peak_; }
  std::optional<Contact::State> peak_outer() const {
    if (!peak_is_last_) return peak_outer_;
    if (!peak_has_outer_) return std::nullopt;
    return recent(1);
  }
  std::optional<Contact::State> peak_inner() const {
    return peak_is_last_ ? std::nullopt : peak_inner_;
  }

 private:
  /// The k-th equilibrium before the last (k = 0: the last), k < 3.
  const Contact::State& recent(int k) const { return ring_[(head_ + 3 - k) % 3]; }

  const Contact* contact_;
  std::array<Contact::State, 3> ring_{};
  int head_ = 0;  ///< the ring's slot of the last equilibrium
  int run_length_ = 0;
  std::int64_t count_ = 0;
  std::int64_t run_top_ = 0;
  double peak_force_ = 0.0;
  double last_force_ = 0.0;
  bool peak_is_last_ = false;    ///< the peak is the last equilibrium, not yet copied out
  bool peak_has_outer_ = false;  ///< the peak came in an unbroken run after another one
  Contact::State peak_{};
  std::optional<Contact::State> peak_outer_;
  std::optional<Contact::State> peak_inner_;
};

/// How the last cascade began: the spring let go at the critical point and the first one
/// due after it.
struct CascadeStart {
  std::int64_t size = 0;  ///< springs detached since the last equilibrium
  bool by_shear = false;  ///< the first spring due after it was broken at zero stretch
  bool flat = true;       ///< every spring due after it was due only to rounding (AdvanceOutcome)
};

void fill_critical(RunResult& result, const Contact& contact, const DetachmentCriterion& criterion,
                   const EquilibriumTrack& track) {
  const Contact::State& critical = track.last();
  result.critical = contact.snapshot_of(critical);
  result.stable_run_top = track.run_top();
  if (const auto outer = track.before_last(1)) {
    if (result.status == RunStatus::instability) {
      result.refined_critical = refine_fold(contact, criterion, *outer, critical);
      result.fold_above_shear_off =
          fold_above_shear_off(contact, criterion, std::nullopt, *outer, critical);
    } else if (const auto outer2 = track.before_last(2)) {
      result.refined_critical = refine_shear_off(contact, criterion, *outer2, *outer, critical);
      result.fold_above_shear_off =
          fold_above_shear_off(contact, criterion, outer2, *outer, critical);
    }
  }
  result.peak = contact.snapshot_of(track.peak());
  if (track.peak().springs_in_contact == critical.springs_in_contact) {
    // The most tensile equilibrium is the critical one: the force still falls at the end.
    if (result.refined_critical) result.refined_peak = *result.refined_critical;
  } else if (track.peak_outer() && track.peak_inner()) {
    result.refined_peak =
        refine_peak(contact, *track.peak_outer(), track.peak(), *track.peak_inner());
  }
}

}  // namespace

ZeroScale shorthand_zero_scale(const Scene& scene) {
  if (scene.graded_image) {
    // The graded springs' stiffness at the glued radius, C_k a_g^k / 2, stands for E*.
    const double a = scene.glued_radius;
    const double modulus = 0.5 * scene.material.grading.punch_constant *
                           std::pow(a, scene.graded_image->grading_exponent());
    return zero_scale(modulus, a, scene.graded_image->image(a),
                      scene.material.largest_work_of_adhesion(), scene.preload_force);
  }
  return zero_scale(scene.material.effective_modulus, scene.glued_radius,
                    scene.profile->mdr_image(scene.glued_radius),
                    scene.material.largest_work_of_adhesion(), scene.preload_force);
}

RunResult run_pull_off(const Scene& scene, const ObserverList& observers) {
  return run_pull_off(scene, scene.springs, observers);
}

RunResult run_pull_off(const Scene& scene, std::int64_t springs, const ObserverList& observers) {
  const auto started = std::chrono::steady_clock::now();
  RunResult result =
      run_row(scene, {.springs = springs, .outer_radius = scene.glued_radius, .record_path = true},
              observers);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  emit_closing_events(result, observers);
  return result;
}

void emit_closing_events(const RunResult& result, const ObserverList& observers) {
  if (result.critical) {
    observers.emit({.kind = EventKind::instability,
                    .state = *result.critical,
                    .status = result.status,
                    .stage = result.critical_stage});
  }
  // Without a critical point the run ends where its last stage ended (a limit, the end of a
  // program), not at the undeformed start.
  if (result.critical || result.stages.empty()) {
    observers.emit({.kind = EventKind::finished,
                    .state = result.critical.value_or(ContactSnapshot{}),
                    .status = result.status,
                    .stage = result.critical_stage});
  } else {
    observers.emit({.kind = EventKind::finished,
                    .state = result.stages.back().end,
                    .status = result.status,
                    .stage = result.stages.back().name});
  }
}

RunResult run_row(const Scene& scene, const RowSpec& row, const ObserverList& observers) {
  const SpringFoundation foundation =
      scene.graded_image
          ? SpringFoundation(*scene.profile, row.outer_radius, row.springs, *scene.graded_image,
                             scene.material.grading.punch_constant)
          : SpringFoundation(*scene.profile, row.outer_radius, row.springs);
  const AffineConstraint normal_constraint =
      row.start ? row.start->normal : scene.normal.controller->constraint();
  const AffineConstraint tangential_constraint = row.start ? row.start->tangential
                                                 : scene.tangential
                                                     ? scene.tangential->controller->constraint()
                                                     : FixedGripsController().constraint();
  Contact contact(foundation, scene.material, normal_constraint, tangential_constraint);

  contact.set_normal_control(row.start ? row.start->normal_held
                                       : contact.normal_control_at(scene.preload_depth));
  // A zoomed row starts past the preload: only a row across the glued radius runs the path.
  std::optional<ShorthandPath> path;
  if (!row.zoomed && row.record_path) {
    path.emplace(normal_constraint, tangential_constraint);
    path->preload(contact);
  }
  if (!row.zoomed) {
    observers.emit({.kind = EventKind::preload_reached, .state = contact.snapshot()});
  }
  if (row.start) {
    contact.set_tangential_held(row.start->tangential_held);
  } else if (scene.tangential) {
    contact.set_tangential_held(scene.tangential->held_value);
    if (!row.zoomed) {
      observers.emit({.kind = EventKind::tangential_applied, .state = contact.snapshot()});
    }
  }
  if (path) {
    const bool spring = drives_through_spring(tangential_constraint);
    path->tangential(contact,
                     spring ? std::optional<double>(1.0 / tangential_constraint.force_coefficient)
                            : std::nullopt);
  }
  const Contact::State applied = contact.save();

  const std::unique_ptr<PullOffMethod> method =
      make_method(scene.solver, contact, *scene.criterion);
  RunResult result;
  result.springs = row.springs;
  result.accuracy.rows = {row.springs};
  result.accuracy.outer_radius = row.outer_radius;
  EquilibriumTrack track(contact);
  CascadeStart cascade;
  ProgressLog progress;
  // An advance's rows wait until it ends in an equilibrium: under a fixed load the last one
  // may end in a flight, which is not reported (docs/programs.md "A fixed load that loses the
  // contact").
  CascadeBuffer buffer(observers);
  ObserverList buffered;
  buffered.add(buffer);
  // Any control: a glue sheared off under compression ends pressed in under fixed grips too.
  const bool may_fly = !observers.empty();
  const ObserverList& pull_off_observers = may_fly ? buffered : observers;
  while (contact.springs_in_contact() > 0) {
    if (result.counts.steps >= scene.solver.max_steps) {
      stop_at_limit(result, StopReason::max_steps);
      break;
    }
    if (result.counts.events >= scene.solver.max_events) {
      stop_at_limit(result, StopReason::max_events);
      break;
    }
    const std::size_t before_advance = buffer.held();
    const AdvanceOutcome out =
        method->advance(contact, *scene.criterion, pull_off_observers, result.counts);
    // An advance that starts at an equilibrium closes what came before it.
    if (may_fly && out.equilibrium_before) buffer.flush(before_advance);
    if (progress.due()) {
      engine_logger().info("pull-off running: {} of {} springs attached, {} steps, {} halvings",
                           contact.springs_in_contact(), row.springs, result.counts.steps,
                           result.counts.halvings);
    }
    if (out.detached == 0) continue;
    // Broken by the tangential load as it was applied: the state before is no equilibrium.
    const bool broken_at_start = track.empty() && cascade.size == 0 && out.first_by_shear;
    if (path) path->advanced(contact, out, out.equilibrium_before && !broken_at_start);
    if (out.equilibrium_before && !broken_at_start) {
      track.add(*out.equilibrium_before, cascade.size > 1);
      cascade = {.size = out.detached,
                 .by_shear = out.detached > 1 && out.second_by_shear,
                 .flat = out.detached == 1 || out.flat};
    } else {
      if (cascade.size == 1) cascade.by_shear = out.first_by_shear;
      cascade.size += out.detached;
      cascade.flat = cascade.flat && out.flat;
    }
  }
  const JumpEnd flight = shorthand_flight(contact.save(), normal_constraint, tangential_constraint,
                                          foundation.image(1));
  if (flight == JumpEnd::state) {
    buffer.flush();
  } else {
    buffer.discard_flight(scene.solver.method == SolverMethod::event);
  }
  result.sliding = flight == JumpEnd::sliding;
  if (flight == JumpEnd::pressed && path) {
    result.warnings.push_back(fmt::format(
        "the glue let go with the indenter pressed in (held normal {}): the springs pressed "
        "back carry a load, which the shorthand does not follow; its pull-off stage ends where "
        "the glue let go, and the same path written as a program follows it on",
        held_normal_text(normal_constraint, contact.save().normal_control)));
  }
  if (path) path->finish(contact, result.stages, result.jumps, result.work);
  if (result.work &&
      !(std::isfinite(result.work->normal) && std::isfinite(result.work->tangential))) {
    // Extreme scenes (dgamma near the largest double) can take the path's work, a product of
    // force and displacement, beyond a double even where both are finite.
    result.stages.clear();
    result.jumps.clear();
    result.work.reset();
    result.warnings.emplace_back(
        "the work of the path left the range of a double (the scene's values are too extreme "
        "together): no stages, jumps or work are reported");
  }
  if (result.stop_reason == StopReason::max_steps) {
    result.warnings.push_back(fmt::format(
        "the stepping method reached solver.max_steps = {} before the contact was lost: there is "
        "no critical point",
        scene.solver.max_steps));
    return result;
  }
  if (result.stop_reason == StopReason::max_events) {
    result.warnings.push_back(fmt::format(
        "the row reached solver.max_events = {} before the contact was lost: there is no "
        "critical point",
        scene.solver.max_events));
    return result;
  }
  if (track.empty()) {
    // Not one equilibrium: the tangential load broke the glue as it was applied.
    result.status = RunStatus::shear_off;
    Contact at_application = contact;
    at_application.restore(applied);
    result.tangential_strength = tangential_strength(at_application, *scene.criterion);
    return result;
  }
  // The status from the cascade that lost the contact (loss_status.hpp). A single let-go's
  // cascade.by_shear is false: the first spring let go at an equilibrium, stretched. A flat
  // cascade is a tie on a falling branch only where the branch fell before it: at a glued
  // row's first let-go the control never fell, and a branch flat from the glued radius on
  // (a flat punch under a constant let-go stretch) is the continuum route's fold there.
  const bool fell = row.zoomed || track.size() > 1;
  const LossCascade loss{
      .changes = cascade.size,
      .springs_before = track.last().springs_in_contact,
      .force_before = track.last_force(),
      .force_scale = (row.zero ? *row.zero : shorthand_zero_scale(scene)).contact_force,
      .first_by_shear = cascade.by_shear,
      .second_by_shear = cascade.by_shear,
      .flat = cascade.flat && fell};
  result.status = loss_status(loss);
  const bool smooth = result.status == RunStatus::no_instability;
  fill_critical(result, contact, *scene.criterion, track);
  if (smooth) {
    result.critical.reset();
    result.refined_critical.reset();  // Richardson and rtol must not find one either
    result.fold_above_shear_off.reset();
    // A smooth peel ends at F -> 0: a "peak" at the last spring is only that spring's own
    // tension, which vanishes as the row is refined.
    if (result.peak && result.peak->springs_in_contact == 1) {
      result.peak.reset();
      result.refined_peak.reset();
    }
  }
  return result;
}

}  // namespace mdrsim
