// The three ways to run a scene (one row, Richardson, rtol) and the warnings they share.
#include "engine/run/run_scene.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "engine/accuracy/adaptive_resolution.hpp"
#include "engine/accuracy/dugdale_rows.hpp"
#include "engine/accuracy/program_resolution.hpp"
#include "engine/accuracy/rate_law_rows.hpp"
#include "engine/accuracy/resolution_warning.hpp"
#include "engine/accuracy/row_refinement.hpp"
#include "engine/accuracy/row_sequence.hpp"
#include "engine/accuracy/shorthand_accuracy.hpp"
#include "engine/accuracy/viscoelastic_rows.hpp"
#include "engine/base/engine_logger.hpp"
#include "engine/base/zero_scale.hpp"
#include "engine/continuum/dugdale_program.hpp"
#include "engine/continuum/run_continuum.hpp"
#include "engine/continuum/run_continuum_program.hpp"
#include "engine/continuum/run_dugdale_continuum.hpp"
#include "engine/events/cascade_buffer.hpp"
#include "engine/model/criterion_contract.hpp"
#include "engine/program/rate_law_row.hpp"
#include "engine/program/run_program.hpp"
#include "engine/program/run_viscoelastic_program.hpp"
#include "engine/pull_off/pull_off.hpp"
#include "engine/result/status_margin.hpp"
#include "engine/run/disk_states.hpp"
#include "engine/run/shorthand_as_program.hpp"
#include "engine/scene/scene_error.hpp"

namespace mdrsim {
namespace {

/// Rows of N/2, N and 2N springs across the glued radius; the finest row's events. The
/// critical point and the peak combined by RowSequence, the path as a program's.
RunResult run_richardson(const Scene& scene, const ObserverList& observers) {
  const std::int64_t n = scene.springs;
  RowSequence seq(Target::critical);
  RunCounts counts;
  for (const std::int64_t springs : {n / 2, n}) {
    seq.add(run_row(
        scene, {.springs = springs, .outer_radius = scene.glued_radius, .record_path = true}, {}));
    counts += seq.last().counts;
  }
  seq.add(run_row(scene,
                  {.springs = 2 * n, .outer_radius = scene.glued_radius, .record_path = true},
                  observers));
  counts += seq.last().counts;

  RunResult result = seq.last();
  result.counts = counts;
  result.accuracy.route = Accuracy::Route::richardson;
  result.accuracy.rows = {n / 2, n, 2 * n};
  if (const auto value = seq.value(Accuracy::Route::richardson)) {
    result.critical = value;
    result.accuracy.critical_error_estimate = seq.estimate(Accuracy::Route::richardson);
  } else if (result.critical) {
    result.warnings.push_back(fmt::format(
        "richardson: the rows of {}, {} and {} springs end differently ({}, {}, {}); the finest "
        "row is reported as it is",
        n / 2, n, 2 * n, to_string(seq.rows()[0].status), to_string(seq.rows()[1].status),
        to_string(seq.rows()[2].status)));
  }
  const RowSequence peaks(Target::peak, seq.rows());
  if (const auto value = peaks.value(Accuracy::Route::richardson)) {
    result.peak = value;
    result.accuracy.peak_error_estimate = peaks.estimate(Accuracy::Route::richardson);
  }
  combine_shorthand_path(scene, seq.rows(), result);
  return result;
}

/// A row whose branch folds close above a_s (status_margin.hpp) says it cannot tell.
std::string cannot_tell_status(const RunResult& result) {
  return fmt::format(
      "the branch folds {:.3g} spacings above the radius where the glue shears off "
      "unstretched ({} springs): the row cannot tell instability from shear-off; "
      "discretization.rtol resolves it",
      result.fold_above_shear_off.value_or(0.0), result.springs);
}

void warn_resolution(const Scene& scene, RunResult& result) {
  // The zoom resolves the critical point; the Dugdale row locates it between springs.
  if (scene.discretization.rtol || scene.material.finite_range()) return;
  const std::int64_t springs = result.springs;
  const double glued = scene.glued_radius;
  const ResolvedRow row{springs, glued, "glued", "discretization.rtol zooms in on it"};
  if (auto w = unresolved_smooth_peel(result, row, scene.material.adhesive())) {
    result.warnings.push_back(std::move(*w));
  } else if (!status_resolved(result)) {
    result.warnings.push_back(cannot_tell_status(result));
  } else if (auto w = unresolved_critical(result, row)) {
    result.warnings.push_back(std::move(*w));
  }
}

/// A path that never pulls has no adhesive peak (Fig. 3a's positive branch: its most tensile
/// equilibrium is still compressive), as a program of the same path reports none. Decided on
/// the reported value, after the rows are combined: a row's own peak may cross zero where the
/// continuum's is barely tensile, and rtol refines through it.
void drop_peak_that_never_pulls(const Scene& scene, RunResult& result) {
  const ZeroScale zero = shorthand_zero_scale(scene);
  if (result.peak && result.peak->normal_force >= -zero.force) {
    result.peak.reset();
    result.refined_peak.reset();
    result.accuracy.peak_error_estimate.reset();
  }
}

/// A program's fixed row (or Richardson's rows): the shorthand's rule on its a_max.
void warn_program_resolution(const Scene& scene, RunResult& result) {
  if (scene.discretization.rtol) return;  // rtol refines until its estimate meets it
  const ResolvedRow row{result.springs, result.accuracy.outer_radius, "largest",
                        scene.material.relaxes() && !result.refined_critical
                            ? "more discretization.springs resolve it (rtol and Richardson do "
                              "not estimate the viscoelastic row's critical point)"
                            : "discretization.rtol refines the row until it is resolved"};
  const bool adhesive = scene.material.adhesive();
  // The rate law's front loses the contact at the axis, where the last spring lets go: a
  // critical point of no springs that no row resolves better.
  const bool at_axis = scene.front_speed_law.has_value();
  for (auto w :
       {never_in_contact(result, row), at_axis ? std::nullopt : unresolved_critical(result, row),
        unresolved_smooth_peel(result, row, adhesive)}) {
    if (w) result.warnings.push_back(std::move(*w));
  }
  if (!status_resolved(result)) result.warnings.push_back(cannot_tell_status(result));
}

/// A Dugdale run whose zone would reach past a body's edge (a sphere's radius, a table's last
/// point), which only the run finds: refused in one line at `at`, the shorthand's preload (its
/// first state, the contact branch at the preload depth, is too wide) or a program's profile.
template <class Run>
RunResult refusing_zone_past_edge(const Scene& scene, const std::string& at, const Run& run) {
  try {
    return run();
  } catch (const std::domain_error&) {
    throw SceneError(at + fmt::format("with material.adhesive_stress the contact and its cohesive "
                                      "zone reach beyond the profile's outer radius ({} m) {}",
                                      scene.profile->outer_radius(),
                                      scene.program ? "on the program's path"
                                                    : "from this preload on; give a smaller "
                                                      "preload, a wider body or a shorter range "
                                                      "(a larger adhesive_stress)"));
  }
}

/// The continuum route: one answer to rtol from the branch. A program it finds it cannot follow
/// as it runs is refused at the key that chose the route (SPEC "Continuum route").
RunResult run_on_continuum(const Scene& scene, const ObserverList& observers,
                           std::int64_t samples) {
  const double rtol = scene.discretization.rtol.value_or(kContinuumRtol);
  if (scene.material.finite_range()) {
    if (scene.program) {
      return refusing_zone_past_edge(scene, scene.profile_at, [&] {
        return run_dugdale_program(scene, rtol, samples, observers);
      });
    }
    return refusing_zone_past_edge(scene, scene.preload_at, [&] {
      return run_dugdale_continuum(scene, rtol, samples, observers);
    });
  }
  if (!scene.program) return run_continuum(scene, rtol, samples, observers);
  ContinuumProgramRun run = run_continuum_program(scene, rtol, samples, observers);
  if (run.cannot_follow) {
    throw SceneError(scene.plan.continuum_chosen_at + *run.cannot_follow +
                     "; use method = \"event\" (docs/continuum.md)");
  }
  return std::move(run.result);
}

/// The friction outputs a run over several rows leaves the finest row's: the stick/slip front is
/// not located between springs (docs/friction.md).
void warn_friction_uncovered(const Scene& scene, std::string_view fields, RunResult& result) {
  result.warnings.push_back(
      fmt::format("friction: {} are the finest row's ({} springs), not "
                  "covered by {}'s estimates",
                  fields, result.springs, to_string(scene.plan.driver)));
}

RunResult run_on_program_row(const Scene& scene, const ObserverList& observers) {
  // The rate law's row takes an elastic or a relaxing bulk.
  if (scene.front_speed_law) {
    switch (scene.plan.driver) {
      case RouteDriver::rtol:
        return run_rate_law_rtol(scene, *scene.discretization.rtol, observers);
      case RouteDriver::richardson:
        return run_rate_law_richardson(scene, observers);
      case RouteDriver::one_row:
        break;
    }
    return run_rate_law_row(scene, observers);
  }
  if (scene.material.relaxes()) {
    RunResult result;
    switch (scene.plan.driver) {
      case RouteDriver::rtol:
        result = run_viscoelastic_rtol(scene, *scene.discretization.rtol, observers);
        break;
      case RouteDriver::richardson:
        result = run_viscoelastic_richardson(scene, observers);
        break;
      case RouteDriver::one_row:
        return run_viscoelastic_program(scene, observers);
    }
    // The works, friction's included, are combined across the rows (docs/viscoelastic.md
    // "Friction").
    if (scene.friction) warn_friction_uncovered(scene, "springs_sliding and stick_radius", result);
    return result;
  }
  RunResult result;
  switch (scene.plan.driver) {
    case RouteDriver::rtol:
      result = run_program_rtol(scene, *scene.discretization.rtol, observers);
      break;
    case RouteDriver::richardson:
      result = run_program_richardson(scene, observers);
      break;
    case RouteDriver::one_row:
      result = run_program(scene, observers);
      break;
  }
  if (scene.friction && scene.plan.driver != RouteDriver::one_row) {
    warn_friction_uncovered(scene, "springs_sliding, stick_radius and dissipated_by_friction",
                            result);
  }
  return result;
}

RunResult run_on_pull_off_row(const Scene& scene, const ObserverList& observers) {
  if (scene.material.finite_range()) {
    return refusing_zone_past_edge(scene, scene.preload_at,
                                   [&] { return run_dugdale_rows(scene, observers); });
  }
  switch (scene.plan.driver) {
    case RouteDriver::rtol: {
      std::vector<RunResult> glued_rows;
      RunResult result = run_adaptive(scene, *scene.discretization.rtol,
                                      forced_route(scene.discretization), observers, &glued_rows);
      refine_shorthand_path(scene, *scene.discretization.rtol, result, std::move(glued_rows));
      return result;
    }
    case RouteDriver::richardson:
      return run_richardson(scene, observers);
    case RouteDriver::one_row:
      break;
  }
  return run_row(
      scene, {.springs = scene.springs, .outer_radius = scene.glued_radius, .record_path = true},
      observers);
}

/// The run as the scene's plan gives it, without the closing events.
RunResult run_as_given(const Scene& scene, const ObserverList& observers, std::int64_t samples) {
  // Once per run, at the glued radius; a program checks at the radius its rows reach.
  if (!scene.program) {
    check_criterion_contract(*scene.criterion, scene.criterion_name, scene.material,
                             scene.glued_radius);
  }
  RunResult result;
  switch (scene.plan.engine) {
    case RouteEngine::continuum:
      result = run_on_continuum(scene, observers, samples);
      drop_peak_that_never_pulls(scene, result);
      break;
    case RouteEngine::program_row:
      result = run_on_program_row(scene, observers);
      warn_program_resolution(scene, result);
      break;
    case RouteEngine::pull_off_row:
      result = run_on_pull_off_row(scene, observers);
      drop_peak_that_never_pulls(scene, result);
      warn_resolution(scene, result);
      break;
  }
  // The disk check knows no cohesive zone (docs/maugis.md) and no relaxing bulk, whose
  // pressures are not the elastic ones: with either it is not made.
  if (!scene.material.finite_range() && !scene.material.relaxes()) {
    check_disk_states(scene, result);
  }
  result.warnings.insert(result.warnings.begin(), scene.warnings.begin(), scene.warnings.end());
  return result;
}

constexpr const char* kAsItsProgram =
    "the glue lets go with the indenter pressed in: the shorthand runs as its three stages on "
    "the program engine, which follows the springs left pressed (docs/programs.md)";

}  // namespace

RunResult run_scene(const Scene& scene, const ObserverList& observers) {
  return run_scene(scene, observers, scene.solver.samples);
}

RunResult run_scene(const Scene& scene, const ObserverList& observers, std::int64_t samples) {
  if (!scene.plan.made) {
    // A scene built in code rather than read: its route from its fields, as the reader's.
    Scene planned = scene;
    plan_route(planned, {.method_given = true});
    return run_scene(planned, observers, samples);
  }
  const auto started = std::chrono::steady_clock::now();
  RunResult result;
  if (const std::optional<Scene> as_program = pressed_in_on_a_first_row(scene)) {
    engine_logger().info(kAsItsProgram);
    result = run_as_given(*as_program, observers, samples);
  } else if (scene.plan.shorthand_stages && scene.plan.continuum_by_rtol) {
    // rtol alone chose the continuum route: its events wait until it is known to apply.
    CascadeBuffer buffer(observers);
    ObserverList buffered;
    buffered.add(buffer);
    result = run_as_given(scene, buffered, samples);
    if (ends_pressed_in(result)) {
      engine_logger().info(kAsItsProgram);
      result = run_as_given(as_its_program(scene), observers, samples);
    } else {
      buffer.flush();
    }
  } else {
    result = run_as_given(scene, observers, samples);
  }
  for (const std::string& warning : result.warnings) engine_logger().warn("{}", warning);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  emit_closing_events(result, observers);
  return result;
}

}  // namespace mdrsim
