// The program loop: per stage, find the next change of the spring row exactly in the stage
// parameter, move there (the equilibrium is affine in between, so the work is exact), apply
// it and every change it makes due at the same parameter (a cascade: a jump when it moves
// more than one spring).
#include "engine/program/program_runner.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "detachment/let_go.hpp"
#include "engine/base/engine_logger.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/program/bulk_paths.hpp"
#include "engine/program/graded_springs.hpp"
#include "engine/program/let_go_trail.hpp"
#include "engine/program/path_watch.hpp"
#include "engine/program/program_events.hpp"
#include "engine/program/program_flight.hpp"
#include "engine/program/program_front.hpp"
#include "engine/program/program_limits.hpp"
#include "engine/program/program_outcome.hpp"
#include "engine/program/program_record.hpp"
#include "engine/program/program_step.hpp"
#include "engine/program/stage_position.hpp"

namespace mdrsim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr std::int64_t kNoLimit = std::numeric_limits<std::int64_t>::max();
/// Stepping: the default increment of the stage parameter.
constexpr double kDefaultStageStep = 1e-3;

std::optional<GradedHessCriterion> graded_criterion(const std::optional<GradedSprings>& springs,
                                                    const Material& material) {
  if (!springs) return std::nullopt;
  return GradedHessCriterion(*springs, material.work_of_adhesion);
}

class ProgramRunner {
 public:
  ProgramRunner(const Scene& scene, const ProgramRowSpec& spec, const ObserverList& observers,
                LargestContact* largest, LastStageStart* last_stage)
      : scene_(scene),
        graded_springs_(GradedSprings::of(scene.graded_image, scene.material)),
        graded_criterion_(graded_criterion(graded_springs_, scene.material)),
        criterion_(graded_criterion_ ? *graded_criterion_ : *scene.criterion),
        step_(scene.solver.method == SolverMethod::stepping
                  ? std::optional(scene.solver.step.value_or(kDefaultStageStep))
                  : std::nullopt),
        at_(ProgramRow(*scene.profile, scene.material, spec.reference_radius,
                       spec.reference_springs, spec.reference_image, scene.program->rebinding)),
        max_springs_(spec.max_springs),
        zero_(spec.zero),
        zoomed_(spec.zoomed),
        events_(observers),
        watch_(scene, spec.zero.force, largest, last_stage),
        limits_(scene.solver, spec.max_springs) {
    at_.row.record_edge_forces(spec.edge_forces);
    if (graded_springs_) at_.row.use_graded_springs(*graded_springs_);
    if (scene.friction) at_.row.enable_friction(*scene.friction);
    // The front located between springs knows no friction: friction rows report their own.
    if (spec.refine && !step_ && !scene.friction) front_.emplace(criterion_);
  }

  RunResult run();

 private:
  /// `machine_set`: a zoomed row's first stage, whose machine the zoom set already.
  void start_stage(const Stage& stage, bool machine_set);
  [[gnu::noinline]] void follow_stage(const Stage& stage);  // keeps next_change inlined in it
  /// Where the stage ended: its record and its stage_end event.
  void end_stage(const Stage& stage);
  /// Moves along the line to t, with no change on the way.
  void advance_to(double t) {
    if (!at_.advance_to(t)) outcome_.stop(StopReason::overflow);
  }
  StepLine step_line() const {
    return {at_.t, at_.line.normal, at_.line.tangential, at_.guards, max_springs_, row_end_};
  }
  /// The change due now into `change` (an out-parameter: the loop reads it back in one word);
  /// false where none is. Outgrowing the row stops the program.
  bool due(Change& change) {
    bool outgrew = false;
    const auto due = locator_.due(at_.row, step_line(), outgrew);
    if (outgrew) outcome_.stop(StopReason::outgrew_row);
    if (!due) return false;
    change = *due;
    return true;
  }
  std::optional<std::pair<double, Change>> next_change(double t_end) {
    return locator_.next_change(at_.row, step_line(), t_end);
  }
  /// Each spring changes at most twice per parameter value (the guards): a cascade past this
  /// does not settle.
  std::int64_t cascade_cap() const { return 4 * (max_springs_ + 2); }
  /// `in_cascade`: a change at the parameter value of the one before it.
  void apply(Change change, Cascade& cascade, bool in_cascade);
  /// The state a cascade starts from, observed as an equilibrium.
  Cascade begin_cascade();
  /// Applies `first` and every change then due at the same t; stops before the change that
  /// would exceed `limit` changes and returns true if one was still due.
  bool run_changes(std::optional<Change> first, Cascade& cascade, std::int64_t limit = kNoLimit);
  /// A cascade from the present state: `first` (where found ahead) and every change due with
  /// it, its events held where it may end in a flight (`hold`).
  void run_cascade(std::optional<Change> first, bool hold);
  void finish_cascade(const Cascade& cascade);
  /// A flight: the stage ends at the cascade's critical point, with the work up to it.
  void end_in_flight(const Cascade& cascade, JumpEnd end);
  void take_step(double t_end);
  /// A bulk path (bulk_paths.hpp) taken or not: what it leaves the loop to do.
  bool after_bulk(BulkEnd end);
  void observe(const ContactSnapshot& s, const ContactSnapshot* cascade_before = nullptr) {
    watch_.observe(s, at_.row, *at_.stage, cascade_before);
  }
  /// The progress line of a long stage, out of line so that the event loop stays tight.
  [[gnu::cold, gnu::noinline]] void log_progress(const Stage& stage);

  const Scene& scene_;
  /// A graded half-space's springs, and Hess's rule on them for the scene's criterion (a
  /// graded scene names none: docs/graded.md).
  std::optional<GradedSprings> graded_springs_;
  std::optional<GradedHessCriterion> graded_criterion_;
  const DetachmentCriterion& criterion_;
  std::optional<double> step_;  ///< stepping: the increment of the stage parameter
  StagePosition at_;            ///< the row in the stage under way
  std::int64_t max_springs_;
  /// The last spring that exists: a zoomed row has none outside its radius (the springs there
  /// have let go, unpressed, by the time its front reaches them: program_zoom.hpp).
  std::int64_t row_end_ = kNoLimit;
  ZeroScale zero_;  ///< below it a force is rounding: no peak, no critical point
  std::optional<ZoomedStart> zoomed_;
  ProgramEvents events_;
  PathWatch watch_;
  RunResult result_;
  std::optional<ProgramFront> front_;  ///< refining rows only
  EventLimits limits_;
  ProgramRecord record_{result_};  ///< stages, jumps and work
  ChangeLocator locator_{criterion_, result_.counts.root_iterations};
  ProgramOutcome outcome_;
  LetGoTrail let_go_trail_;
  Flight flight_;  ///< a flight that ended the program
};

void ProgramRunner::apply(Change change, Cascade& cascade, bool in_cascade) {
  // At one t only a fixed-load axis moves its driving point (the indenter, at constant force);
  // under fixed grips and compliant the driving point is the held value, which stays.
  const bool normal_moves = holds_force(at_.row.normal().constraint);
  const bool tangential_moves = holds_force(at_.row.tangential().constraint);
  const AxisPoint n0 = normal_moves ? at_.normal_point() : AxisPoint{};
  const AxisPoint x0 = tangential_moves ? at_.tangential_point() : AxisPoint{};
  const std::int64_t k = at_.row.glued();
  const std::int64_t m = at_.row.in_contact();
  // Only a glue or a let-go moves energy at one parameter value (a touch, a lift, a slip or a
  // stick changes no spring's force there). Where they stay local the row sums what they
  // release; else it is measured on the whole row.
  const bool measured = (change == Change::glue || change == Change::let_go) && !at_.energy.local;
  const StagePosition::EnergyPoint energy_before =
      measured ? at_.energy_point() : StagePosition::EnergyPoint{};
  bool by_shear = false;
  switch (change) {
    case Change::fall_in:
      at_.row.edit_normal().rest = at_.row.image(1);
      break;
    case Change::glue:
      at_.row.glue_next();
      at_.guards.glued_from = std::min(at_.guards.glued_from, k + 1);
      events_.spring(EventKind::spring_glued, at_.row, k + 1, in_cascade);
      break;
    case Change::let_go: {
      const double d = at_.row.indentation();
      const double u = at_.row.tangential_displacement();
      // Glued again at this parameter only if it goes with a stretch (its own, before the let-go).
      const bool with_stretch = at_.row.boundary_stretch(d, u) != 0.0;
      const double stretch_x = at_.row.boundary_released_stretch(d, u);
      // Broken at rest is a let-go `now`: the boundary's let-go is cached for this stretch.
      by_shear = locator_.boundary_let_go(at_.row, stretch_x).kind == LetGo::Kind::now;
      let_go_trail_.note(cascade, at_.row, at_.line, criterion_, k, stretch_x, by_shear);
      events_.spring(EventKind::spring_detached, at_.row, k, in_cascade);
      at_.work.friction += at_.row.let_go_boundary(at_.row.image(k) <= d);
      at_.guards.released_to = std::max(at_.guards.released_to, k);
      at_.guards.released_with_stretch = with_stretch;
      break;
    }
    case Change::touch:
      at_.row.touch_next();
      at_.guards.touched_from = std::min(at_.guards.touched_from, m + 1);
      events_.spring(EventKind::spring_touched, at_.row, m + 1, in_cascade);
      break;
    case Change::lift:
      events_.spring(EventKind::spring_lifted, at_.row, m, in_cascade);
      at_.row.lift_outer();
      at_.guards.lifted_to = std::max(at_.guards.lifted_to, m);
      break;
    case Change::friction: {
      // Each spring slips or sticks a few times at one parameter at most: more is a loop,
      // which run_changes stops (an unending cascade).
      ++cascade.friction_events;
      const RowFrictionEvent& event = locator_.friction_event();
      at_.row.apply_friction(event);
      ++result_.counts.events;
      events_.slip(event.event.kind, at_.row, event.spring, in_cascade);
      break;
    }
  }
  at_.add_work(normal_moves ? &n0 : nullptr, tangential_moves ? &x0 : nullptr);
  if (measured) at_.add_release(energy_before);
  // What the locator keeps of a run that may glue again (rebinding).
  if (at_.row.friction()) locator_.changed(change, m);
  if (change != Change::fall_in && change != Change::friction) {
    cascade.count(change, by_shear);
    ++result_.counts.events;
  }
}

void ProgramRunner::end_in_flight(const Cascade& cascade, JumpEnd end) {
  // What the cascade did after its critical point is the flight: its springs' stretches
  // (the held force on the last spring alone) and the work at constant force grow with the
  // spring count, and none of it is reported.
  events_.discard_flight(!step_);
  flight_ = {end,
             cascade.before,
             cascade.refined_before,
             cascade.stored_before,
             cascade.surface_before,
             cascade.released_before};
  at_.work = cascade.work_before;
  outcome_.losses().record(cascade, at_.row.glued(), at_.row.in_contact());
  if (cascade.changes < 2) return;
  JumpRecord& jump = record_.add_jump(cascade, at_.row.in_contact(), at_.row.glued());
  jump.end = end;
  jump.refined_critical = cascade.refined_before;
  events_.emit(EventKind::jump, cascade.before);
}

void ProgramRunner::finish_cascade(const Cascade& cascade) {
  // An unending cascade is not an equilibrium: nothing is recorded.
  if (outcome_.stopped_by(StopReason::unending_cascade)) return;
  if (const JumpEnd end = flight_of(cascade, at_.row, at_.line); end != JumpEnd::state) {
    end_in_flight(cascade, end);
    return;
  }
  events_.release();
  const ContactSnapshot after = at_.row.snapshot();
  // `before` is within range: advance_to checked the work up to it.
  if (!within_double(after) || !at_.work_within_double()) {
    outcome_.stop(StopReason::overflow);  // values beyond a double: nothing of it is recorded
    return;
  }
  observe(after, &cascade.before);
  outcome_.losses().record(cascade, at_.row.glued(), at_.row.in_contact());
  // Springs that carry no force and no glue leaving together (a flat tip at rounding) is no jump.
  const bool idle = cascade.glued == 0 && at_.row.glued() == 0 &&
                    zero_.zero_force(cascade.before.normal_force) &&
                    zero_.zero_force(after.normal_force);
  if (cascade.changes < 2 || idle) return;
  JumpRecord& jump = record_.add_jump(cascade, at_.row.in_contact(), at_.row.glued());
  jump.inward = jump.springs > 0 || (jump.springs == 0 && jump.glued_springs > 0);
  jump.after = after;
  if (front_) {
    jump.refined_critical = cascade.refined_before;
    jump.refined_after = front_->at_rest(at_.row);
    if (cascade.fold_parameter) {
      if (auto landed = front_->at_rest_at(at_.row, at_.line, *cascade.fold_parameter)) {
        jump.refined_after = landed;
      }
    }
    front_->other_change();
    front_->candidate(jump.refined_critical);
    front_->candidate(jump.refined_after);
  }
  events_.emit(EventKind::jump, after);
}

void ProgramRunner::start_stage(const Stage& stage, bool machine_set) {
  if (stage.normal && !machine_set) at_.row.hand_normal_to(stage.normal->controller->constraint());
  if (stage.tangential && !machine_set) {
    at_.row.hand_tangential_to(stage.tangential->controller->constraint());
  }
  at_.start(stage);
  let_go_trail_.clear();
  events_.start_stage(stage.name);
  watch_.start_stage(stage, at_.row);
  if (front_) front_->stage_started();
}

Cascade ProgramRunner::begin_cascade() {
  // Built in place, the snapshot with it: not assigned into a zeroed Cascade.
  Cascade cascade{.before = at_.row.snapshot(),
                  .in_contact = at_.row.in_contact(),
                  .glued = at_.row.glued(),
                  .work_before = at_.work,
                  .stage = at_.stage};
  // Only a held force can end a cascade in a flight, whose stage ends at `before`.
  if (holds_force(at_.row.normal().constraint) || holds_force(at_.row.tangential().constraint)) {
    cascade.stored_before = at_.row.stored_energy();
    cascade.surface_before = at_.row.glued_surface();
    cascade.released_before = at_.released();
  }
  observe(cascade.before);
  return cascade;
}

bool ProgramRunner::run_changes(std::optional<Change> first, Cascade& cascade, std::int64_t limit) {
  bool in_cascade = false;
  if (first) {
    apply(*first, cascade, in_cascade);
    in_cascade = true;
  }
  // Every spring a change makes due at this parameter value goes with it.
  const std::int64_t cap = cascade_cap();
  Change change{};
  while (due(change)) {
    if (cascade.changes >= limit) return true;
    if (front_ && cascade.changes == 1 && cascade.first == change) {
      // The critical point of a jump out of a run of let-gos, or into one of glues.
      if (change == Change::let_go) {
        cascade.refined_before = front_->fold(at_.row, at_.line, at_.t, cascade.before);
      } else if (change == Change::glue) {
        cascade.refined_before = front_->advancing_fold(at_.row, at_.line, at_.t, cascade.before);
      }
      if (cascade.refined_before) cascade.fold_parameter = front_->fold_parameter();
    }
    if (cascade.changes > cap || cascade.friction_events > cap) {
      // Rounding at values far from the scene's scales (a push until separation that goes on
      // for ever) can keep one parameter value's changes (or slips and sticks) from settling:
      // stop there.
      outcome_.stop_unending(at_.t);
      return false;
    }
    apply(change, cascade, in_cascade);
    in_cascade = true;
  }
  return false;
}

void ProgramRunner::run_cascade(std::optional<Change> first, bool hold) {
  Cascade cascade = begin_cascade();
  events_.hold(hold);
  run_changes(first, cascade);
  events_.hold(false);
  finish_cascade(cascade);
  // A located change that ends in a flight ends the stage before the front hears of it.
  if (front_ && !(first && flight_.flying())) front_->track(cascade, at_.t);
}

void ProgramRunner::take_step(double t_end) {
  // The paper's increments on the stage parameter: a step that changes more than one spring
  // is taken back and halved, down to max_halvings (SolverOptions).
  double step = *step_;
  for (int halvings = 0;; ++halvings) {
    double target = std::min(at_.t + step, t_end);
    if (!(target > at_.t)) target = next_parameter(at_.t);
    const bool last_try = halvings >= scene_.solver.max_halvings || at_.t + 0.5 * step == at_.t;
    const StagePosition saved = at_;  // what a trial step changes, to take it back
    const RunCounts saved_counts = result_.counts;
    Cascade cascade = begin_cascade();  // its `before` is the last accepted equilibrium
    events_.drop();
    events_.hold(true);
    advance_to(target);
    const bool more = run_changes(std::nullopt, cascade, last_try ? kNoLimit : 1);
    events_.hold(false);
    if (outcome_.stopped_by(StopReason::unending_cascade)) return;
    if (more && !last_try) {
      at_ = saved;
      result_.counts = saved_counts;
      locator_.forget();
      step *= 0.5;
      ++result_.counts.halvings;
      events_.step(EventKind::step_halved, at_.row, step);
      continue;
    }
    ++result_.counts.steps;
    // A step that went past the critical point into the flight keeps none of its events.
    if (flight_of(cascade, at_.row, at_.line) == JumpEnd::state) {
      events_.release();
      events_.step(EventKind::step_accepted, at_.row, step);
    }
    finish_cascade(cascade);
    return;
  }
}

bool ProgramRunner::after_bulk(BulkEnd end) {
  if (end == BulkEnd::not_taken) return false;
  if (end == BulkEnd::overflow) outcome_.stop(StopReason::overflow);
  if (end == BulkEnd::unending) outcome_.stop_unending(at_.t);
  if (end != BulkEnd::taken) return true;
  // Slips and sticks applied outside the locator: what it knows of the runs goes.
  if (at_.row.friction()) locator_.forget();
  observe(at_.row.snapshot());  // the ends of a bulk path hold its extremes
  if (front_) front_->other_change();
  return true;
}

void ProgramRunner::log_progress(const Stage& stage) {
  engine_logger().info(
      "program running: stage '{}' at parameter {:.4g}, {} springs in contact, {} events, {} "
      "steps",
      stage.name, at_.t, at_.row.in_contact(), result_.counts.events, result_.counts.steps);
}

void ProgramRunner::follow_stage(const Stage& stage) {
  if (stage.until_separation && at_.row.in_contact() == 0) {
    result_.warnings.push_back(fmt::format(
        "stage '{}' runs until separation but starts with no spring in contact: it ends at once",
        stage.name));
    return;
  }
  const double t_end = stage.until_separation ? kInfinity : 1.0;
  const bool hold_cascades = events_.springs() && (holds_force(at_.row.normal().constraint) ||
                                                   holds_force(at_.row.tangential().constraint));
  const bool presses_in_bulk = stage_presses_in_bulk(at_.row, at_.line, t_end, events_.springs());
  const bool slides_in_bulk =
      stage_slides_in_bulk(at_.row, at_.line, step_.has_value(), events_.slips());
  const std::int64_t last_spring = std::min(max_springs_, row_end_);
  const auto slide = [&](std::int64_t events_until) {
    return slide_in_bulk(at_, t_end, events_until, row_end_, cascade_cap(), result_.counts);
  };
  // The sticks a ramp's reversal makes due at its start are a friction row's own as well.
  if (slides_in_bulk) after_bulk(slide(limits_.before_stage()));
  if (!outcome_.stopped()) run_cascade(std::nullopt, hold_cascades);
  limits_.start_stage(result_.counts.events);
  while (!outcome_.stopped() && !flight_.flying()) {
    if (stage.until_separation && at_.row.in_contact() == 0) break;
    if (result_.counts.events > limits_.look_at()) [[unlikely]] {
      if (const auto limit = limits_.passed(result_.counts.events)) {
        outcome_.stop(*limit);
        break;
      }
      if (limits_.progress_due(result_.counts.events)) log_progress(stage);
    }
    if (cannot_hold(at_.row, at_.line)) {
      outcome_.stop_lost_hold(at_.row);
      break;
    }
    if (step_) {
      if (at_.t >= t_end) break;
      if (result_.counts.steps >= scene_.solver.max_steps) {
        outcome_.stop(StopReason::max_steps);
        break;
      }
      take_step(t_end);
      continue;
    }
    if (presses_in_bulk && after_bulk(press_in_bulk(at_, t_end, last_spring, result_.counts))) {
      continue;
    }
    if (slides_in_bulk && after_bulk(slide(limits_.look_at()))) continue;
    const auto next = next_change(t_end);
    if (!next) {
      if (std::isfinite(t_end)) {
        advance_to(t_end);
        // What the end's exact held value makes due there (spring N reached at a_max).
        run_cascade(std::nullopt, false);
      } else {
        outcome_.stop(StopReason::no_end);
      }
      break;
    }
    advance_to(next->first);
    if (outcome_.stopped()) break;  // overflow
    // Under a fixed load a cascade may end in a flight, whose springs are not reported.
    run_cascade(next->second, hold_cascades);
  }
}

void ProgramRunner::end_stage(const Stage& stage) {
  // The stage's numbers left the range of a double, or its changes did not settle.
  if (outcome_.stopped_by(StopReason::overflow) ||
      outcome_.stopped_by(StopReason::unending_cascade)) {
    return;
  }
  const bool stopped = outcome_.stopped();
  if (flight_.flying()) {
    // The stop the loop's next turn would have found (the outcome reads the status from it).
    if (!stopped && !(stage.until_separation && at_.row.in_contact() == 0)) {
      outcome_.stop_lost_hold(at_.row);
    }
    // The stage ends where the flight began: its critical point.
    StageRecord& record = record_.end_stage(stage.name, flight_.from, at_.work);
    record.refined_end = flight_.refined_from;
    record.energy = at_.balance(flight_.stored_from, flight_.surface_from, flight_.released_from);
    if (front_) front_->candidate(flight_.refined_from);
    events_.emit(EventKind::stage_end, flight_.from);
    return;
  }
  const ContactSnapshot end = at_.row.snapshot();
  StageRecord& record = record_.end_stage(stage.name, end, at_.work);
  record.energy = at_.balance(at_.row.stored_energy(), at_.row.glued_surface(), at_.released());
  if (front_ && !stopped) {
    record.refined_end = front_->at_rest(at_.row);
    front_->candidate(record.refined_end);
  }
  events_.emit(EventKind::stage_end, end);
}

RunResult ProgramRunner::run() {
  std::size_t first = 0;
  if (zoomed_) {
    at_.row.start_zoomed(zoomed_->normal, zoomed_->tangential, zoomed_->offset);
    first = zoomed_->stage;
    row_end_ = at_.row.reference_springs();
  }
  const auto& stages = scene_.program->stages;
  for (std::size_t i = first; i < stages.size() && !outcome_.stopped() && !flight_.flying(); ++i) {
    start_stage(stages[i], zoomed_ && i == first);
    follow_stage(stages[i]);
    end_stage(stages[i]);
  }
  result_.work = record_.total_work();
  EnergyBalance energy;
  for (const StageRecord& stage : result_.stages) {
    if (stage.energy) energy += *stage.energy;
  }
  result_.energy = energy;
  outcome_.decide(
      {scene_, *at_.stage, at_.row, at_.line.normal, max_springs_, zero_, watch_, flight_},
      result_);
  result_.jumps.shrink_to_fit();
  if (const auto& peak = watch_.peak()) {
    result_.peak = peak;
    if (front_) result_.refined_peak = front_->peak(*peak);
  }
  return std::move(result_);
}

}  // namespace

RunResult run_program_row(const Scene& scene, const ProgramRowSpec& row,
                          const ObserverList& observers, LargestContact* largest,
                          LastStageStart* last_stage) {
  ProgramRunner runner(scene, row, observers, largest, last_stage);
  RunResult result = runner.run();
  result.springs = row.reference_springs;
  result.accuracy.rows = {row.reference_springs};
  result.accuracy.outer_radius = row.reference_radius;
  return result;
}

}  // namespace mdrsim
