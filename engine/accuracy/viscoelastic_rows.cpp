// Rows of the viscoelastic row combined: Richardson across N/4 ... 2N springs, and rtol by
// doubling the springs until the estimates meet it.
#include "engine/accuracy/viscoelastic_rows.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "engine/accuracy/doubling_rows.hpp"
#include "engine/program/run_viscoelastic_program.hpp"
#include "engine/result/rtol_rule.hpp"

namespace mdrsim {
namespace {

/// rtol's first row.
constexpr std::int64_t kFirstViscoelasticSprings = 256;

RunResult viscoelastic_row_of(const Scene& scene, std::int64_t springs,
                              const ObserverList& observers) {
  Scene row = scene;
  row.springs = springs;
  return run_viscoelastic_program(row, observers);
}

/// Whether the rows end alike (status, why a limit stopped them, stages, the critical point's
/// presence and stage, a peak), so that their values are the same quantities.
bool viscoelastic_rows_alike(std::span<const RunResult> rows) {
  const RunResult& c = rows.back();
  for (const RunResult* r = rows.data(); r != &c; ++r) {
    if (r->status != c.status || r->stop_reason != c.stop_reason ||
        r->stages.size() != c.stages.size() || r->critical.has_value() != c.critical.has_value() ||
        r->critical_stage != c.critical_stage || r->peak.has_value() != c.peak.has_value()) {
      return false;
    }
  }
  return true;
}

/// The order of an event time's error across the rows: 2 where its changes fall by 4 (within
/// 10 %) at both doublings, else 1. A contact lost at zero force on a parabola is the first:
/// its last spring, at x = a / N, leaves as the contact radius passes it, and the radius falls
/// like the square root of the time left. Equal times (a stage of fixed duration) are exact
/// either way.
int event_time_order(double coarsest, double coarse, double middle, double fine) {
  const double d1 = coarse - coarsest;
  const double d2 = middle - coarse;
  const double d3 = fine - middle;
  if (d2 == 0.0 || d3 == 0.0) return 1;
  const auto near_four = [](double ratio) { return std::abs(ratio - 4.0) <= 0.4; };
  return near_four(d1 / d2) && near_four(d2 / d3) ? 2 : 1;
}

/// The finest of four rows with the values named in `covers` replaced by their values across
/// the rows, and whether every estimate meets rtol.
class ViscoelasticCombination {
 public:
  ViscoelasticCombination(std::span<const RunResult, 4> rows, bool extrapolate, double rtol)
      : rows_(rows), extrapolate_(extrapolate), rtol_(rtol), result_(rows[3]) {}

  /// The field `field(row)` of every row combined into the result's; its estimate, held to
  /// rtol max(|value|, floor) where `floor` >= 0 (a negative floor: not held), into `met` where
  /// given, else into met().
  template <class Field>
  double combine(Field field, double floor, int order = 1, bool* met = nullptr) {
    const DoublingValue v = doubling_value(field(rows_[0]), field(rows_[1]), field(rows_[2]),
                                           field(result_), extrapolate_, order);
    field(result_) = v.value;
    bool& held = met ? *met : met_;
    if (floor >= 0.0) held = held && meets_rtol(v.error, v.value, rtol_, floor);
    return v.error;
  }
  /// Whether rtol is held (not 0: Richardson's rows hold none).
  double rtol() const { return rtol_; }

  /// The order of the error of the time `field` across the rows (event_time_order).
  template <class Field>
  int time_order(Field field) const {
    return event_time_order(field(rows_[0]), field(rows_[1]), field(rows_[2]), field(result_));
  }
  RunResult& result() { return result_; }
  bool met() const { return met_; }

 private:
  std::span<const RunResult, 4> rows_;
  bool extrapolate_;
  double rtol_;
  RunResult result_;
  bool met_ = true;
};

/// Every term of a stage's energy balance combined as its work is, so that the combined
/// balance closes as each row's does (the combination is linear); no estimates of their own.
void combine_viscoelastic_energy(ViscoelasticCombination& c, std::size_t k) {
  if (!c.result().stages[k].energy) return;
  const auto term = [&](double EnergyBalance::*member) {
    c.combine(
        [&](auto& r) -> auto& { return (*r.stages[k].energy).*member; }, -1.0);
  };
  for (double EnergyBalance::*member :
       {&EnergyBalance::machine_work, &EnergyBalance::stored_change, &EnergyBalance::surface_change,
        &EnergyBalance::dissipated_by_friction, &EnergyBalance::dissipated_by_bulk,
        &EnergyBalance::jump_losses, &EnergyBalance::residual}) {
    term(member);
  }
}

/// Whether every row located its critical point between springs (viscoelastic_fold.hpp).
bool viscoelastic_critical_located(std::span<const RunResult, 4> rows) {
  return std::all_of(rows.begin(), rows.end(), [](const RunResult& q) {
    return q.critical.has_value() && q.refined_critical.has_value();
  });
}

/// Whether stage `s` of `q` ended at its critical point (the glue's loss ends its stage there).
bool viscoelastic_stage_ends_at_critical(const RunResult& q, const StageRecord& s) {
  return q.critical && s.name == q.critical_stage && s.end.time == q.critical->time;
}

/// The state `end` of a stage moved to the critical point `fold` in time: the continuum's stage
/// ends at its fold.
void move_viscoelastic_end_to(const ContactSnapshot& fold, ContactSnapshot& end) {
  end.time = fold.time;
  end.indentation = fold.indentation;
  end.normal_control = fold.normal_control;
}

/// The rows with their critical point where they located it between springs, and the end of
/// the stage that ended at it there too.
std::array<RunResult, 4> viscoelastic_rows_at_fold(std::span<const RunResult, 4> rows) {
  std::array<RunResult, 4> moved{rows[0], rows[1], rows[2], rows[3]};
  for (RunResult& q : moved) {
    const ContactSnapshot& fold = *q.refined_critical;
    for (StageRecord& s : q.stages) {
      if (viscoelastic_stage_ends_at_critical(q, s)) move_viscoelastic_end_to(fold, s.end);
    }
    q.critical = fold;
  }
  return moved;
}

/// The finest of four rows (N/4, N/2, N, 2N springs) with the stages' end forces, times and
/// works, the peak tension, the critical point and the totals replaced by their values across
/// the rows, and their estimates. The critical point is the one every row located between
/// springs (viscoelastic_fold.hpp); where one did not (a shear-off, a cascade from the first
/// let-go), it stays the finest row's: it sits on a spring, the same spring of every row of a
/// doubling sequence, and the force still varies along the branch there, so the rows agree on a
/// value O(1/N) off that their changes do not show; so do the stage end times of such a run
/// (the glue's loss ends its stage at the critical point's time).
DoublingCombined combine_viscoelastic_rows(std::span<const RunResult, 4> plain_rows,
                                           bool extrapolate, double rtol) {
  const bool located = viscoelastic_critical_located(plain_rows);
  std::array<RunResult, 4> at_fold;
  std::optional<std::size_t> fold_stage;  // the finest row's stage that ended at the fold
  if (located) {
    at_fold = viscoelastic_rows_at_fold(plain_rows);
    const RunResult& finest = plain_rows[3];
    for (std::size_t k = 0; k < finest.stages.size(); ++k) {
      if (viscoelastic_stage_ends_at_critical(finest, finest.stages[k])) fold_stage = k;
    }
  }
  const std::span<const RunResult, 4> rows =
      located ? std::span<const RunResult, 4>(at_fold) : plain_rows;
  ViscoelasticCombination c(rows, extrapolate, rtol);
  RunResult& r = c.result();
  double force_scale = r.peak ? std::abs(r.peak->normal_force) : 0.0;
  double depth_scale = r.critical ? std::abs(r.critical->indentation) : 0.0;
  double work_scale = 1e-300;
  for (const StageRecord& s : r.stages) {
    force_scale = std::max(force_scale, std::abs(s.end.normal_force));
    depth_scale = std::max(depth_scale, std::abs(s.end.indentation));
    work_scale += std::abs(s.work.normal) + std::abs(s.work.tangential) +
                  std::abs(s.work.friction) + std::abs(s.work.bulk);
  }
  // A stage's end force is held to rtol of the path's largest force (a stage may end at zero
  // force, where its relative error has no meaning), a time to rtol of the program's duration.
  const double force_floor = 1e-300 + force_scale;
  const double time_floor = 1e-300 + (r.stages.empty() ? 0.0 : std::abs(r.stages.back().end.time));
  double critical_time_error = 0.0;
  bool critical_met = true;
  if (located) {
    // A depth is held to rtol of the path's deepest (the fold's may lie near zero), a radius to
    // rtol of the row's.
    const double depth_floor = 1e-300 + depth_scale;
    const double radius_floor = 1e-300 + r.accuracy.outer_radius;
    r.accuracy.critical_error_estimate = c.combine(
        [](auto& q) -> auto& { return q.critical->normal_force; }, force_floor, 1, &critical_met);
    c.combine(
        [](auto& q) -> auto& { return q.critical->indentation; }, depth_floor, 1, &critical_met);
    c.combine(
        [](auto& q) -> auto& { return q.critical->normal_control; }, -1.0);
    c.combine(
        [](auto& q) -> auto& { return q.critical->contact_radius; }, radius_floor, 1,
        &critical_met);
    c.combine(
        [](auto& q) -> auto& { return q.critical->glued_radius; }, -1.0);
    c.combine(
        [](auto& q) -> auto& { return q.critical->tangential_force; }, -1.0);
    c.combine(
        [](auto& q) -> auto& { return q.critical->tangential_displacement; }, -1.0);
    critical_time_error = c.combine(
        [](auto& q) -> auto& { return q.critical->time; }, time_floor, 1, &critical_met);
    r.refined_critical = r.critical;
  }
  if (r.peak) {
    r.accuracy.peak_error_estimate = c.combine(
        [](auto& q) -> auto& { return q.peak->normal_force; }, force_floor);
  }
  AxisWork total;
  AxisWork total_error;
  EnergyBalance total_energy;
  for (std::size_t k = 0; k < r.stages.size(); ++k) {
    StageRecord& s = r.stages[k];
    s.normal_force_error_estimate = c.combine(
        [k](auto& q) -> auto& { return q.stages[k].end.normal_force; }, force_floor);
    if (!r.critical || located) {
      // Under fixed grips the depth is the held depth at the end's time: it moves with it.
      const auto time = [k](auto& q) -> auto& { return q.stages[k].end.time; };
      const int order = c.time_order(time);
      s.time_error_estimate = c.combine(time, time_floor, order);
      c.combine(
          [k](auto& q) -> auto& { return q.stages[k].end.indentation; }, -1.0, order);
      c.combine(
          [k](auto& q) -> auto& { return q.stages[k].end.normal_control; }, -1.0, order);
    }
    AxisWork error;
    error.normal = c.combine(
        [k](auto& q) -> auto& { return q.stages[k].work.normal; }, work_scale);
    error.bulk = c.combine(
        [k](auto& q) -> auto& { return q.stages[k].work.bulk; }, work_scale);
    // A tangential stage's work and friction's share of it are the rows' sums as the normal
    // work is: combined and estimated alike, or `work` would claim what only the finest row has.
    error.tangential = c.combine(
        [k](auto& q) -> auto& { return q.stages[k].work.tangential; }, work_scale);
    error.friction = c.combine(
        [k](auto& q) -> auto& { return q.stages[k].work.friction; }, work_scale);
    s.work_error_estimate = error;
    combine_viscoelastic_energy(c, k);
    total += s.work;
    total_error += error;
    if (s.energy) total_energy += *s.energy;
  }
  if (fold_stage) {
    // Ends exactly at the combined critical point (its time combined as the critical's is).
    StageRecord& s = r.stages[*fold_stage];
    move_viscoelastic_end_to(*r.critical, s.end);
    s.time_error_estimate = critical_time_error;
  }
  r.work = total;
  if (r.energy) r.energy = total_energy;
  r.accuracy.work_error_estimate = total_error;
  r.accuracy.covers = {"stages.end.normal_force", "stages.work", "work"};
  if (!r.critical || located) {
    r.accuracy.covers.insert(r.accuracy.covers.begin() + 1, "stages.end_time");
  }
  if (r.peak) r.accuracy.covers.insert(r.accuracy.covers.begin(), "peak_adhesion.normal_force");
  // Where rounding alone takes what rtol allows a field of the critical point, more
  // springs cannot locate the fold better (viscoelastic_fold.hpp): the critical point is
  // reported with its estimate, and left out of covers.
  const auto rounding_of = [&](double ContactSnapshot::*field) {
    const double fine = rows[3].refined_critical_rounding.*field;
    return extrapolate ? 2.0 * fine + rows[2].refined_critical_rounding.*field : fine;
  };
  bool critical_rounded = false;
  if (located && !critical_met && c.rtol() > 0.0) {
    for (const auto& [field, floor] :
         {std::pair{&ContactSnapshot::normal_force, force_floor},
          std::pair{&ContactSnapshot::indentation, 1e-300 + depth_scale},
          std::pair{&ContactSnapshot::contact_radius, 1e-300 + r.accuracy.outer_radius},
          std::pair{&ContactSnapshot::time, time_floor}}) {
      const double rounding = rounding_of(field);
      critical_rounded =
          critical_rounded || !meets_rtol(rounding, (*r.critical).*field, c.rtol(), floor);
    }
  }
  if (located && !critical_rounded) {
    r.accuracy.covers.insert(r.accuracy.covers.begin(),
                             {"critical.normal_force", "critical.indentation",
                              "critical.contact_radius", "critical.time"});
  }
  if (critical_rounded) {
    r.warnings.push_back(fmt::format(
        "rtol: the critical point's place between springs is limited by rounding on rows of {} "
        "springs (its force to about {:.2g} N, estimate {:.2g} N): it is reported without "
        "meeting rtol = {:.3g}, and covers leaves critical.* out",
        r.springs, rounding_of(&ContactSnapshot::normal_force), *r.accuracy.critical_error_estimate,
        c.rtol()));
  }
  r.accuracy.rows = {rows[0].springs, rows[1].springs, rows[2].springs, r.springs};
  const bool met = c.met() && (critical_met || critical_rounded);
  return {std::move(r), met};
}

DoublingRows viscoelastic_rows(const Scene& scene) {
  return {[&scene](std::int64_t springs, const ObserverList& observers) {
            return viscoelastic_row_of(scene, springs, observers);
          },
          viscoelastic_rows_alike, combine_viscoelastic_rows};
}

}  // namespace

RunResult run_viscoelastic_richardson(const Scene& scene, const ObserverList& observers) {
  return run_doubling_richardson(scene.springs, observers, viscoelastic_rows(scene));
}

RunResult run_viscoelastic_rtol(const Scene& scene, double rtol, const ObserverList& observers) {
  const bool extrapolate =
      scene.discretization.extrapolation != DiscretizationOptions::Extrapolation::none;
  return run_doubling_rtol(rtol, extrapolate, kFirstViscoelasticSprings,
                           scene.discretization.max_row_springs, observers,
                           viscoelastic_rows(scene));
}

}  // namespace mdrsim
