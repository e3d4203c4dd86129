// The step of a program row: what change is due at the present stage parameter, and where
// along the stage's line the next one lies. The loop (program_runner.cpp) applies them.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>

#include "detachment/criterion.hpp"
#include "engine/base/bracketed_root.hpp"
#include "engine/model/boundary_let_go.hpp"
#include "engine/program/program_cascade.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/stage_motion.hpp"

namespace mdrsim {

/// The next double above a stage parameter t >= 0: std::nextafter without the library call,
/// which every step asks for.
inline double next_parameter(double t) {
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(t) + 1);
}

/// Guards at the present t, so that nothing flips back at the same parameter value when a
/// located change leaves its condition met only to rounding (or with equality, as the
/// reversible front does).
struct SameParameterGuards {
  std::int64_t glued_from = std::numeric_limits<std::int64_t>::max();    ///< do not let go
  std::int64_t touched_from = std::numeric_limits<std::int64_t>::max();  ///< do not lift
  std::int64_t released_to = 0;  ///< glue again only if let go with a tangential stretch
  bool released_with_stretch = false;
  std::int64_t lifted_to = 0;  ///< do not touch again
};

/// The stage's line at the present parameter t: each axis's held value start + rate t.
struct StepLine {
  double t;
  const AxisMotion& normal;
  const AxisMotion& tangential;
  const SameParameterGuards& guards;
  std::int64_t max_springs;  ///< the row ends here: a change beyond it outgrows the row
  std::int64_t row_end;      ///< the last spring that exists (a zoomed row's N)
};

/// Locates the row's changes. Defined inline: the event loop calls it once per event.
class ChangeLocator {
 public:
  /// `root_iterations` counts the criterion's root searches (RunCounts).
  ChangeLocator(const DetachmentCriterion& criterion, std::int64_t& root_iterations)
      : criterion_(criterion), root_iterations_(&root_iterations) {}

  /// The change due at the present parameter; `outgrew` set (and nothing returned) where it
  /// needs a spring beyond line.max_springs.
  std::optional<Change> due(const ProgramRow& row, const StepLine& line, bool& outgrew);
  /// The first change along the line before t_end, and its parameter.
  std::optional<std::pair<double, Change>> next_change(const ProgramRow& row, const StepLine& line,
                                                       double t_end);
  /// Where the boundary spring lets go at tangential stretch stretch_x [m] (ProgramRow::
  /// boundary_released_stretch).
  /// A reference into the locator's cache, valid until its next call: a LetGo returned by
  /// value would go through the stack on every event.
  const LetGo& boundary_let_go(const ProgramRow& row, double stretch_x);
  /// Whether spring k+1 may glue at tangential displacement u [m] as far as its stretch goes.
  /// A spring not pressed glues at no stretch: yes. A pressed spring sticking under friction
  /// glues keeping its stretch (rebinding), and a glue whose boundary the criterion lets go at
  /// once is none: it glues where some spring of the run that can glue now from k+1 outwards
  /// (pressed, sticking, allowed to glue) holds at its kept stretch with no elongation, so
  /// that the run glues out to its outermost such spring and no further (else glue and let-go
  /// would follow each other without end). The run is scanned once per parameter value.
  bool kept_stretch_holds(const ProgramRow& row, const StepLine& line, double u);
  /// Stepping takes a trial step back: what was cached of it goes too.
  void forget() {
    let_go_cache_.reset();
    run_scan_.reset();
    holdless_.reset();
  }
  /// The loop applied `change` to a row with `in_contact` springs in contact before it: what
  /// kept_stretch_holds knows of the run stays true where the change leaves it so.
  void changed(Change change, std::int64_t in_contact) {
    if (change == Change::glue) return;  // the run glues outwards: both scans still hold
    run_scan_.reset();
    if (change != Change::let_go && change != Change::fall_in && holdless_) {
      // A slip ends the run there, a stick gives the spring a new offset, a touch or a lift
      // changes the springs in contact there: the springs inside it are as they were.
      const std::int64_t spring = change == Change::friction ? friction_event_.spring
                                  : change == Change::touch  ? in_contact + 1
                                                             : in_contact;
      holdless_->checked_to = std::min(holdless_->checked_to, spring - 1);
    } else {
      holdless_.reset();  // a let-go changes k
    }
  }
  /// The friction event the last Change::friction stands for.
  const RowFrictionEvent& friction_event() const { return friction_event_; }
  /// The motion of d and u_x along the line from its present parameter (affine while the
  /// springs stay as they are), as the friction row reads it.
  static LinearMotion motion(const ProgramRow& row, double t, const AxisMotion& normal,
                             const AxisMotion& tangential) {
    const double vd = normal.rate != 0.0 ? row.indentation_per_held() * normal.rate : 0.0;
    return {t, row.indentation(), row.tangential_displacement(), vd,
            (tangential.rate != 0.0 ? row.tangential_per_held() * tangential.rate : 0.0) +
                (vd != 0.0 ? row.tangential_per_indentation() * vd : 0.0)};
  }
  static LinearMotion motion(const ProgramRow& row, const StepLine& line) {
    return motion(row, line.t, line.normal, line.tangential);
  }

 private:
  /// next_change's searches along the line up to `best`, for a row whose boundary or next
  /// spring moves in u_x at rate vu (and d at vd): where pressed spring k+1, sticking with
  /// more stretch than its glue holds, comes to hold as u_x moves back; where the boundary
  /// spring lets go as its elongation and stretch both move. The parameter, or none before
  /// `best`.
  std::optional<double> glue_back(const ProgramRow& row, const StepLine& line, double vu,
                                  double best);
  std::optional<double> let_go_along(const ProgramRow& row, const StepLine& line, double vd,
                                     double vu, double best);

  const DetachmentCriterion& criterion_;
  std::int64_t* root_iterations_;
  struct LetGoCache {
    std::int64_t spring;
    double stretch_x;
    LetGo go;
  };
  std::optional<LetGoCache> let_go_cache_;
  RowFrictionEvent friction_event_{};
  /// kept_stretch_holds: the run scanned at this parameter, u_x and glued count, and the
  /// outermost spring of it that holds (k itself: none).
  struct RunScan {
    double t;
    double u;
    std::int64_t glued;
    std::int64_t holds_to;
  };
  std::optional<RunScan> run_scan_;
  /// kept_stretch_holds: springs k+1..checked_to of the run hold at no stretch they had, and
  /// u_x has moved only away from holding since (each stretch's sign along `direction`, or
  /// u_x still): while they stick, none of them will hold (a convex holding set containing
  /// no stretch is left for good along a ray). So a scan resumes past them.
  struct HoldlessPrefix {
    std::int64_t glued;
    std::int64_t checked_to;
    double u;
    int direction;  ///< +1 / -1: every stretch u - s of the prefix has this sign; 0: u_x still
  };
  std::optional<HoldlessPrefix> holdless_;
  double inverse_of_ = 0.0;  ///< next_change: the d(d)/dt whose inverse is `inverse_`
  double inverse_ = 0.0;
};

inline const LetGo& ChangeLocator::boundary_let_go(const ProgramRow& row, double stretch_x) {
  const double a = row.position(row.glued());
  // The same spring at the same tangential stretch lets go at the same elongation: a step
  // asks twice (what is due, what comes next), and a retract at fixed u_x asks once per spring.
  if (let_go_cache_ && let_go_cache_->spring == row.glued() &&
      let_go_cache_->stretch_x == stretch_x) {
    return let_go_cache_->go;
  }
  const LetGo go = locate_let_go(criterion_, a, stretch_x, std::abs(stretch_x) + row.spacing());
  *root_iterations_ += go.root_iterations;
  require_let_go(go, a);
  let_go_cache_ = {row.glued(), stretch_x, go};
  return let_go_cache_->go;
}

inline bool ChangeLocator::kept_stretch_holds(const ProgramRow& row, const StepLine& line,
                                              double u) {
  const std::int64_t k = row.glued();
  const FrictionRow* friction = row.friction();
  if (!friction || k + 1 > row.in_contact()) return true;
  // Within one scan the run glues outwards: k grows up to the spring found.
  if (run_scan_ && run_scan_->t == line.t && run_scan_->u == u && run_scan_->glued <= k &&
      (k < run_scan_->holds_to || run_scan_->glued == k)) {
    return k < run_scan_->holds_to;
  }
  std::int64_t first = k + 1;
  int direction = 2;  // the stretches' one sign so far (2: no spring yet, 0: mixed or zero)
  if (holdless_ && holdless_->glued == k &&
      (u == holdless_->u ||
       (holdless_->direction != 0 && (u - holdless_->u) * holdless_->direction > 0.0))) {
    first = std::max(k + 1, holdless_->checked_to + 1);
    if (holdless_->checked_to > k) direction = holdless_->direction;
  }
  std::int64_t holds_to = k;
  std::int64_t last = first - 1;
  for (std::int64_t i = first; i <= row.in_contact() && i <= line.row_end && row.can_glue(i); ++i) {
    const double stretch = u - friction->spring(i).offset;
    if (criterion_.margin({0.0, stretch, row.position(i)}) > 0.0) holds_to = i;
    const int sign = stretch > 0.0 ? 1 : (stretch < 0.0 ? -1 : 0);
    if (direction == 2) direction = sign;
    if (sign != direction) direction = 0;
    last = i;
  }
  run_scan_ = RunScan{line.t, u, k, holds_to};
  if (holds_to == k) {
    // None holds: u_x moving along the stretches' one sign takes them further away.
    holdless_ = HoldlessPrefix{k, last, u, direction == 2 ? 0 : direction};
  } else {
    holdless_.reset();
  }
  return k < holds_to;
}

inline std::optional<Change> ChangeLocator::due(const ProgramRow& row, const StepLine& line,
                                                bool& outgrew) {
  const std::int64_t k = row.glued();
  const std::int64_t m = row.in_contact();
  if (m == 0 && !row.normal_has_stiffness() &&
      (row.normal().held > 0.0 || (row.normal().held == 0.0 && line.normal.rate > 0.0)) &&
      row.normal().rest < row.image(1)) {
    return Change::fall_in;  // a compressive load with nothing to hold it: the indenter falls in
  }
  const double d = row.indentation();
  if (k > 0 && k < line.guards.glued_from) {
    const LetGo& go =
        boundary_let_go(row, row.boundary_released_stretch(d, row.tangential_displacement()));
    if (go.kind == LetGo::Kind::now || row.image(k) - d >= go.elongation) return Change::let_go;
  }
  const bool front_glues = row.adhesive() && row.can_glue(k + 1) && k < line.row_end;
  // A glue its criterion would let go at once is none: a pressed spring keeping a stretch
  // beyond what the glue holds stays a friction spring (else glue and let-go would follow
  // each other at the same parameter without end).
  if (front_glues && kept_stretch_holds(row, line, row.tangential_displacement())) {
    const double gap = row.image(k + 1) - d;
    const double limit = row.front_limit(k + 1);
    const bool released_now = k + 1 <= line.guards.released_to;
    if (released_now ? line.guards.released_with_stretch && gap < limit : gap <= limit) {
      if (k + 1 > line.max_springs) {
        outgrew = true;
        return std::nullopt;
      }
      return Change::glue;
    }
  }
  if (!(m == k && front_glues) && m < line.row_end) {
    const double gap = row.image(m + 1) - d;
    // An unglued spring carries no force where it touches or lifts, so nothing at this t
    // can press it back: only rounding could.
    if (m + 1 > line.guards.lifted_to && gap <= 0.0) {
      if (m + 1 > line.max_springs) {
        outgrew = true;
        return std::nullopt;
      }
      return Change::touch;
    }
  }
  if (m > k && m < line.guards.touched_from && row.image(m) - d > 0.0) return Change::lift;
  if (const FrictionRow* friction = row.friction()) {
    // A spring on its limit moving outwards slips at once, a slide that reverses sticks.
    // (Not asked where nothing can: a press's touches.)
    const LinearMotion along = motion(row, line);
    if (!friction->may_change(along)) return std::nullopt;
    if (const auto event = friction->next_event(along, line.t);
        event && event->event.at <= line.t) {
      friction_event_ = *event;
      return Change::friction;
    }
  }
  return std::nullopt;
}

inline std::optional<double> ChangeLocator::glue_back(const ProgramRow& row, const StepLine& line,
                                                      double vu, double best) {
  // Spring k+1 sticks, pressed, with more stretch than a glue there holds, and no spring of
  // its run holds either: it glues where u_x, moving back towards its offset s, brings its
  // margin above zero (the criterion holds at no stretch and its holding states are convex,
  // so the margin rises once on the way to s). An outer spring of the run that comes to hold
  // first glues the run at the next event (docs/friction.md).
  const std::int64_t k = row.glued();
  const double u = row.tangential_displacement();
  const double s = row.friction()->spring(k + 1).offset;
  const double a = row.position(k + 1);
  const double towards = line.t + (s - u) / vu;
  if (!(towards > line.t)) return std::nullopt;
  const auto margin = [&](double t) {
    return criterion_.margin({0.0, u + vu * (t - line.t) - s, a});
  };
  const double soonest = next_parameter(line.t);
  const double hi = std::min(towards, best);
  if (margin(soonest) > 0.0) return soonest;
  if (!(hi > soonest && margin(hi) > 0.0)) return std::nullopt;
  const RootBracket b = bracket_root(margin, soonest, hi);
  *root_iterations_ += b.iterations;
  return b.hi;
}

inline std::optional<double> ChangeLocator::let_go_along(const ProgramRow& row,
                                                         const StepLine& line, double vd, double vu,
                                                         double best) {
  // Both displacements move: root-find the margin along the line. The criterion's holding
  // states are convex in (stretch, u_x) (its contract, criterion.hpp, sampled before the
  // run), so the margin along a line is positive on one interval and one sign change
  // brackets the first let-go.
  const std::int64_t k = row.glued();
  const double d = row.indentation();
  const double u = row.tangential_displacement();
  const double a = row.position(k);
  const double g = row.image(k);
  const auto margin = [&](double t) {
    const double d_t = d + vd * (t - line.t);
    const double stretch = std::max(0.0, g - d_t);
    return criterion_.margin(
        {stretch, row.boundary_released_stretch(d_t, u + vu * (t - line.t)), a});
  };
  const double now = margin(line.t);
  if (now <= 0.0) return line.t;
  double hi = best;
  if (!std::isfinite(hi)) {
    hi = line.t + 1.0;
    for (int i = 0; i < 1100 && margin(hi) > 0.0; ++i) hi = line.t + 2.0 * (hi - line.t);
  }
  if (!(margin(hi) <= 0.0)) return std::nullopt;
  const RootBracket b = bracket_root([&](double t) { return margin(t) / now; }, line.t, hi);
  *root_iterations_ += b.iterations;
  return b.hi;
}

inline std::optional<std::pair<double, Change>> ChangeLocator::next_change(const ProgramRow& row,
                                                                           const StepLine& line,
                                                                           double t_end) {
  const std::int64_t k = row.glued();
  const std::int64_t m = row.in_contact();
  const double d = row.indentation();
  const double u = row.tangential_displacement();
  const double vd = line.normal.rate != 0.0 ? row.indentation_per_held() * line.normal.rate : 0.0;
  double vu = line.tangential.rate != 0.0 ? row.tangential_per_held() * line.tangential.rate : 0.0;
  if (vd != 0.0 && row.friction()) vu += row.tangential_per_indentation() * vd;
  const double soonest = next_parameter(line.t);
  double best = t_end;
  std::optional<Change> change;
  const auto consider = [&](double t, Change c) {
    t = std::max(t, soonest);
    if (t < best || (t == best && !change)) {
      best = t;
      change = c;
    }
  };
  // 1/vd changes only with the springs' response (never under fixed grips): a division per
  // event is a good share of its time.
  if (vd != inverse_of_) {
    inverse_of_ = vd;
    inverse_ = vd != 0.0 ? 1.0 / vd : 0.0;
  }
  const double per_indentation = inverse_;
  const auto when_indentation = [&](double target) {
    return line.t + (target - d) * per_indentation;
  };

  if (m == 0 && !row.normal_has_stiffness() && line.normal.rate > 0.0) {
    consider(-line.normal.start / line.normal.rate, Change::fall_in);
  }
  const bool front_glues = row.adhesive() && row.can_glue(k + 1) && k < line.row_end;
  if (front_glues && vd > 0.0 && kept_stretch_holds(row, line, u)) {
    consider(when_indentation(row.gluing_depth(k + 1)), Change::glue);
  }
  if (!(m == k && front_glues) && vd > 0.0 && m < line.row_end) {
    consider(when_indentation(row.image(m + 1)), Change::touch);
  }
  if (m > k && vd < 0.0) consider(when_indentation(row.image(m)), Change::lift);
  if (front_glues && k < m && vu != 0.0 && !kept_stretch_holds(row, line, u)) {
    if (const auto t = glue_back(row, line, vu, best)) consider(*t, Change::glue);
  }
  if (k > 0) {
    if (!row.boundary_stretch_moves(d, vd, vu)) {
      // Its stretch stays (u_x still): the spring lets go only as d falls to g - e*(stretch).
      // (Broken at rest, it would be due already.)
      if (vd < 0.0) {
        const LetGo& go = boundary_let_go(row, row.boundary_released_stretch(d, u));
        if (go.kind == LetGo::Kind::now) {
          consider(soonest, Change::let_go);
        } else {
          consider(when_indentation(row.image(k) - go.elongation), Change::let_go);
        }
      }
    } else if (const auto t = let_go_along(row, line, vd, vu, best)) {
      consider(*t, Change::let_go);
    }
  }
  if (const FrictionRow* friction = row.friction()) {
    const LinearMotion along{line.t, d, u, vd, vu};
    if (const auto event =
            friction->may_change(along) ? friction->next_event(along, best) : std::nullopt;
        event && (event->event.at < best || !change)) {
      friction_event_ = *event;
      consider(event->event.at, Change::friction);
      // consider() keeps a spring change at the same t: the friction event waits for it.
      if (change != Change::friction) friction_event_ = {};
    }
  }
  if (!change) return std::nullopt;
  return std::make_pair(best, *change);
}

}  // namespace mdrsim
