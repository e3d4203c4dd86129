// Status, states, stages, jump and work of the shorthand on the Dugdale path.
#include "engine/continuum/run_dugdale_continuum.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "controllers/builtin_controllers.hpp"
#include "engine/continuum/continuum_branch.hpp"
#include "engine/continuum/continuum_work.hpp"
#include "engine/continuum/dugdale_path.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/result/lost_contact.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

/// The empty contact the machine holds after the jump: at the held value over a_u, or under a
/// fixed load where the critical state left it (as the JKR route reports it).
ContactSnapshot after_jump(const AffineConstraint& normal, double held, const DugdaleState& last) {
  ContactSnapshot s;
  s.normal_control = held;
  const double au = normal.displacement_coefficient;
  s.indentation = au > 0.0 ? held / au : last.indentation;
  return s;
}

/// |F| plus its two terms' magnitudes, E* nf(a) and the zone's pull [N]: what F's rounding is a
/// few ulps of.
double force_terms(const Profile& profile, const DugdaleLaw& law, const DugdaleState& s) {
  const double pressed =
      std::abs(law.effective_modulus * profile.nonadhesive_force_per_modulus(s.contact_radius));
  return std::abs(s.normal_force) + pressed + std::abs(s.normal_force - pressed);
}

}  // namespace

RunResult run_dugdale_continuum(const Scene& scene, double rtol, std::int64_t samples,
                                const ObserverList& observers) {
  const AffineConstraint normal = scene.normal.controller->constraint();
  const DugdaleLaw law = dugdale_law(scene.material);
  const DugdalePath path(*scene.profile, law, scene.glued_radius, scene.preload_depth);

  RunResult result;
  result.accuracy.route = Accuracy::Route::continuum;
  result.accuracy.outer_radius = scene.glued_radius;

  // Stage preload: pressed at fixed grips from touch to the preload depth (the contact a_g);
  // the zone then pulls the contact out to a_p at that depth, where the grips do no work. Its
  // work is the energy the springs store, as on the JKR route.
  const DugdaleState preload = path.at(0.0);
  const ContactSnapshot preload_snapshot = dugdale_snapshot(preload, normal);
  observers.emit({.kind = EventKind::preload_reached, .state = preload_snapshot});
  const FixedGripsController grips;
  ContinuumBranch pressed(*scene.profile, *scene.criterion, scene.material, grips.constraint(),
                          grips.constraint(), 0.0);
  const Estimated preload_energy = stored_energy(
      pressed, pressed.state(scene.glued_radius,
                             scene.profile->mdr_image(scene.glued_radius) - scene.preload_depth));
  double work_error = preload_energy.error;
  StageRecord preload_stage{"preload", preload_snapshot, {}};
  preload_stage.work.normal = preload_energy.value;
  result.stages.push_back(preload_stage);
  // No tangential stage is applied; the record keeps the shorthand's three stages.
  result.stages.push_back({"tangential", preload_snapshot, {}});

  const std::optional<DugdaleFold> fold = first_fold(path, normal);
  const double s_end = fold ? fold->s : DugdalePath::kEnd;
  const DugdaleState end = fold ? fold->state : path.at(s_end);
  double work = path_work(path, 0.0, s_end, work_error);
  if (drives_through_spring(normal)) {
    // The machine's end moves by d + F/k: its spring's energy change on top of int F dd.
    work += 0.5 * normal.force_coefficient *
            (end.normal_force * end.normal_force - preload.normal_force * preload.normal_force);
  }

  if (samples >= 2) {
    // The curve solved as a walk (each state from the last ones), then emitted.
    std::vector<double> places(static_cast<std::size_t>(samples));
    for (std::int64_t k = 0; k < samples; ++k) {
      places[static_cast<std::size_t>(k)] =
          s_end * static_cast<double>(k) / static_cast<double>(samples - 1);
    }
    for (const DugdaleState& state : path.states(places)) {
      observers.emit({.kind = EventKind::sample, .state = dugdale_snapshot(state, normal)});
    }
  }

  const ContactSnapshot end_snapshot = dugdale_snapshot(end, normal);
  const double held = end_snapshot.normal_control;
  StageRecord pull_off{"pull-off", end_snapshot, {}};
  pull_off.work.normal = work;
  if (fold) {
    result.status = RunStatus::instability;
    result.critical = end_snapshot;
    result.accuracy.critical_error_estimate =
        with_rounding(fold->force_error, force_terms(*scene.profile, law, fold->state));
    const JumpEnd flight = lost_contact_flight(normal, held, FixedGripsController().constraint(),
                                               0.0, scene.profile->mdr_image(0.0));
    JumpRecord jump{.stage = "pull-off", .inward = false, .critical = end_snapshot, .end = flight};
    if (flight == JumpEnd::state) jump.after = after_jump(normal, held, end);
    result.jumps.push_back(jump);
    if (flight == JumpEnd::state) pull_off.end = after_jump(normal, held, end);
  } else {
    // The zone shrinks to nothing without a jump: the contact is lost smoothly.
    result.status = RunStatus::no_instability;
  }
  result.stages.push_back(pull_off);

  DugdaleFold peak = most_tensile(path, s_end);
  // A peak no more tensile than the fold, within both errors, is the fold (fixed load).
  if (fold &&
      peak.state.normal_force >= fold->state.normal_force - peak.force_error - fold->force_error) {
    peak = *fold;
  }
  result.peak = dugdale_snapshot(peak.state, normal);
  result.accuracy.peak_error_estimate =
      with_rounding(peak.force_error, force_terms(*scene.profile, law, peak.state));

  AxisWork total;
  double magnitude = 0.0;
  for (const StageRecord& stage : result.stages) {
    total += stage.work;
    magnitude += std::abs(stage.work.normal);
  }
  result.work = total;
  result.accuracy.work_error_estimate = AxisWork{with_rounding(work_error, magnitude), 0.0};
  result.accuracy.covers = {"critical.normal_force", "peak_adhesion.normal_force", "work"};

  const double floor = 1e-300 + std::abs(preload.normal_force) * 1e-6;
  bool met = meets_rtol(work_error, std::abs(total.normal), rtol, preload_energy.value);
  if (result.critical) {
    met = met && meets_rtol(*result.accuracy.critical_error_estimate, result.critical->normal_force,
                            rtol, floor);
  }
  met = met &&
        meets_rtol(*result.accuracy.peak_error_estimate, result.peak->normal_force, rtol, floor);
  result.accuracy.rtol_met = met;
  if (!met) {
    result.warnings.push_back(fmt::format(
        "continuum: the Dugdale path's error estimates exceed rtol = {:.3g} (critical {:.3g} N, "
        "peak {:.3g} N, work {:.3g} J)",
        rtol, result.accuracy.critical_error_estimate.value_or(0.0),
        *result.accuracy.peak_error_estimate, work_error));
  }
  return result;
}

}  // namespace mdrsim
