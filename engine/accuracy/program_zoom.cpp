// The zoom of adaptive_resolution.cpp on a program's last stage: rows of 512 springs glued
// across the radius of spring n_c + max(4, n_c / 8), widened where a row's first let-go is its
// critical point, then doubled until the RowSequence estimate meets rtol.
#include "engine/accuracy/program_zoom.hpp"

#include <algorithm>

#include "engine/accuracy/row_refinement.hpp"
#include "engine/base/engine_logger.hpp"
#include "engine/program/stage_motion.hpp"
#include "engine/pull_off/pull_off.hpp"

namespace mdrsim {
namespace {

constexpr std::int64_t kZoomSprings = 512;

/// The springs in contact when the last stage's final run of single let-gos began: at the
/// stage's start, or after its last jump before the critical point's own.
std::int64_t stable_top(const RunResult& row, const LastStageStart& start, const Scene& scene) {
  std::int64_t top = start.springs;
  const std::string& name = scene.program->stages[start.stage].name;
  for (const JumpRecord& jump : row.jumps) {
    if (jump.stage != name || jump.end != JumpEnd::state) continue;
    if (row.critical && jump.critical.springs_in_contact == row.critical->springs_in_contact &&
        jump.critical.normal_force == row.critical->normal_force) {
      continue;
    }
    top = std::min(top, jump.after.springs_in_contact);
  }
  return top;
}

/// A zoomed row of `springs` across `radius`, and whether it kept the zoom's conditions.
struct ZoomRow {
  RunResult row;
  bool exact;
};

/// Whether the last stage only lowers the normal held value at a still tangential one: the
/// shorthand's pull-off, which the pull-off loop runs at a third of the program loop's cost
/// per let-go (docs/design.md "Why two loops").
bool peels_as_pull_off(const Scene& scene, const LastStageStart& start) {
  const Stage& stage = scene.program->stages[start.stage];
  return axis_motion(stage.normal, start.normal.held).rate < 0.0 &&
         axis_motion(stage.tangential, start.tangential.held).rate == 0.0;
}

/// A pull-off row's state as the program row would report it: the glued springs' offset s
/// added back to u_x (the row ran on the stretch u_x - s), and glued out to its edge.
void as_program_state(std::optional<ContactSnapshot>& state, double offset) {
  if (!state) return;
  state->tangential_displacement += offset;
  state->glued_radius = state->contact_radius;
}

/// The zoomed row on the pull-off loop: every spring glued at the offset s, so that the
/// stretch is u_x - s; the tangential constraint a_u u_x + a_F F_x = h holds the stretch
/// at h - a_u s.
RunResult pull_off_row(const Scene& scene, const LastStageStart& start, const ZeroScale& zero,
                       double radius, std::int64_t springs) {
  const MachineStart machine{
      .normal = start.normal.constraint,
      .normal_held = start.normal.held,
      .tangential = start.tangential.constraint,
      .tangential_held = start.tangential.held -
                         start.tangential.constraint.displacement_coefficient * start.offset};
  RunResult row = run_row(
      scene,
      {.springs = springs, .outer_radius = radius, .zoomed = true, .start = machine, .zero = zero},
      {});
  for (auto* state : {&row.critical, &row.refined_critical, &row.peak, &row.refined_peak}) {
    as_program_state(*state, start.offset);
  }
  return row;
}

ZoomRow zoomed_row(const Scene& scene, const LastStageStart& start, const ZeroScale& zero,
                   double radius, std::int64_t springs) {
  if (peels_as_pull_off(scene, start)) {
    return {pull_off_row(scene, start, zero, radius, springs), true};
  }
  ProgramRowSpec spec{
      .reference_radius = radius,
      .reference_springs = springs,
      .reference_image = program_image(scene, radius),
      .max_springs = springs + 64,
      .edge_forces = true,
      .refine = true,
      .zero = zero,
      .zoomed = ZoomedStart{start.stage, start.normal, start.tangential, start.offset}};
  LastStageStart seen;
  RunResult row = run_program_row(scene, spec, {}, nullptr, &seen);
  const bool exact = row.critical ? seen.zoomable_to(*row.critical) : seen.zoomable;
  return {std::move(row), exact};
}

/// The time of a state of the last stage, from the full row's state `reference` of that stage:
/// the zoomed rows run without the program's clock, which is affine in the stage parameter as
/// the held values are (docs/programs.md "Time").
double last_stage_time(const Scene& scene, const LastStageStart& start,
                       const ContactSnapshot& reference, const ContactSnapshot& s) {
  const Stage& stage = scene.program->stages[start.stage];
  const auto held = [](const MachineAxis& axis, double u, double f) {
    return axis.constraint.displacement_coefficient * u + axis.constraint.force_coefficient * f;
  };
  const double normal = axis_motion(stage.normal, start.normal.held).rate;
  const double tangential = axis_motion(stage.tangential, start.tangential.held).rate;
  const double per_parameter = seconds_per_parameter(stage, normal != 0.0 ? normal : tangential);
  if (per_parameter == 0.0) return reference.time;
  if (normal != 0.0) {
    return reference.time +
           per_parameter *
               (held(start.normal, s.indentation, s.normal_force) -
                held(start.normal, reference.indentation, reference.normal_force)) /
               normal;
  }
  if (tangential == 0.0) return reference.time;
  return reference.time +
         per_parameter *
             (held(start.tangential, s.tangential_displacement, s.tangential_force) -
              held(start.tangential, reference.tangential_displacement,
                   reference.tangential_force)) /
             tangential;
}

/// Whether the row's peak is its critical point, as the row located both: the zoom of one is
/// the zoom of the other.
bool peak_is_critical(const RunResult& row) {
  if (!row.peak || !row.critical || row.peak->springs_in_contact >= row.springs) return false;
  if (row.peak->springs_in_contact != row.critical->springs_in_contact ||
      row.peak->normal_force != row.critical->normal_force) {
    return false;
  }
  if (row.refined_peak.has_value() != row.refined_critical.has_value()) return false;
  return !row.refined_peak || row.refined_peak->normal_force == row.refined_critical->normal_force;
}

}  // namespace

/// The springs in contact at the row's state of `target`; 0 where it has none (or, for the
/// peak, where it sits at the row's outermost spring: the path goes on outside a zoomed row).
std::int64_t target_springs(const RunResult& row, Target target, bool zoomed) {
  if (target == Target::critical) return row.critical ? row.critical->springs_in_contact : 0;
  if (!row.peak || row.peak->springs_in_contact <= 1) return 0;
  if (zoomed && row.peak->springs_in_contact >= row.springs) return 0;
  return row.peak->springs_in_contact;
}

std::optional<ZoomedCritical> zoom_program_state(const Scene& scene, const RunResult& coarse,
                                                 const LastStageStart& start, double rtol,
                                                 Target target, const ZoomedCritical* critical) {
  if (!coarse.critical || !start.zoomable_to(*coarse.critical) ||
      scene.solver.method != SolverMethod::event) {
    return std::nullopt;
  }
  // The peak only where the last stage holds it: more tensile than anything before it.
  if (target == Target::peak && !(coarse.peak && coarse.peak->normal_force < start.peak_before)) {
    return std::nullopt;
  }
  if (coarse.status != RunStatus::instability && coarse.status != RunStatus::shear_off) {
    return std::nullopt;
  }
  ZoomedCritical out{};
  const ZeroScale zero = program_zero_scale(scene, coarse.accuracy.outer_radius,
                                            program_image(scene, coarse.accuracy.outer_radius));
  // One zoom from the full row (a second gains little on a program's folds, which sit at a
  // fair share of the largest radius).
  const std::int64_t k = target_springs(coarse, target, false);
  const std::int64_t top = stable_top(coarse, start, scene);
  if (k <= 0 || k > top) return std::nullopt;
  std::int64_t index = std::min(top, k + std::max<std::int64_t>(4, k / 8));
  if (3 * index > 2 * coarse.springs) return std::nullopt;  // gains less than 1.5x
  if (target == Target::peak && critical && critical->holds_peak && peak_is_critical(coarse)) {
    ZoomedCritical same = *critical;
    same.counts = {};
    return same;
  }
  std::optional<RunResult> first;
  double radius = 0.0;
  while (index < coarse.springs) {
    radius = coarse.accuracy.outer_radius * static_cast<double>(index) /
             static_cast<double>(coarse.springs);
    ZoomRow z = zoomed_row(scene, start, zero, radius, kZoomSprings);
    out.counts += z.row.counts;
    const std::int64_t found = target_springs(z.row, target, true);
    engine_logger().debug("program zoom: {} springs across {:.6g} m ({} -> {}): {} at spring {}",
                          kZoomSprings, radius, k, index, to_string(z.row.status), found);
    if (!z.exact || z.row.status != coarse.status) return std::nullopt;
    if (target == Target::critical && found <= 0) return std::nullopt;
    if (found > 0 && found < kZoomSprings) {
      first = std::move(z.row);
      break;
    }
    // Its first let-go is its critical point (glued inside the jump), or its peak is at its
    // outermost spring (the path's lies outside it).
    if (index == top) return std::nullopt;
    index = std::min(top, 2 * index);
  }
  if (!first) return std::nullopt;
  const RowOfSprings row = [&](std::int64_t springs) -> std::optional<RunResult> {
    ZoomRow z = zoomed_row(scene, start, zero, radius, springs);
    out.counts += z.row.counts;
    if (!z.exact || (target == Target::peak && target_springs(z.row, target, true) == 0)) {
      return std::nullopt;
    }
    return std::move(z.row);
  };
  RowRefinement refined = refine_rows(
      RowSequence(target, {std::move(*first)}).with_rough_radii(rough_radii(scene.material)), row,
      rtol, forced_route(scene.discretization), scene.discretization.max_row_springs,
      WhenRowsDisagree::give_up);
  if (refined.gave_up) return std::nullopt;
  out.met = refined.met;
  const RowSequence& seq = refined.sequence;
  const Accuracy::Route route = refined.route;
  const auto value = seq.value(route);
  const auto estimate = seq.estimate(route);
  if (!value || !estimate) return std::nullopt;
  out.value = *value;
  const ContactSnapshot& reference = target == Target::critical ? *coarse.critical : *coarse.peak;
  out.value.time = last_stage_time(scene, start, reference, out.value);
  out.estimate = *estimate;
  out.route = route;
  out.outer_radius = radius;
  out.holds_peak = target == Target::critical;
  for (const RunResult& row : seq.rows()) {
    out.rows.push_back(row.springs);
    out.holds_peak = out.holds_peak && peak_is_critical(row);
  }
  return out;
}

}  // namespace mdrsim
