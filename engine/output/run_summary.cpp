// The summary lines: status, program stages and jumps, accuracy, critical point, peak, counts.
#include "engine/output/run_summary.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <string>

#include "engine/model/dimensionless_scales.hpp"
#include "engine/model/snapshot_fields.hpp"
#include "engine/output/result_json.hpp"

namespace mdrsim::cli {
namespace {

/// `v` with a negative zero as 0: a force that is zero because no spring holds reads
/// "F = 0 N", not "F = -0 N".
double plain_zero(double v) { return v == 0.0 ? 0.0 : v; }

/// Why a run has no critical point, in the words of its status.
const char* missing_critical(const RunResult& r) {
  // A program that never touched (e.g. a tensile fixed load from the start).
  if (r.work && r.counts.events == 0) return "none: no spring was ever in contact";
  switch (r.status) {
    case RunStatus::no_instability:
      // A program may have jumped on its way (a jump-in, a jump that kept the contact).
      return r.jumps.empty() ? "none: the contact peeled off smoothly, nothing jumped"
                             : "none: the contact peeled off smoothly at its end (no jump lost it)";
    case RunStatus::shear_off:
      return "none: the tangential load broke the glue as it was applied";
    case RunStatus::step_limit:
      return "none: the run stopped at a limit first (see the warning)";
    case RunStatus::completed:
      return "none: the contact was never lost";
    case RunStatus::instability:
      break;
  }
  return "none";
}

void print_accuracy(std::FILE* out, const Scene& scene, const RunResult& r) {
  const Accuracy& a = r.accuracy;
  // The viscoelastic row's rows estimate its stages and peak, never its critical point
  // (docs/viscoelastic.md "Richardson and rtol"), whether or not there is one.
  const bool bulk_rows = scene.material.relaxes() && (a.route == Accuracy::Route::richardson ||
                                                      scene.discretization.rtol.has_value());
  if (!scene.discretization.rtol && !a.critical_error_estimate && !bulk_rows) {
    // A plain row is the paper's row at N springs: its numbers carry an O(1/N) discretization
    // error that nothing here estimates. Say so, and how to have it estimated.
    if (a.route == Accuracy::Route::row && r.springs > 0) {
      fmt::print(out,
                 "accuracy: plain row of {} springs; its discretization error (O(1/N)) is not "
                 "estimated: extrapolation = \"richardson\" or rtol estimate it\n",
                 r.springs);
    }
    return;
  }
  if (a.route == Accuracy::Route::continuum) {
    std::string line = "continuum route, no springs";
    if (a.critical_error_estimate && r.critical) {
      line += fmt::format("; critical force error estimate {:.3g} N", *a.critical_error_estimate);
    }
    fmt::print(out, "accuracy: {}; rtol {} {}\n", line, scene.discretization.rtol.value_or(0.0),
               a.rtol_met ? "met" : "NOT met");
    return;
  }
  if (r.status == RunStatus::no_instability && !bulk_rows) {
    // rtol followed the peel down to the zoom's floor and found no fold on the way.
    fmt::print(out,
               "accuracy: no fold down to the last spring at a = {:.6g} m (a row of {} springs "
               "zoomed to {:.6g} m)\n",
               a.outer_radius / static_cast<double>(r.springs), r.springs, a.outer_radius);
    return;
  }
  std::string line =
      a.route == Accuracy::Route::richardson ? "richardson over rows of " : "plain row; rows of ";
  line += fmt::format("{} springs across {:.6g} m", fmt::join(a.rows, ", "), a.outer_radius);
  if (a.critical_zoom) {
    line += fmt::format("; critical point on zoomed rows of {} springs across {:.6g} m",
                        fmt::join(a.critical_zoom->rows, ", "), a.critical_zoom->outer_radius);
  }
  if (a.critical_error_estimate && r.critical) {
    line += fmt::format("; critical force error estimate {:.3g} N ({:.3g} relative)",
                        *a.critical_error_estimate,
                        *a.critical_error_estimate / std::abs(r.critical->normal_force));
  }
  if (bulk_rows && r.critical && !a.critical_error_estimate) {
    line += "; the critical point is the finest row's, not estimated";
  }
  if (scene.discretization.rtol) {
    line += fmt::format("; rtol {} {}", *scene.discretization.rtol, a.rtol_met ? "met" : "NOT met");
  }
  fmt::print(out, "accuracy: {}\n", line);
}

/// The springs in contact after a state: ", N springs in contact" (a stage's end) or
/// " (N springs)" (a jump's states); nothing on the continuum route, which has none.
std::string springs_of(const ContactSnapshot& s, bool row, bool jump) {
  if (!row) return {};
  return jump ? fmt::format(" ({} springs)", s.springs_in_contact)
              : fmt::format(", {} springs in contact", s.springs_in_contact);
}

/// A program's stages and jumps, one line each.
void print_program(std::FILE* out, const RunResult& r, bool row) {
  for (const StageRecord& stage : r.stages) {
    const ContactSnapshot& e = stage.end;
    fmt::print(out,
               "stage {}: ends at d = {:.6g} m, F = {:.6g} N, ux = {:.6g} m, Fx = {:.6g} N{}; "
               "work {:.6g} J normal, {:.6g} J tangential\n",
               stage.name, plain_zero(e.indentation), plain_zero(e.normal_force),
               plain_zero(e.tangential_displacement), plain_zero(e.tangential_force),
               springs_of(e, row, false), plain_zero(stage.work.normal),
               plain_zero(stage.work.tangential));
  }
  for (const JumpRecord& jump : r.jumps) {
    const std::string to =
        jump.end == JumpEnd::separated ? "the indenter separates (nothing holds the fixed load)"
        : jump.end == JumpEnd::sliding
            ? "the indenter slides away (nothing holds the tangential fixed load)"
        : jump.end == JumpEnd::pressed
            ? "the indenter pressed in on springs without glue (not followed by the shorthand)"
            : fmt::format("d = {:.6g} m, F = {:.6g} N{}", plain_zero(jump.after.indentation),
                          plain_zero(jump.after.normal_force), springs_of(jump.after, row, true));
    fmt::print(out, "jump {} in stage {}{}: from d = {:.6g} m, F = {:.6g} N{} to {}\n",
               jump.inward ? "in" : "out", jump.stage, jump.by_shear ? " (by shear)" : "",
               plain_zero(jump.critical.indentation), plain_zero(jump.critical.normal_force),
               springs_of(jump.critical, row, true), to);
  }
  if (r.work) {
    fmt::print(out, "work: {:.6g} J normal, {:.6g} J tangential\n", plain_zero(r.work->normal),
               plain_zero(r.work->tangential));
  }
}

}  // namespace

void print_summary(std::FILE* out, const Scene& scene, const RunResult& r) {
  const auto [normal_control, tangential_control] = final_controls(scene, r.stages.size());
  const bool row = scene.solver.method != SolverMethod::continuum;
  fmt::print(out, "status: {}{} (normal {}, tangential {}, criterion {}, {})\n",
             to_string(r.status),
             r.stop_reason ? fmt::format(", stop reason {}", to_string(*r.stop_reason)) : "",
             normal_control, tangential_control, scene.detachment_law(),
             row ? fmt::format("{} springs", r.springs) : std::string("continuum route"));
  print_program(out, r, row);
  print_accuracy(out, scene, r);
  if (!scene.profile->proves_one_disk()) {
    fmt::print(out, "disk: {}\n",
               r.disk_valid ? "one contact disk at every reported state (checked)"
                            : "NOT one contact disk at some reported state (see the warning)");
  }
  const auto s = dimensionless_scales(scene);
  if (r.critical) {
    const ContactSnapshot& c = *r.critical;
    std::string line;
    for (const SnapshotField& f : kSnapshotFields) {
      line += fmt::format("{} = {:.8g} {}, ", f.symbol, plain_zero(c.*f.member), f.unit);
    }
    if (row) line += fmt::format("{} springs in contact", c.springs_in_contact);
    fmt::print(out, "critical: {}\n", row ? line : line.substr(0, line.size() - 2));
    if (s) {
      line.clear();
      for (const SnapshotField& f : kSnapshotFields) {
        line += fmt::format("{}{}/{} = {:.8g}", line.empty() ? "" : ", ", f.symbol,
                            scale_symbol(f.scale), plain_zero(c.*f.member / scale_of(*s, f.scale)));
      }
      fmt::print(out, "dimensionless: {}\n", line);
      fmt::print(out, "scales: F0 = {:.8g} N, a0 = {:.8g} m, d0 = {:.8g} m; {}\n", s->force,
                 s->radius, s->depth, s->basis);
    } else if (!(scene.material.adhesive())) {
      fmt::print(out, "dimensionless: not defined without adhesion (F0 = 0)\n");
    } else {
      fmt::print(out,
                 "dimensionless: not defined for profile \"{}\" (no closed-form pull-off "
                 "scales)\n",
                 scene.profile_name);
    }
  } else {
    fmt::print(out, "critical: {}\n", missing_critical(r));
  }
  if (r.peak) {
    fmt::print(
        out, "peak adhesion: F = {:.8g} N at a = {:.8g} m, d = {:.8g} m{}\n",
        plain_zero(r.peak->normal_force), plain_zero(r.peak->contact_radius),
        plain_zero(r.peak->indentation),
        s ? fmt::format(" (F/F0 = {:.8g})", plain_zero(r.peak->normal_force / s->force)) : "");
  }
  if (r.tangential_strength) {
    fmt::print(
        out, "tangential strength: Fx = {:.8g} N{}\n", plain_zero(*r.tangential_strength),
        s ? fmt::format(" (Fx/F0 = {:.8g})", plain_zero(*r.tangential_strength / s->force)) : "");
  }
  fmt::print(out, "counts: {} events, {} steps, {} halvings; {:.3g} s\n", r.counts.events,
             r.counts.steps, r.counts.halvings, r.wall_time_s);
}

}  // namespace mdrsim::cli
