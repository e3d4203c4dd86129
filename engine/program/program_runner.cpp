// The program loop: per stage, find the next change of the spring row exactly in the stage
// parameter, move there (the equilibrium is affine in between, so the work is exact), apply
// it and every change it makes due at the same parameter (a cascade: a jump when it moves
// more than one spring).
#include "engine/program/program_runner.hpp"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "detachment/let_go.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/events/progress_log.hpp"
#include "engine/model/boundary_let_go.hpp"
#include "engine/model/machine_work.hpp"
#include "engine/program/program_front.hpp"
#include "engine/program/program_losses.hpp"
#include "engine/program/program_record.hpp"
#include "engine/program/program_step.hpp"
#include "engine/program/stage_motion.hpp"
#include "engine/result/status_margin.hpp"

namespace mdrsim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// Spring changes per spring of the row a stage may take: a stage sweeps its row a few times
/// at most, but stick-slip (rebinding under a shear ramp) changes the edge spring once per
/// slip, and a large ramp slips without end.
constexpr std::int64_t kSweepsPerStage = 64;
/// Stepping: the default increment of the stage parameter.
constexpr double kDefaultStageStep = 1e-3;

/// Whether a state's numbers are all within a double (extreme scenes can leave it).
bool finite(const ContactSnapshot& s) {
  return std::isfinite(s.indentation) && std::isfinite(s.normal_force) &&
         std::isfinite(s.tangential_displacement) && std::isfinite(s.tangential_force) &&
         std::isfinite(s.normal_control);
}

class ProgramRunner {
 public:
  ProgramRunner(const Scene& scene, const ProgramRowSpec& spec, const ObserverList& observers,
                LargestContact* largest, LastStageStart* last_stage)
      : stepping_(scene.solver.method == SolverMethod::stepping),
        step_(scene.solver.step.value_or(kDefaultStageStep)),
        scene_(scene),
        criterion_(*scene.criterion),
        row_(*scene.profile, scene.material, spec.reference_radius, spec.reference_springs,
             spec.reference_image, scene.program->rebinding),
        max_springs_(spec.max_springs),
        observers_(observers),
        observe_springs_(observers.wants(EventKind::spring_detached)),
        observe_slips_(observers.wants(EventKind::spring_slipped)),
        largest_(largest),
        last_stage_(last_stage),
        zoomed_(spec.zoomed),
        zero_(spec.zero) {
    row_.record_edge_forces(spec.edge_forces);
    if (scene.friction) row_.enable_friction(*scene.friction);
    // The front located between springs knows no friction: friction rows report their own.
    if (spec.refine && !stepping_ && !scene.friction) front_.emplace(criterion_);
  }

  RunResult run();

 private:
  void start_stage(const Stage& stage);
  [[gnu::noinline]] void run_stage(const Stage& stage);  // keeps next_change inlined in it
  void set_parameter(double t);
  AxisPoint normal_point() const;
  AxisPoint tangential_point() const;
  void advance_to(double t);
  /// Adds the work from the given points (an axis not given did not move) to the present state.
  void add_work(const AxisPoint* normal_from, const AxisPoint* tangential_from);
  StepLine step_line() const { return {t_, normal_, tangential_, guards_, max_springs_, row_end_}; }
  /// The locator's, with outgrowing the row as a stop.
  /// The change due now into `change`; false where none is. (A std::optional<Change> kept
  /// across the loop was stored as a value and a flag and read back as one word: a stalled
  /// load per event, 5 % of a one-row program.)
  bool due(Change& change) {
    bool outgrew = false;
    const auto due = locator_.due(row_, step_line(), outgrew);
    if (outgrew) stop_ = Stop::outgrew;
    if (!due) return false;
    change = *due;
    return true;
  }
  std::optional<std::pair<double, Change>> next_change(double t_end) {
    return locator_.next_change(row_, step_line(), t_end);
  }
  const LetGo& boundary_let_go(double stretch_x) {
    return locator_.boundary_let_go(row_, stretch_x);
  }
  void apply(Change change, Cascade& cascade);
  /// The state a cascade starts from, observed as an equilibrium.
  Cascade begin_cascade();
  /// Applies `first` and every change then due at the same t; stops before the change that
  /// would exceed `limit` changes and returns true if one was still due.
  bool run_changes(std::optional<Change> first, Cascade& cascade, std::int64_t limit);
  void take_step(double t_end);
  /// A press that only glues springs as it reaches them, taken in one pass (below).
  bool press_in_bulk(double t_end);
  /// A tangential ramp whose only changes are slips and sticks, taken event by event without
  /// the rest of the loop (below); stops once result_.counts.events passes `events_until`.
  bool slide_in_bulk(double t_end, std::int64_t events_until);
  void finish_cascade(const Cascade& cascade);
  /// Whether a fixed-load axis holds a force that nothing holds: a tension with no spring in
  /// contact, a tangential force with nothing glued.
  bool normal_cannot_hold() const;
  bool tangential_cannot_hold() const;
  bool cannot_hold() const { return normal_cannot_hold() || tangential_cannot_hold(); }
  /// How a cascade that just ran ends: with the contact lost under a fixed load that nothing
  /// holds any more, in a flight (docs/programs.md "A fixed load that loses the contact").
  JumpEnd flight_of(const Cascade& cascade) const;
  /// A flight: the stage ends at the cascade's critical point, with the work up to it.
  void end_in_flight(const Cascade& cascade, JumpEnd end);
  /// The stages after the one under way, which a flight does not run.
  void warn_skipped_stages();
  /// An equilibrium on the path; `cascade_before`: the state the cascade that ended at `s`
  /// began at, where it did (LastStageStart::lost_after).
  void observe(const ContactSnapshot& s, const ContactSnapshot* cascade_before = nullptr);
  void emit(EventKind kind, const ContactSnapshot& state, std::int64_t spring = 0,
            bool in_cascade = false);
  void finish(RunResult& result);
  StageLine line() const { return {normal_, tangential_}; }
  /// Tells the front what a cascade of one change did to it.
  void track_front(const Cascade& cascade);
  /// The progress line of a long stage, when its interval has passed; asked every 65536
  /// events, out of line, so that the event loop stays tight (a check of its own in the
  /// loop cost it 17 instructions per event, 10 %).
  [[gnu::cold, gnu::noinline]] void log_progress(const Stage& stage);

  bool stepping_;
  double step_;  ///< stepping: the increment of the stage parameter
  const Scene& scene_;
  const DetachmentCriterion& criterion_;
  ProgramRow row_;
  std::int64_t max_springs_;
  const ObserverList& observers_;
  /// Asked once: whether anyone observes single springs (a log observer asks spdlog).
  bool observe_springs_;
  bool observe_slips_;  ///< the same for slip and stick
  LargestContact* largest_;
  LastStageStart* last_stage_;  ///< null where nobody asks
  std::optional<ZoomedStart> zoomed_;
  bool keep_machine_ = false;  ///< a zoomed row's first stage: the machine is set already
  /// The last spring that exists: a zoomed row has none outside its radius (the springs there
  /// have let go, unpressed, by the time its front reaches them: program_zoom.hpp).
  std::int64_t row_end_ = std::numeric_limits<std::int64_t>::max();
  ZeroScale zero_;  ///< below it a force is rounding: no peak, no critical point
  RunResult result_;
  std::optional<ProgramFront> front_;  ///< refining rows only
  ProgressLog progress_;
  std::int64_t next_progress_check_ = 1 << 16;  ///< in result_.counts.events

  // The stage under way: held = start + rate * t on each axis.
  const Stage* stage_ = nullptr;
  double t_ = 0.0;
  AxisMotion normal_;  ///< stage_motion.hpp
  AxisMotion tangential_;
  ProgramRecord record_{result_};  ///< stages, jumps and work; its stage_work is the stage's

  SameParameterGuards guards_;  ///< program_step.hpp
  bool in_cascade_ = false;

  ChangeLocator locator_{criterion_, result_.counts.root_iterations};

  // Path record.
  double largest_force_ = 0.0;
  std::optional<ContactSnapshot> peak_;
  ProgramLosses losses_;  ///< what finish decides the status by
  bool ever_in_contact_ = false;
  enum class Stop {
    none,
    cannot_hold_normal,
    cannot_hold_tangential,
    outgrew,
    no_end,
    endless,
    step_limit,
    overflow,
    unending_cascade
  };
  /// Stepping: what a trial step changes, to take it back.
  struct Saved {
    ProgramRow row;
    AxisWork stage_work;
    double t;
    SameParameterGuards guards;
    RunCounts counts;
  };
  std::vector<Event> pending_;  ///< stepping: the events of the trial step
  bool buffering_ = false;
  /// The last let-gos that began a cascade in this stage, by their stretch (not at rest):
  /// the branch next to a shear-off, for its status margin (status_margin.hpp).
  struct LetGoPoint {
    std::int64_t spring;
    double control;  ///< the held normal value
  };
  std::array<LetGoPoint, 3> let_go_trail_{};
  int let_go_trail_size_ = 0;
  void note_let_go(Cascade& cascade, std::int64_t k, double stretch_x, bool by_shear);
  Stop stop_ = Stop::none;
  double unending_at_ = 0.0;  ///< the parameter of an unending cascade (Stop::unending_cascade)
  bool slid_ = false;         ///< friction could not hold a held F_x: gross sliding
  /// A flight ended the program: the state and the located state the last stage ends at.
  JumpEnd flight_ = JumpEnd::state;
  ContactSnapshot flight_end_;
  std::optional<ContactSnapshot> flight_refined_end_;
};

void ProgramRunner::set_parameter(double t) {
  // An axis that does not move keeps its cached equilibrium; `to` lands exactly on its value.
  const bool until_separation = stage_ && stage_->until_separation;
  const bool lands = t == 1.0 && !until_separation;
  if (normal_.rate != 0.0 || (lands && normal_.end)) {
    row_.set_normal_held(normal_.at(t, until_separation));
  }
  if (tangential_.rate != 0.0 || (lands && tangential_.end)) {
    row_.set_tangential_held(tangential_.at(t, until_separation));
  }
}

AxisPoint ProgramRunner::normal_point() const {
  return {row_.normal_force(),
          driving_point(row_.normal().constraint, row_.normal().held, row_.indentation())};
}

AxisPoint ProgramRunner::tangential_point() const {
  return {row_.tangential_force(),
          driving_point(row_.tangential().constraint, row_.tangential().held,
                        row_.tangential_displacement())};
}

void ProgramRunner::add_work(const AxisPoint* normal_from, const AxisPoint* tangential_from) {
  // Force and driving point are affine in between (the springs stay): the trapezoid is exact.
  if (normal_from) record_.stage_work.normal += trapezoid_work(*normal_from, normal_point());
  if (tangential_from) {
    record_.stage_work.tangential += trapezoid_work(*tangential_from, tangential_point());
  }
}

void ProgramRunner::advance_to(double t) {
  // While the row stays as it is, an axis whose held value does not move stays where it is.
  const bool normal_moves = normal_.rate != 0.0;
  // With friction under a held F_x, u_x follows d too (the sliding springs' mu f_z).
  const bool tangential_moves =
      tangential_.rate != 0.0 ||
      (normal_moves && row_.friction() && !is_fixed_grips(row_.tangential().constraint));
  const AxisPoint n0 = normal_moves ? normal_point() : AxisPoint{};
  const AxisPoint x0 = tangential_moves ? tangential_point() : AxisPoint{};
  // The friction row follows d and u_x along the line; no friction event lies before t.
  std::optional<LinearMotion> along;
  if (row_.friction() && t > t_) along = ChangeLocator::motion(row_, step_line());
  set_parameter(t);
  if (along) record_.stage_work.friction += row_.advance_friction(*along, t);
  add_work(normal_moves ? &n0 : nullptr, tangential_moves ? &x0 : nullptr);
  // A force or displacement beyond a double makes the work of its moving axis so (an axis
  // that does not move keeps its state until a change, which finish_cascade checks).
  if (!std::isfinite(record_.stage_work.normal) || !std::isfinite(record_.stage_work.tangential)) {
    stop_ = Stop::overflow;
  }
  t_ = t;
  guards_ = {};
}

void ProgramRunner::observe(const ContactSnapshot& s, const ContactSnapshot* cascade_before) {
  if (!finite(s)) return;
  largest_force_ = std::max(largest_force_, std::abs(s.normal_force));
  if (s.springs_in_contact > 0 && s.normal_force < -zero_.force &&
      (!peak_ || s.normal_force < peak_->normal_force)) {
    peak_ = s;
  }
  if (s.springs_in_contact > 0) ever_in_contact_ = true;
  // The zoom's conditions through the last stage: nothing pressed, nothing glued anew.
  if (last_stage_ && last_stage_->zoomable && stage_ == &scene_.program->stages.back() &&
      ((row_.in_contact() > 0 && row_.in_contact() != row_.glued()) ||
       row_.glued() > last_stage_->springs)) {
    last_stage_->zoomable = false;
    if (cascade_before) last_stage_->lost_after = *cascade_before;
  }
  if (largest_ && s.springs_in_contact > 0) {
    largest_->most_springs = std::max(largest_->most_springs, s.springs_in_contact);
    if (largest_->springs == 0 || s.indentation > largest_->indentation) {
      largest_->springs = s.springs_in_contact;
      largest_->indentation = s.indentation;
      largest_->glued_edge = row_.glued() == row_.in_contact();
      largest_->normal_constraint = row_.normal().constraint;
      largest_->normal_held = s.normal_control;
    }
  }
}

void ProgramRunner::emit(EventKind kind, const ContactSnapshot& state, std::int64_t spring,
                         bool in_cascade) {
  const Event e{.kind = kind,
                .state = state,
                .spring = spring,
                .in_cascade = in_cascade,
                .stage = stage_ ? std::string_view(stage_->name) : std::string_view()};
  if (buffering_) {
    pending_.push_back(e);
  } else {
    observers_.emit(e);
  }
}

bool ProgramRunner::normal_cannot_hold() const {
  return !row_.normal_has_stiffness() && row_.in_contact() == 0 &&
         (row_.normal().held < 0.0 || (row_.normal().held == 0.0 && normal_.rate < 0.0));
}

bool ProgramRunner::tangential_cannot_hold() const {
  return !row_.tangential_has_stiffness() &&
         (row_.tangential().held != 0.0 || tangential_.rate != 0.0);
}

JumpEnd ProgramRunner::flight_of(const Cascade& cascade) const {
  if (cascade.in_contact > 0 && row_.in_contact() == 0 && normal_cannot_hold()) {
    return JumpEnd::separated;
  }
  if (cascade.glued > 0 && row_.glued() == 0 && tangential_cannot_hold()) return JumpEnd::sliding;
  return JumpEnd::state;
}

void ProgramRunner::apply(Change change, Cascade& cascade) {
  // At one t only a fixed-load axis moves its driving point (the indenter, at constant force);
  // under fixed grips and compliant the driving point is the held value, which stays.
  const bool normal_moves = holds_force(row_.normal().constraint);
  const bool tangential_moves = holds_force(row_.tangential().constraint);
  const AxisPoint n0 = normal_moves ? normal_point() : AxisPoint{};
  const AxisPoint x0 = tangential_moves ? tangential_point() : AxisPoint{};
  const std::int64_t k = row_.glued();
  const std::int64_t m = row_.in_contact();
  bool by_shear = false;
  switch (change) {
    case Change::fall_in:
      row_.edit_normal().rest = row_.image(1);
      break;
    case Change::glue:
      row_.glue_next();
      guards_.glued_from = std::min(guards_.glued_from, k + 1);
      if (observe_springs_) emit(EventKind::spring_glued, row_.snapshot(), k + 1, in_cascade_);
      break;
    case Change::let_go: {
      const double d = row_.indentation();
      const double u = row_.tangential_displacement();
      const double stretch_x = row_.boundary_stretch(d, u);
      // Broken at rest is a let-go `now`: the boundary's let-go is cached for this stretch.
      by_shear = boundary_let_go(stretch_x).kind == LetGo::Kind::now;
      note_let_go(cascade, k, stretch_x, by_shear);
      if (observe_springs_) emit(EventKind::spring_detached, row_.snapshot(), k, in_cascade_);
      record_.stage_work.friction += row_.let_go_boundary(row_.image(k) <= d);
      guards_.released_to = std::max(guards_.released_to, k);
      guards_.released_with_stretch = stretch_x != 0.0;
      break;
    }
    case Change::touch:
      row_.touch_next();
      guards_.touched_from = std::min(guards_.touched_from, m + 1);
      if (observe_springs_) emit(EventKind::spring_touched, row_.snapshot(), m + 1, in_cascade_);
      break;
    case Change::lift:
      if (observe_springs_) emit(EventKind::spring_lifted, row_.snapshot(), m, in_cascade_);
      row_.lift_outer();
      guards_.lifted_to = std::max(guards_.lifted_to, m);
      break;
    case Change::friction: {
      // Each spring slips or sticks a few times at one parameter at most: more is a loop,
      // which run_changes stops (Stop::unending_cascade).
      ++cascade.friction_events;
      const RowFrictionEvent& event = locator_.friction_event();
      row_.apply_friction(event);
      ++result_.counts.events;
      if (observe_slips_ && event.event.kind != FrictionEventKind::limit_kink) {
        emit(event.event.kind == FrictionEventKind::slip ? EventKind::spring_slipped
                                                         : EventKind::spring_stuck,
             row_.snapshot(), event.spring, in_cascade_);
      }
      break;
    }
  }
  add_work(normal_moves ? &n0 : nullptr, tangential_moves ? &x0 : nullptr);
  if (row_.friction()) {  // what the locator keeps of a run that may glue again (rebinding)
    const std::int64_t spring = change == Change::friction ? locator_.friction_event().spring
                                : change == Change::touch  ? m + 1
                                : change == Change::lift   ? m
                                                           : k;
    locator_.changed(change, spring);
  }
  if (change != Change::fall_in && change != Change::friction) {
    ++cascade.changes;
    ++result_.counts.events;
    if (cascade.changes == 1) {
      cascade.first_by_shear = by_shear;
      cascade.first = change;
    }
    if (cascade.changes == 2) cascade.second_by_shear = by_shear;
  }
}

void ProgramRunner::note_let_go(Cascade& cascade, std::int64_t k, double stretch_x, bool by_shear) {
  // Only a stage that lowers the normal held value at a still tangential one peels along one
  // branch of that value; the glue carries one stretch.
  if (!(normal_.rate < 0.0) || tangential_.rate != 0.0 || !row_.one_offset()) return;
  if (cascade.changes == 0 && !by_shear) {
    if (let_go_trail_size_ == 3) {
      let_go_trail_[0] = let_go_trail_[1];
      let_go_trail_[1] = let_go_trail_[2];
      --let_go_trail_size_;
    }
    let_go_trail_[let_go_trail_size_++] = {k, row_.normal().held};
    return;
  }
  // Spring K = k + 1 let go by its stretch and spring k breaks at rest right after it: the
  // row's shear-off, whose branch may fold above a_s within a spacing of spring K.
  if (cascade.changes != 1 || !by_shear || cascade.first != Change::let_go ||
      cascade.first_by_shear || let_go_trail_size_ < 3) {
    return;
  }
  const auto& [outer2, outer, boundary] = let_go_trail_;  // springs K + 2, K + 1, K
  if (boundary.spring != k + 1 || outer.spring != k + 2 || outer2.spring != k + 3) return;
  cascade.fold_above_shear_off = program_fold_above_shear_off(
      criterion_, stretch_x, row_.position(k),
      {row_.position(k + 1), row_.position(k + 2), row_.position(k + 3)},
      {boundary.control, outer.control, outer2.control}, row_.spacing());
}

void ProgramRunner::end_in_flight(const Cascade& cascade, JumpEnd end) {
  // What the cascade did after its critical point is the flight: its springs' stretches
  // (the held force on the last spring alone) and the work at constant force grow with the
  // spring count, and none of it is reported. The event method's first change is at the
  // critical point itself; a step's changes are all past it.
  if (!stepping_) {
    for (const Event& e : pending_) {
      if (!e.in_cascade) observers_.emit(e);
    }
  }
  pending_.clear();
  flight_ = end;
  record_.stage_work = cascade.work_before;
  flight_end_ = cascade.before;
  flight_refined_end_ = cascade.refined_before;
  losses_.record(cascade, row_.glued(), row_.in_contact());
  if (cascade.changes < 2) return;
  JumpRecord& jump = record_.add_jump(cascade, row_.in_contact(), row_.glued());
  jump.end = end;
  jump.refined_critical = cascade.refined_before;
  emit(EventKind::jump, cascade.before);
}

void ProgramRunner::finish_cascade(const Cascade& cascade) {
  if (stop_ == Stop::unending_cascade) return;  // not an equilibrium: nothing is recorded
  if (const JumpEnd end = flight_of(cascade); end != JumpEnd::state) {
    end_in_flight(cascade, end);
    return;
  }
  for (const Event& e : pending_) observers_.emit(e);
  pending_.clear();
  const ContactSnapshot after = row_.snapshot();
  // `before` is within range: advance_to checked the work up to it.
  if (!finite(after) || !std::isfinite(record_.stage_work.normal) ||
      !std::isfinite(record_.stage_work.tangential)) {
    stop_ = Stop::overflow;  // values beyond a double: nothing of it is recorded
    return;
  }
  observe(after, &cascade.before);
  losses_.record(cascade, row_.glued(), row_.in_contact());
  // Springs that carry no force and no glue leaving together (a flat tip at rounding) is no jump.
  const bool idle = cascade.glued == 0 && row_.glued() == 0 &&
                    zero_.zero_force(cascade.before.normal_force) &&
                    zero_.zero_force(after.normal_force);
  if (cascade.changes < 2 || idle) return;
  JumpRecord& jump = record_.add_jump(cascade, row_.in_contact(), row_.glued());
  jump.inward = jump.springs > 0 || (jump.springs == 0 && jump.glued_springs > 0);
  jump.after = after;
  if (front_) {
    jump.refined_critical = cascade.refined_before;
    jump.refined_after = front_->at_rest(row_);
    front_->other_change();
    front_->candidate(jump.refined_critical);
    front_->candidate(jump.refined_after);
  }
  emit(EventKind::jump, after);
}

void ProgramRunner::start_stage(const Stage& stage) {
  stage_ = &stage;
  let_go_trail_size_ = 0;
  record_.start_stage();
  const auto start_axis = [&](const std::optional<StageAxis>& axis, bool normal,
                              AxisMotion& motion) {
    if (axis && !keep_machine_) {
      // A new controller takes its held value from the present state: nothing jumps.
      const AffineConstraint c = axis->controller->constraint();
      const double rest = normal ? row_.indentation() : row_.tangential_displacement();
      const double held = normal ? row_.held_value_of_normal(c) : row_.held_value_of_tangential(c);
      MachineAxis& machine = normal ? row_.edit_normal() : row_.edit_tangential();
      machine = {c, held, rest};
    }
    motion = axis_motion(axis, normal ? row_.normal().held : row_.tangential().held);
  };
  start_axis(stage.normal, true, normal_);
  start_axis(stage.tangential, false, tangential_);
  keep_machine_ = false;
  if (last_stage_ && &stage == &scene_.program->stages.back()) {
    *last_stage_ = {
        .zoomable = stage.until_separation && !scene_.program->rebinding && !scene_.friction &&
                    row_.glued() > 0 && row_.glued() == row_.in_contact() && row_.one_offset(),
        .stage = scene_.program->stages.size() - 1,
        .normal = row_.normal(),
        .tangential = row_.tangential(),
        .offset = row_.glued() > 0 ? row_.boundary_offset() : 0.0,
        .springs = row_.glued(),
        .peak_before = peak_ ? peak_->normal_force : std::numeric_limits<double>::infinity()};
  }
  t_ = 0.0;
  guards_ = {};
  if (front_) front_->stage_started();
}

void ProgramRunner::track_front(const Cascade& cascade) {
  if (!front_ || cascade.changes != 1) return;
  if (cascade.first == Change::glue) {
    front_->glued_one(cascade.before);
  } else if (cascade.first == Change::let_go) {
    front_->let_go_one(t_, cascade.glued, cascade.before);
  } else {
    front_->other_change();
  }
}

Cascade ProgramRunner::begin_cascade() {
  // Built in place: a snapshot assigned into a zeroed Cascade cost 4 % of a one-row program's
  // time (the zeroing, and a copy whose loads waited on the snapshot's stores).
  Cascade cascade{.before = row_.snapshot(),
                  .in_contact = row_.in_contact(),
                  .glued = row_.glued(),
                  .work_before = record_.stage_work,
                  .stage = stage_};
  observe(cascade.before);
  return cascade;
}

bool ProgramRunner::run_changes(std::optional<Change> first, Cascade& cascade, std::int64_t limit) {
  in_cascade_ = false;
  if (first) {
    apply(*first, cascade);
    in_cascade_ = true;
  }
  // Every spring a change makes due at this parameter value goes with it; each spring
  // changes at most twice per value (the guards), so the loop ends.
  const std::int64_t cap = 4 * (max_springs_ + 2);
  Change change{};
  while (due(change)) {
    if (cascade.changes >= limit) return true;
    if (front_ && cascade.changes == 1 && cascade.first == Change::let_go &&
        change == Change::let_go) {
      cascade.refined_before = front_->fold(row_, line(), t_, cascade.before);
    }
    if (cascade.changes > cap || cascade.friction_events > cap) {
      // Rounding at values far from the scene's scales (a push until separation that goes on
      // for ever) can keep one parameter value's changes (or slips and sticks) from settling:
      // stop there.
      stop_ = Stop::unending_cascade;
      unending_at_ = t_;
      return false;
    }
    apply(change, cascade);
    in_cascade_ = true;
  }
  return false;
}

void ProgramRunner::take_step(double t_end) {
  // The paper's increments on the stage parameter: a step that changes more than one spring
  // is taken back and halved, down to max_halvings (SolverOptions).
  double step = step_;
  for (int halvings = 0;; ++halvings) {
    double target = std::min(t_ + step, t_end);
    if (!(target > t_)) target = next_parameter(t_);
    const bool last_try = halvings >= scene_.solver.max_halvings || t_ + 0.5 * step == t_;
    const Saved saved{row_, record_.stage_work, t_, guards_, result_.counts};
    Cascade cascade = begin_cascade();  // its `before` is the last accepted equilibrium
    pending_.clear();
    buffering_ = true;
    advance_to(target);
    const bool more =
        run_changes(std::nullopt, cascade, last_try ? std::numeric_limits<std::int64_t>::max() : 1);
    buffering_ = false;
    if (stop_ == Stop::unending_cascade) return;
    if (more && !last_try) {
      row_ = saved.row;
      record_.stage_work = saved.stage_work;
      t_ = saved.t;
      guards_ = saved.guards;
      result_.counts = saved.counts;
      locator_.forget();
      step *= 0.5;
      ++result_.counts.halvings;
      if (observers_.wants(EventKind::step_halved)) {
        observers_.emit({.kind = EventKind::step_halved,
                         .state = row_.snapshot(),
                         .step = step,
                         .stage = stage_->name});
      }
      continue;
    }
    ++result_.counts.steps;
    if (flight_of(cascade) != JumpEnd::state) {
      // The step went past the critical point into the flight: its events are not kept.
      finish_cascade(cascade);
      return;
    }
    for (const Event& e : pending_) observers_.emit(e);
    pending_.clear();
    if (observers_.wants(EventKind::step_accepted)) {
      observers_.emit({.kind = EventKind::step_accepted,
                       .state = row_.snapshot(),
                       .step = step,
                       .stage = stage_->name});
    }
    finish_cascade(cascade);
    return;
  }
}

bool ProgramRunner::press_in_bulk(double t_end) {
  // Fixed grips pressing at a held u_x, every spring in contact glued, the front gluing each
  // spring as it touches (dgamma_a = 0), no friction: each event is one spring glued, in the
  // order of the images, and nothing else happens (a glued spring pressed further holds: its
  // margin does not fall with its elongation, criterion.hpp, and next_change asks no let-go
  // here either). Every such spring but the last few before the stage's end glues in one pass,
  // the stage's work on them in closed form; the loop then takes the rest one by one, with
  // everything it records. Not where single springs are observed (their events are wanted).
  constexpr std::int64_t kLeftToTheLoop = 3;
  constexpr std::int64_t kWorthIt = 16;
  if (!(normal_.rate > 0.0) || tangential_.rate != 0.0 || observe_springs_ || row_.friction() ||
      !std::isfinite(t_end) || !is_fixed_grips(row_.normal().constraint) ||
      !is_fixed_grips(row_.tangential().constraint) || !row_.adhesive() || !row_.glues_on_touch()) {
    return false;
  }
  const std::int64_t k = row_.glued();
  if (row_.in_contact() != k || !row_.can_glue(k + 1)) return false;
  const double d = row_.indentation();
  const double d_end = normal_.at(t_end, false) * row_.indentation_per_held();
  // Springs whose images rise strictly between d and d_end glue one at a time (a spring whose
  // image does not rise glues with the one before it: a jump, the loop's).
  const std::int64_t limit = std::min(max_springs_, row_end_);
  std::int64_t last = k;
  double image = d;
  while (last < limit) {
    const double next = row_.image(last + 1);
    if (!(next > image) || !(next < d_end)) break;
    image = next;
    ++last;
  }
  last -= kLeftToTheLoop;
  if (last - k < kWorthIt) return false;
  // Where the loop would glue spring `last`: the locator's parameter of its image.
  const double vd = row_.indentation_per_held() * normal_.rate;
  const double t = std::max(t_ + (row_.image(last) - d) * (1.0 / vd), next_parameter(t_));
  advance_to(t);  // the springs glued before: the trapezoid
  if (stop_ != Stop::none) return true;
  record_.stage_work.normal += row_.glue_through(last);
  result_.counts.events += last - k;
  guards_.glued_from = last;
  observe(row_.snapshot());  // the force rose all along: the ends hold the extremes
  if (front_) front_->other_change();
  return true;
}

bool ProgramRunner::slide_in_bulk(double t_end, std::int64_t events_until) {
  // Fixed grips moving u_x at a still normal held value, nothing glued nor able to glue, every
  // spring on the keys (FrictionRow::slides_in_bulk), nobody observing single slips: d stays
  // (the axes are uncoupled), so no spring touches, lifts, glues or lets go, and the only
  // changes are the friction row's own events, which it locates exactly as the loop does
  // (FrictionRow::next_event, in the same order). Each is applied where the loop would apply
  // it, with the same advance and work, without looking for changes that cannot come, nor
  // snapshots of equilibria whose normal state does not change (observed once, at the end).
  const FrictionRow* friction = row_.friction();
  if (stepping_ || observe_slips_ || friction == nullptr || normal_.rate != 0.0 ||
      tangential_.rate == 0.0 || !is_fixed_grips(row_.tangential().constraint) ||
      row_.glued() > 0 || !friction->slides_in_bulk()) {
    return false;
  }
  const std::int64_t m = row_.in_contact();
  const double d = row_.indentation();
  // Nothing else due now (a spring to touch, lift or glue is the loop's), and nothing can be.
  if (m == 0 || (row_.adhesive() && row_.can_glue(1)) || row_.image(m) - d > 0.0 ||
      (m < row_end_ && row_.image(m + 1) - d <= 0.0)) {
    return false;
  }
  const std::int64_t cap = 4 * (max_springs_ + 2);
  std::int64_t at_this_t = 0;
  bool applied = false;
  while (result_.counts.events <= events_until) {
    const LinearMotion along = ChangeLocator::motion(row_, step_line());
    const auto event = friction->next_event(along, t_end);
    if (!event) break;
    double t = t_;
    if (event->event.at > t_) {
      t = std::max(event->event.at, next_parameter(t_));
      if (!(t < t_end)) break;  // the stage's end is the loop's
      advance_to(t);
      if (stop_ != Stop::none) return true;
      at_this_t = 0;
    }
    if (++at_this_t > cap) {
      // Rounding that keeps one parameter value's slips and sticks from settling (run_changes).
      stop_ = Stop::unending_cascade;
      unending_at_ = t_;
      return true;
    }
    row_.apply_friction(*event);
    ++result_.counts.events;
    applied = true;
  }
  if (!applied) return false;
  locator_.forget();
  observe(row_.snapshot());
  return true;
}

void ProgramRunner::log_progress(const Stage& stage) {
  next_progress_check_ = result_.counts.events + (1 << 16);
  if (!progress_.interval_passed()) return;
  spdlog::info(
      "program running: stage '{}' at parameter {:.4g}, {} springs in contact, {} events, {} "
      "steps",
      stage.name, t_, row_.in_contact(), result_.counts.events, result_.counts.steps);
}

void ProgramRunner::run_stage(const Stage& stage) {
  start_stage(stage);
  const double t_end = stage.until_separation ? kInfinity : 1.0;
  if (stage.until_separation && row_.in_contact() == 0) {
    result_.warnings.push_back(fmt::format(
        "stage '{}' runs until separation but starts with no spring in contact: it ends at once",
        stage.name));
  } else {
    const bool buffer_cascades = observe_springs_ && (holds_force(row_.normal().constraint) ||
                                                      holds_force(row_.tangential().constraint));
    // The sticks a ramp's reversal makes due at its start are a friction row's own as well.
    slide_in_bulk(t_end, next_progress_check_);
    if (stop_ == Stop::none) {
      Cascade cascade = begin_cascade();
      buffering_ = buffer_cascades;
      run_changes(std::nullopt, cascade, std::numeric_limits<std::int64_t>::max());
      buffering_ = false;
      finish_cascade(cascade);
      track_front(cascade);
    }
    // A contact that slides by stick-slip (rebinding under a shear ramp) changes its edge
    // spring once per slip, forever until separation and without bound under a large ramp:
    // the stage stops after this many changes.
    const std::int64_t event_limit = result_.counts.events + kSweepsPerStage * (max_springs_ + 1);
    // The events at which to look at the limit or the progress line: one compare per change.
    std::int64_t look_at = std::min(event_limit, next_progress_check_);
    while (stop_ == Stop::none && flight_ == JumpEnd::state) {
      if (stage.until_separation && row_.in_contact() == 0) break;
      if (result_.counts.events > look_at) [[unlikely]] {
        if (result_.counts.events > event_limit) {
          stop_ = Stop::endless;
          break;
        }
        log_progress(stage);
        look_at = std::min(event_limit, next_progress_check_);
      }
      if (cannot_hold()) {
        stop_ = row_.in_contact() == 0 && !row_.normal_has_stiffness()
                    ? Stop::cannot_hold_normal
                    : Stop::cannot_hold_tangential;
        break;
      }
      if (stepping_) {
        if (t_ >= t_end) break;
        if (result_.counts.steps >= scene_.solver.max_steps) {
          stop_ = Stop::step_limit;
          break;
        }
        take_step(t_end);
        if (flight_ != JumpEnd::state) break;
        continue;
      }
      if (press_in_bulk(t_end)) continue;
      if (row_.friction() && slide_in_bulk(t_end, look_at)) continue;  // no call without friction
      const auto next = next_change(t_end);
      if (!next) {
        if (std::isfinite(t_end)) {
          advance_to(t_end);
          // What the end's exact held value makes due there (spring N reached at a_max).
          Cascade cascade = begin_cascade();
          run_changes(std::nullopt, cascade, std::numeric_limits<std::int64_t>::max());
          finish_cascade(cascade);
          track_front(cascade);
        } else {
          stop_ = Stop::no_end;
        }
        break;
      }
      advance_to(next->first);
      if (stop_ == Stop::overflow) break;
      Cascade cascade = begin_cascade();
      // Under a fixed load a cascade may end in a flight, whose springs are not reported.
      buffering_ = buffer_cascades;
      run_changes(next->second, cascade, std::numeric_limits<std::int64_t>::max());
      buffering_ = false;
      finish_cascade(cascade);
      if (flight_ != JumpEnd::state) break;
      track_front(cascade);
    }
  }
  // The stage's numbers left the range of a double, or its changes did not settle.
  if (stop_ == Stop::overflow || stop_ == Stop::unending_cascade) return;
  if (flight_ != JumpEnd::state) {
    // The stop the loop's next turn would have found (finish() reads the status from it).
    if (stop_ == Stop::none && !(stage.until_separation && row_.in_contact() == 0)) {
      stop_ = row_.in_contact() == 0 && !row_.normal_has_stiffness() ? Stop::cannot_hold_normal
                                                                     : Stop::cannot_hold_tangential;
    }
    // The stage ends where the flight began: its critical point.
    record_.end_stage(stage.name, flight_end_).refined_end = flight_refined_end_;
    if (front_) front_->candidate(flight_refined_end_);
    emit(EventKind::stage_end, flight_end_);
    return;
  }
  const ContactSnapshot end = row_.snapshot();
  StageRecord& record = record_.end_stage(stage.name, end);
  if (front_ && stop_ == Stop::none) {
    record.refined_end = front_->at_rest(row_);
    front_->candidate(record.refined_end);
  }
  emit(EventKind::stage_end, end);
}

void ProgramRunner::finish(RunResult& r) {
  r.work = record_.total_work();
  const bool lost = row_.in_contact() == 0 && ever_in_contact_;
  const auto decide_loss = [&](const Cascade& c) {
    ProgramLosses::decide(c, zero_, largest_force_, r);
  };
  const auto& glue_loss = losses_.last_glue_loss();
  const auto& contact_loss = losses_.last_contact_loss();
  const auto deciding_loss = [&]() -> const Cascade& { return losses_.deciding(); };
  switch (stop_) {
    case Stop::outgrew:
      r.status = RunStatus::step_limit;
      r.warnings.push_back(fmt::format(
          "stage '{}': the contact outgrew the row of {} springs (radius {:.6g} m): the program "
          "stops here",
          stage_->name, max_springs_, row_.position(max_springs_)));
      return;
    case Stop::no_end:
      r.status = RunStatus::step_limit;
      r.warnings.push_back(fmt::format(
          "stage '{}' runs until separation, but nothing on its path can part the contact ({} "
          "springs in contact): the program stops here",
          stage_->name, row_.in_contact()));
      return;
    case Stop::step_limit:
      r.status = RunStatus::step_limit;
      r.warnings.push_back(fmt::format(
          "the stepping method reached solver.max_steps = {} in stage '{}' before the program's "
          "end: there is no critical point",
          scene_.solver.max_steps, stage_->name));
      return;
    case Stop::overflow:
      r.status = RunStatus::step_limit;
      r.critical.reset();
      r.warnings.push_back(fmt::format(
          "stage '{}': the program's forces, displacements or work left the range of a double "
          "(the scene's values are too extreme together): it stops there, and only the stages "
          "before it are reported",
          stage_->name));
      return;
    case Stop::unending_cascade:
      r.status = RunStatus::step_limit;
      r.critical.reset();
      r.warnings.push_back(fmt::format(
          "stage '{}': at parameter {:.6g} the spring row kept changing without settling "
          "(rounding of values far beyond the scene's scales, {} springs in contact): it stops "
          "there, and only the stages before it are reported",
          stage_->name, unending_at_, row_.in_contact()));
      return;
    case Stop::endless:
      r.status = RunStatus::step_limit;
      r.warnings.push_back(fmt::format(
          "stage '{}' changed its spring row more than {} times per spring ({} changes; {} "
          "springs in contact, {} glued): the contact slides by stick-slip without end; the "
          "program stops here",
          stage_->name, kSweepsPerStage, result_.counts.events, row_.in_contact(), row_.glued()));
      return;
    case Stop::cannot_hold_tangential:
      if (scene_.friction && row_.in_contact() > 0) {
        // Every spring in contact slides at its limit and the held F_x asks for more: gross
        // sliding, at the last equilibrium (docs/friction.md "Statuses"): where the last
        // spring began to slide, or, where a glue's jump ended in the slide, before that jump.
        r.status = RunStatus::shear_off;
        if (flight_ == JumpEnd::sliding) {
          r.critical = flight_end_;
          r.refined_critical = flight_refined_end_;
        } else {
          r.critical = row_.snapshot();
        }
        slid_ = true;
        r.warnings.push_back(fmt::format(
            "stage '{}': friction can no longer hold F_x = {:.6g} N ({} springs in contact, all "
            "sliding): the contact slides away and the program ends here",
            stage_->name, row_.tangential().held, row_.in_contact()));
        return;
      }
      if (glue_loss) {
        decide_loss(*glue_loss);
        if (glue_loss->changes < 2) r.status = RunStatus::shear_off;
      } else {
        r.status = RunStatus::no_instability;
        r.warnings.push_back(fmt::format(
            "stage '{}': fixed-load holds F_x = {:.6g} N with no glued spring: the program ends "
            "here",
            stage_->name, row_.tangential().held));
      }
      return;
    case Stop::cannot_hold_normal:
      if (!contact_loss) {
        r.status = RunStatus::no_instability;
        r.warnings.push_back(fmt::format(
            "stage '{}': a fixed load pulls (F = {:.6g} N, moving towards {:.6g} N) with no "
            "spring in contact, so nothing holds it: the program ends here",
            stage_->name, row_.normal().held, normal_.start + normal_.rate));
        return;
      }
      decide_loss(deciding_loss());
      return;
    case Stop::none:
      break;
  }
  if (lost && contact_loss) {
    decide_loss(deciding_loss());
    return;
  }
  r.status = RunStatus::completed;
  if (contact_loss) {
    r.critical = contact_loss->before;
    r.refined_critical = contact_loss->refined_before;
  }
}

void ProgramRunner::warn_skipped_stages() {
  const auto& stages = scene_.program->stages;
  std::string skipped;
  for (auto it = stages.begin() + (stage_ - stages.data()) + 1; it != stages.end(); ++it) {
    skipped += fmt::format("{}'{}'", skipped.empty() ? "" : ", ", it->name);
  }

  const bool separated = flight_ == JumpEnd::separated;
  result_.warnings.push_back(fmt::format(
      "stage '{}': the {} fixed load (F{} = {:.6g} N) lost what held it and the indenter {}: "
      "the program ends at its critical point; stages not run: {}",
      stage_->name, separated ? "normal" : "tangential", separated ? "" : "x",
      separated ? row_.normal().held : row_.tangential().held,
      separated ? "separates" : "slides away", skipped));
}

RunResult ProgramRunner::run() {
  std::size_t first = 0;
  if (zoomed_) {
    // Every spring glued with the one offset (at zero stretch: the tangential machine holds
    // u_x there while they glue), then the machine as the stage started on the full row.
    row_.edit_tangential() = {{1.0, 0.0}, zoomed_->offset, zoomed_->offset};
    row_.glue_first(row_.reference_springs());
    row_.edit_normal() = zoomed_->normal;
    row_.edit_tangential() = zoomed_->tangential;
    first = zoomed_->stage;
    keep_machine_ = true;
    row_end_ = row_.reference_springs();
  }
  const auto& stages = scene_.program->stages;
  for (std::size_t i = first; i < stages.size(); ++i) {
    run_stage(stages[i]);
    if (stop_ != Stop::none || flight_ != JumpEnd::state) break;
  }
  if (flight_ != JumpEnd::state && stage_ != &scene_.program->stages.back()) {
    warn_skipped_stages();
  }
  finish(result_);
  result_.sliding = flight_ == JumpEnd::sliding || slid_;
  // The stage of the critical point, for the closing events (finish picks it from a loss).
  for (const auto* loss : {&losses_.last_contact_loss(), &losses_.last_glue_loss()}) {
    if (*loss && result_.critical &&
        (*loss)->before.springs_in_contact == result_.critical->springs_in_contact &&
        (*loss)->before.indentation == result_.critical->indentation &&
        (*loss)->before.tangential_displacement == result_.critical->tangential_displacement) {
      result_.critical_stage = (*loss)->stage->name;
    }
  }
  result_.jumps.shrink_to_fit();
  if (peak_) {
    result_.peak = peak_;
    if (front_) result_.refined_peak = front_->peak(*peak_);
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
