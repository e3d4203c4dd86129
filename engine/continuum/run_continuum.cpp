// Status, states, stages, jumps and work of the shorthand from the continuum pull-off walk.
#include "engine/continuum/run_continuum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "controllers/builtin_controllers.hpp"
#include "engine/continuum/continuum_pull_off.hpp"
#include "engine/continuum/continuum_work.hpp"
#include "engine/result/lost_contact.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

/// How the indenter goes on once the contact is empty (docs/programs.md "A fixed load that
/// loses the contact"), as the row decides it (shorthand_path.hpp), g(0) for its first spring.
JumpEnd flight_after(const ContinuumBranch& branch, double normal_held, double g0) {
  return lost_contact_flight(branch.normal(), normal_held, branch.tangential(),
                             branch.tangential_held(), g0);
}

/// The empty contact the machine holds where the last spring left: at zero force the
/// indentation is the held value over a_u; under a fixed load (a_u = 0) where the last
/// equilibrium `last` left it, as the row reports it.
ContactSnapshot lost_snapshot(const ContinuumBranch& branch, double held, const BranchState& last) {
  ContactSnapshot s;
  s.normal_control = held;
  const double au = branch.normal().displacement_coefficient;
  s.indentation = au > 0.0 ? held / au : last.indentation;
  return s;
}

/// The followed branch at `samples` radii evenly from a_g down to where the path ends, as
/// `sample` events; radii that a jump passes over carry no equilibrium and are left out.
void emit_samples(const ContinuumBranch& branch, const ContinuumPullOff& p, std::int64_t samples,
                  const ObserverList& observers) {
  if (samples < 2 || p.segments.empty()) return;
  const double top = p.segments.front().first;
  const double bottom = p.segments.back().second;
  for (std::int64_t k = 0; k < samples; ++k) {
    const double a = k + 1 == samples ? bottom
                                      : top - (top - bottom) * static_cast<double>(k) /
                                                  static_cast<double>(samples - 1);
    for (const auto& [from, to] : p.segments) {
      if (a <= from && a >= to) {
        const BranchState s = a > branch.shear_off_radius() ? branch.at(a) : branch.state(a, 0.0);
        observers.emit({.kind = EventKind::sample, .state = s.snapshot()});
        break;
      }
    }
  }
}

}  // namespace

RunResult run_continuum(const Scene& scene, double rtol, std::int64_t samples,
                        const ObserverList& observers) {
  const AffineConstraint normal = scene.normal.controller->constraint();
  const AffineConstraint tangential = scene.tangential ? scene.tangential->controller->constraint()
                                                       : FixedGripsController().constraint();
  const double held = scene.tangential ? scene.tangential->held_value : 0.0;
  ContinuumBranch branch(*scene.profile, *scene.criterion, scene.material, normal, tangential, held,
                         scene.graded_image);
  const double ag = scene.glued_radius;
  const double preload_stretch = branch.image(ag) - scene.preload_depth;

  RunResult result;
  result.accuracy.route = Accuracy::Route::continuum;
  result.accuracy.outer_radius = ag;

  // Stage preload: pressed at fixed grips from touch, the work the energy stored.
  BranchState preload = branch.state(ag, preload_stretch);
  preload.tangential_displacement = 0.0;
  preload.tangential_force = 0.0;
  observers.emit({.kind = EventKind::preload_reached, .state = preload.snapshot()});
  ContinuumBranch pressed(*scene.profile, *scene.criterion, scene.material,
                          FixedGripsController().constraint(), tangential, 0.0, scene.graded_image);
  // The tangential load moves neither a nor d: both states store the same normal energy.
  const BranchState applied = branch.state(ag, preload_stretch);
  const Estimated glued_normal = glued_normal_energy(branch, applied);
  const Estimated preload_energy =
      stored_energy(pressed, pressed.state(ag, preload_stretch), glued_normal);
  double work_error = preload_energy.error;
  StageRecord preload_stage{"preload", preload.snapshot(), {}};
  preload_stage.work.normal = preload_energy.value;
  preload_stage.end.normal_control = preload.control;
  result.stages.push_back(preload_stage);

  // Stage tangential: u_x ramped on the glued contact, F_x = 2 G* a u_x.
  if (scene.tangential) {
    observers.emit({.kind = EventKind::tangential_applied, .state = applied.snapshot()});
  }
  StageRecord tangential_stage{"tangential", applied.snapshot(), {}};
  tangential_stage.work.tangential =
      0.5 * applied.tangential_force * applied.tangential_displacement;
  if (drives_through_spring(tangential)) {
    tangential_stage.work.tangential +=
        0.5 * applied.tangential_force * applied.tangential_force * tangential.force_coefficient;
  }
  result.stages.push_back(tangential_stage);

  const ContinuumPullOff p = continuum_pull_off(branch, ag);
  using End = ContinuumPullOff::End;
  if (p.end == End::shear_off_at_application) {
    result.status = RunStatus::shear_off;
    if (std::isfinite(p.tangential_strength)) result.tangential_strength = p.tangential_strength;
    result.stages.push_back({"pull-off", applied.snapshot(), {}});
    if (flight_after(branch, applied.control, scene.profile->mdr_image(0.0)) == JumpEnd::sliding)
      result.sliding = true;
  } else {
    // The pinned phase (the front stays at a_g until e reaches its let-go value), then each
    // stable stretch of the branch and the jumps between them.
    const StoredState pinned = stored_state(branch, branch.at(ag));
    AxisWork work = stretch_work(branch, {applied, stored_energy(branch, applied, glued_normal)},
                                 pinned, work_error);
    for (std::size_t k = 0; k < p.segments.size(); ++k) {
      const StoredState top = k == 0 ? pinned : stored_state(branch, p.partial_jumps[k - 1].to);
      const BranchState bottom = k < p.partial_jumps.size() ? p.partial_jumps[k].from : p.critical;
      work += stretch_work(branch, top, stored_state(branch, bottom), work_error);
      if (k < p.partial_jumps.size()) {
        const ContinuumJump& jump = p.partial_jumps[k];
        work += jump_work(branch, jump.from, jump.to);
        result.jumps.push_back({.stage = "pull-off",
                                .inward = false,
                                .critical = jump.from.snapshot(),
                                .after = jump.to.snapshot()});
      }
    }
    emit_samples(branch, p, samples, observers);
    const JumpEnd flight = flight_after(branch, p.critical.control, scene.profile->mdr_image(0.0));
    result.sliding = flight == JumpEnd::sliding;
    if (p.end == End::smooth_peel) {
      result.status = RunStatus::no_instability;
      result.stages.push_back(
          {"pull-off", lost_snapshot(branch, p.critical.control, p.critical), work});
    } else {
      result.status = p.end == End::shear_off ? RunStatus::shear_off : RunStatus::instability;
      result.critical = p.critical.snapshot();
      result.accuracy.critical_error_estimate =
          with_rounding(p.critical_error, branch.force_magnitude(p.critical));
      JumpRecord last{.stage = "pull-off",
                      .inward = false,
                      .critical = p.critical.snapshot(),
                      .end = flight,
                      .by_shear = p.end == End::shear_off};
      if (flight == JumpEnd::state)
        last.after = lost_snapshot(branch, p.critical.control, p.critical);
      result.jumps.push_back(last);
      result.stages.push_back({"pull-off",
                               flight == JumpEnd::state
                                   ? lost_snapshot(branch, p.critical.control, p.critical)
                                   : p.critical.snapshot(),
                               work});
      if (flight == JumpEnd::pressed) {
        result.warnings.push_back(fmt::format(
            "the glue let go with the indenter pressed in (held normal {}): the shorthand's "
            "pull-off stage ends where the glue let go",
            held_normal_text(branch.normal(), p.critical.control)));
      }
    }
    if (p.peak) {
      result.peak = p.peak->snapshot();
      // A peak at the critical point carries the fold's error too.
      const double search = p.peak->contact_radius == p.critical.contact_radius
                                ? std::max(p.peak_error, p.critical_error)
                                : p.peak_error;
      result.accuracy.peak_error_estimate = with_rounding(search, branch.force_magnitude(*p.peak));
    }
  }
  AxisWork total;
  AxisWork magnitude;  // of the stages' works, which the total rounds a few ulps of
  for (const StageRecord& stage : result.stages) {
    total += stage.work;
    magnitude += AxisWork{std::abs(stage.work.normal), std::abs(stage.work.tangential)};
  }
  result.work = total;
  result.accuracy.work_error_estimate = AxisWork{with_rounding(work_error, magnitude.normal),
                                                 with_rounding(work_error, magnitude.tangential)};
  result.accuracy.covers = {"critical.normal_force", "peak_adhesion.normal_force", "work"};
  result.counts.root_iterations = branch.iterations();

  // rtol on each reported force, relative to the preload's scale where a value is near 0.
  const double floor = 1e-300 + std::abs(preload.normal_force) * 1e-6;
  // The work relative to the path's scale, the preload's energy: a cycle's net work may
  // cancel to nothing (no adhesion) while its parts are of that size.
  bool met = meets_rtol(work_error, std::abs(total.normal) + std::abs(total.tangential), rtol,
                        preload_energy.value);
  if (result.critical) {
    met = met && meets_rtol(*result.accuracy.critical_error_estimate, p.critical.normal_force, rtol,
                            floor);
  }
  if (result.peak) {
    met =
        met && meets_rtol(*result.accuracy.peak_error_estimate, p.peak->normal_force, rtol, floor);
  }
  result.accuracy.rtol_met = met;
  if (!met) {
    result.warnings.push_back(fmt::format(
        "continuum: the root searches' error estimates exceed rtol = {:.3g} (the branch is not "
        "smooth enough at the critical point for its difference quotients)",
        rtol));
  }
  return result;
}

}  // namespace mdrsim
