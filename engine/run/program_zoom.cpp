// The zoom of adaptive_resolution.cpp on a program's last stage: rows of 512 springs glued
// across the radius of spring n_c + max(4, n_c / 8), widened where a row's first let-go is its
// critical point, then doubled until the RowSequence estimate meets rtol.
#include "engine/run/program_zoom.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

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

ZoomRow zoomed_row(const Scene& scene, const LastStageStart& start, const ZeroScale& zero,
                   double radius, std::int64_t springs) {
  ProgramRowSpec spec{
      .reference_radius = radius,
      .reference_springs = springs,
      .reference_image = scene.profile->mdr_image(radius),
      .max_springs = springs + 64,
      .edge_forces = true,
      .refine = true,
      .zero = zero,
      .zoomed = ZoomedStart{start.stage, start.normal, start.tangential, start.offset}};
  LastStageStart seen;
  RunResult row = run_program_row(scene, spec, {}, nullptr, &seen);
  return {std::move(row), seen.zoomable};
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
                                                 Target target) {
  if (!start.zoomable || !coarse.critical || scene.solver.method != SolverMethod::event) {
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
                                            scene.profile->mdr_image(coarse.accuracy.outer_radius));
  // One zoom from the full row (a second gains little on a program's folds, which sit at a
  // fair share of the largest radius).
  const std::int64_t k = target_springs(coarse, target, false);
  const std::int64_t top = stable_top(coarse, start, scene);
  if (k <= 0 || k > top) return std::nullopt;
  std::int64_t index = std::min(top, k + std::max<std::int64_t>(4, k / 8));
  if (3 * index > 2 * coarse.springs) return std::nullopt;  // gains less than 1.5x
  std::optional<RunResult> first;
  double radius = 0.0;
  while (index < coarse.springs) {
    radius = coarse.accuracy.outer_radius * static_cast<double>(index) /
             static_cast<double>(coarse.springs);
    ZoomRow z = zoomed_row(scene, start, zero, radius, kZoomSprings);
    out.counts += z.row.counts;
    const std::int64_t found = target_springs(z.row, target, true);
    spdlog::debug("program zoom: {} springs across {:.6g} m ({} -> {}): {} at spring {}",
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
  RowSequence seq(target, {std::move(*first)});
  Accuracy::Route route = Accuracy::Route::richardson;
  for (;;) {
    if (!seq.usable()) return std::nullopt;
    // Four rows before anything is accepted, as on the shorthand (adaptive_resolution.cpp).
    if (seq.rows().size() >= 4) {
      route = scene.discretization.extrapolation == DiscretizationOptions::Extrapolation::none
                  ? Accuracy::Route::row
              : scene.discretization.richardson() ? Accuracy::Route::richardson
                                                  : cheaper_route(seq, rtol);
      if (meets(seq, route, rtol)) {
        out.met = true;
        break;
      }
    }
    if (seq.next_springs() > scene.discretization.max_row_springs) break;
    ZoomRow z = zoomed_row(scene, start, zero, radius, seq.next_springs());
    out.counts += z.row.counts;
    if (!z.exact || (target == Target::peak && target_springs(z.row, target, true) == 0)) {
      return std::nullopt;
    }
    seq.add(std::move(z.row));
  }
  const auto value = seq.value(route);
  const auto estimate = seq.estimate(route);
  if (!value || !estimate) return std::nullopt;
  out.value = *value;
  out.estimate = *estimate;
  out.route = route;
  out.outer_radius = radius;
  for (const RunResult& row : seq.rows()) out.rows.push_back(row.springs);
  return out;
}

}  // namespace mdrsim
