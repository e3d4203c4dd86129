// The Dugdale row's result in a run's terms: the path's states as snapshots, the preload and
// pull-off stages with their work, the jump and the let-go events.
#include "engine/pull_off/dugdale_row_run.hpp"

#include <fmt/format.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include <cmath>
#include <numbers>

#include "controllers/builtin_controllers.hpp"
#include "engine/model/dugdale_material.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/pull_off/dugdale_row.hpp"
#include "engine/result/lost_contact.hpp"

namespace mdrsim {
namespace {

ContactSnapshot snapshot_of(const DugdaleRowState& s, const AffineConstraint& normal) {
  ContactSnapshot c;
  c.indentation = s.indentation;
  c.normal_force = s.normal_force;
  c.contact_radius = s.contact_radius;
  c.cohesive_radius = s.cohesive_radius;
  c.springs_in_contact = s.springs_in_contact;
  c.normal_control =
      normal.displacement_coefficient * s.indentation + normal.force_coefficient * s.normal_force;
  return c;
}

/// E* dx sum (d_p - g_i)^2 over the springs inside a_g, the cell across a_g by its part inside
/// (its value at a_g): a right-point sum of (d_p - g)^2 over (0, a_g], whose error is smooth
/// in dx to first order, E* dx ((d_p - g(a_g))^2 - (d_p - g(0))^2) / 2.
double pressing_energy(const Profile& profile, double modulus, double spacing, double glued_radius,
                       double preload_depth) {
  double sum = 0.0;
  std::int64_t i = 1;
  for (; static_cast<double>(i) * spacing <= glued_radius; ++i) {
    const double u = preload_depth - profile.mdr_image(static_cast<double>(i) * spacing);
    sum += u * u;
  }
  const double inside = glued_radius - static_cast<double>(i - 1) * spacing;
  const double u = preload_depth - profile.mdr_image(glued_radius);
  return modulus * (spacing * sum + inside * u * u);
}

/// int F dd along the no-contact branch from c0 down to c [J], F = -pi sigma_0 c^2 and
/// d(c) = f(c) - 4 sigma_0 c/(pi E*) - h0: by parts, [F d] + 2 pi sigma_0 int c d(c) dc, free
/// of f'.
double no_contact_work(const Profile& profile, const DugdaleLaw& law, double c0, double c) {
  const auto depth = [&](double r) { return dugdale_free_state(profile, law, r).indentation; };
  const auto force = [&](double r) { return -std::numbers::pi * law.adhesive_stress * r * r; };
  const double integral = boost::math::quadrature::gauss_kronrod<double, 61>::integrate(
      [&](double r) { return r * depth(r); }, c0, c, 8, 1e-14);
  return force(c) * depth(c) - force(c0) * depth(c0) +
         2.0 * std::numbers::pi * law.adhesive_stress * integral;
}

/// The empty contact the machine holds after the jump (as the continuum route reports it).
ContactSnapshot after_jump(const AffineConstraint& normal, double held,
                           const ContactSnapshot& last) {
  ContactSnapshot s;
  s.normal_control = held;
  const double au = normal.displacement_coefficient;
  s.indentation = au > 0.0 ? held / au : last.indentation;
  return s;
}

}  // namespace

RunResult run_dugdale_row_scene(const Scene& scene, std::int64_t springs, double preload_radius,
                                const ObserverList& observers) {
  const Profile& profile = *scene.profile;
  const AffineConstraint normal = scene.normal.controller->constraint();
  const DugdaleLaw law = dugdale_law(scene.material);
  // The path is kept only for the trajectory: the row sums the work as it goes.
  const bool trajectory = observers.wants(EventKind::spring_detached);
  const DugdaleRowResult row = run_dugdale_row(profile, law,
                                               {.springs = springs,
                                                .glued_radius = preload_radius,
                                                .normal = normal,
                                                .record_path = trajectory,
                                                .max_events = scene.solver.max_events});

  RunResult result;
  result.springs = springs;
  result.accuracy.route = Accuracy::Route::row;
  result.accuracy.rows = {springs};
  result.accuracy.outer_radius = preload_radius;
  result.counts.events = row.counts.events;
  result.counts.root_iterations = row.counts.opening_evaluations;

  const ContactSnapshot preload = snapshot_of(row.first, normal);
  observers.emit({.kind = EventKind::preload_reached, .state = preload});
  if (trajectory) {
    for (const DugdaleRowState& s : row.path) {
      if (s.springs_in_contact == 0) break;
      observers.emit({.kind = EventKind::spring_detached,
                      .state = snapshot_of(s, normal),
                      .spring = s.springs_in_contact});
    }
  }

  const double spacing = preload_radius / static_cast<double>(springs);
  StageRecord preload_stage{"preload", preload, {}};
  preload_stage.work.normal = pressing_energy(profile, law.effective_modulus, spacing,
                                              scene.glued_radius, scene.preload_depth);
  preload_stage.refined_end = preload;
  result.stages.push_back(preload_stage);
  result.stages.push_back({"tangential", preload, {}, {}, preload});

  const ContactSnapshot end = snapshot_of(row.critical, normal);
  // The row's trapezoids up to the critical point or the no-contact branch's start; that
  // branch's part in closed form in c.
  double work = row.work;
  if (row.no_contact_start > 0.0) {
    const double start_force = dugdale_free_state(profile, law, row.no_contact_start).normal_force;
    work += no_contact_work(profile, law, row.no_contact_start, end.cohesive_radius);
    if (drives_through_spring(normal)) {
      // The machine's end moves by d + F/k: its spring's energy change on top of int F dd.
      work += 0.5 * normal.force_coefficient *
              (end.normal_force * end.normal_force - start_force * start_force);
    }
  }

  StageRecord pull_off{"pull-off", end, {}};
  pull_off.work.normal = work;
  pull_off.refined_end = end;
  if (row.event_limit) {
    // As the JKR row: no critical point, the path up to the last let-go.
    stop_at_limit(result, StopReason::max_events);
    result.warnings.push_back(fmt::format(
        "the row reached solver.max_events = {} before the contact was lost: there is no "
        "critical point",
        scene.solver.max_events));
  } else if (row.instability) {
    result.status = RunStatus::instability;
    result.critical = end;
    result.refined_critical = end;
    const JumpEnd flight =
        lost_contact_flight(normal, end.normal_control, FixedGripsController().constraint(), 0.0,
                            profile.mdr_image(0.0));
    JumpRecord jump{.stage = "pull-off", .inward = false, .critical = end, .end = flight};
    jump.refined_critical = end;
    if (flight == JumpEnd::state) {
      jump.after = after_jump(normal, end.normal_control, end);
      pull_off.end = jump.after;
    }
    result.jumps.push_back(jump);
  } else {
    result.status = RunStatus::no_instability;
  }
  result.stages.push_back(pull_off);
  result.peak = snapshot_of(row.peak, normal);
  result.refined_peak = result.peak;
  AxisWork total;
  for (const StageRecord& stage : result.stages) total += stage.work;
  result.work = total;
  return result;
}

}  // namespace mdrsim
