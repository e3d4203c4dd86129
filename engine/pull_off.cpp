// The pull-off loop: tracks cascades so that the last equilibrium before the jump is the result.
#include "engine/pull_off.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "controllers/builtin_controllers.hpp"
#include "engine/boundary_let_go.hpp"
#include "engine/fold_refinement.hpp"
#include "engine/methods/event_method.hpp"
#include "engine/methods/stepping_method.hpp"

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

/// Logs progress every few seconds on long runs; cheap to call each iteration.
class ProgressLog {
 public:
  explicit ProgressLog(std::int64_t springs) : springs_(springs) {}
  void tick(const Contact& contact, const RunCounts& counts) {
    if ((++calls_ & 0xFFFF) != 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::seconds(2)) return;
    last_ = now;
    spdlog::info("pull-off running: {} of {} springs attached, {} steps, {} halvings",
                 contact.springs_in_contact(), springs_, counts.steps, counts.halvings);
  }

 private:
  std::int64_t springs_;
  std::uint64_t calls_ = 0;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

RunResult run_pull_off(const Scene& scene, const ObserverList& observers) {
  return run_pull_off(scene, scene.springs, observers);
}

RunResult run_pull_off(const Scene& scene, std::int64_t springs, const ObserverList& observers) {
  const auto started = std::chrono::steady_clock::now();
  const SpringFoundation foundation(*scene.profile, scene.glued_radius, springs);
  const AffineConstraint tangential_constraint = scene.tangential
                                                     ? scene.tangential->controller->constraint()
                                                     : FixedGripsController().constraint();
  Contact contact(foundation, scene.material, scene.normal.controller->constraint(),
                  tangential_constraint);

  contact.set_normal_control(contact.normal_control_at(scene.preload_depth));
  observers.emit({.kind = EventKind::preload_reached, .state = contact.snapshot()});
  if (scene.tangential) {
    contact.set_tangential_held(scene.tangential->held_value);
    observers.emit({.kind = EventKind::tangential_applied, .state = contact.snapshot()});
  }

  const std::unique_ptr<PullOffMethod> method =
      make_method(scene.solver, contact, *scene.criterion);
  RunResult result;
  result.springs = springs;
  result.resolutions = {springs};
  Contact::State critical = contact.save();
  std::optional<Contact::State> before_critical;  // the equilibrium before, for the fold
  std::int64_t cascade_size = 0;                  // springs detached since the last equilibrium
  bool cascade_by_shear = false;
  double cascade_stretch = 0.0;
  ProgressLog progress(springs);
  while (contact.springs_in_contact() > 0) {
    if (result.counts.steps >= scene.solver.max_steps) {
      result.status = RunStatus::step_limit;
      break;
    }
    const AdvanceOutcome out = method->advance(contact, *scene.criterion, observers, result.counts);
    progress.tick(contact, result.counts);
    if (out.detached == 0) continue;
    if (out.equilibrium_before || cascade_size == 0) {
      if (out.equilibrium_before) {
        before_critical = critical;
        critical = *out.equilibrium_before;
      }
      cascade_size = 0;
      cascade_by_shear = out.first_by_shear;
      cascade_stretch = out.first_stretch;
    }
    cascade_size += out.detached;
  }
  if (contact.springs_in_contact() == 0) {
    // A last spring that leaves unstretched carries no force: the contact ends smoothly.
    const bool smooth =
        cascade_size == 1 && !cascade_by_shear && cascade_stretch <= 1e-9 * foundation.spacing();
    result.status = cascade_by_shear ? RunStatus::shear_off
                    : smooth         ? RunStatus::no_instability
                                     : RunStatus::instability;
  } else {
    critical = contact.save();
  }
  result.critical = contact.snapshot_of(critical);
  if (result.status == RunStatus::instability && scene.solver.method == SolverMethod::event &&
      before_critical) {
    if (const auto fold = refine_fold(contact, *scene.criterion, *before_critical, critical)) {
      result.fold = fold->state;
      result.fold_force_step = fold->normal_force_step;
    }
  }
  if (result.status == RunStatus::instability || result.status == RunStatus::shear_off) {
    observers.emit(
        {.kind = EventKind::instability, .state = result.critical, .status = result.status});
  }
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  observers.emit({.kind = EventKind::finished, .state = result.critical, .status = result.status});
  return result;
}

}  // namespace mdrsim
