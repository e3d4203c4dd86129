// Where a program row's glued front sits between two springs, and the row's states there: what
// makes a program's reported states smooth in the spacing, so that Richardson can extrapolate.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "detachment/criterion.hpp"
#include "engine/model/contact_snapshot.hpp"
#include "engine/program/program_cascade.hpp"
#include "engine/program/program_row.hpp"
#include "engine/program/stage_motion.hpp"

namespace mdrsim {

/// The line of a stage: the held value of each axis is start + rate t (stage_motion.hpp).
struct StageLine {
  AxisMotion normal;
  AxisMotion tangential;
  /// The program's clock over the stage: its start time [s] and seconds per unit of t (0 for
  /// an untimed program).
  AxisMotion clock;
  /// Puts `row`'s held values and time at parameter t (inside the stage: start + rate t).
  void place(ProgramRow& row, double t) const;
};

/// A row's glued front only ever sits on a spring, so every state it reports jumps by one
/// spring as the spacing changes: a sawtooth of O(dx) that no extrapolation removes. The row's
/// states with k - 1, k and k + 1 glued springs at the same parameter lie on a smooth branch,
/// and the front's margin crosses zero between two of them: quadratic interpolation of the
/// branch there leaves a smooth O(dx) error. The front's fraction beyond spring k (its phase)
/// is read off the margin where the front is moving (an advancing front: the gap of the next
/// spring against its gluing limit; a receding one: the criterion's margin at the boundary),
/// and kept where it is pinned: 0 after a spring glued alone, 1 after one let go alone.
///
/// Declines (returns nothing) where the branch is not that simple: springs pressed outside the
/// glued ones (a second front), fewer than two glued springs, a pinned front whose phase is
/// not known (since a jump that left it pinned), a cascade that a spring broken at rest starts
/// (a shear-off, not a fold).
class ProgramFront {
 public:
  explicit ProgramFront(const DetachmentCriterion& criterion) : criterion_(&criterion) {}

  void stage_started() { other_change(); }
  /// Spring k glued alone at t from the equilibrium `before` (k - 1 glued).
  void glued_one(double t, std::int64_t k, const ContactSnapshot& before) {
    phase_ = 0.0;
    previous_single_ = PreviousSingle{t, k, before, false};
    branch_state(false, before);
  }
  /// Spring k let go alone at t from the equilibrium `before`.
  void let_go_one(double t, std::int64_t k, const ContactSnapshot& before) {
    phase_ = 1.0;
    previous_single_ = PreviousSingle{t, k, before, true};
    branch_state(true, before);
  }
  /// A change that leaves the glued front (a touch, a lift, a fall-in) or a jump ends a run
  /// of single changes.
  void other_change() {
    previous_single_.reset();
    branch_size_ = 0;
  }
  /// What a cascade of one change at t did to the front.
  void track(const Cascade& cascade, double t) {
    if (cascade.changes != 1) return;
    if (cascade.first == Change::glue) {
      glued_one(t, cascade.glued + 1, cascade.before);
    } else if (cascade.first == Change::let_go) {
      let_go_one(t, cascade.glued, cascade.before);
    } else {
      other_change();
    }
  }

  /// A state located between springs (a stage end, a jump's): a candidate for the peak.
  void candidate(const std::optional<ContactSnapshot>& state);
  /// The most tensile equilibrium between springs: the lowest of the located states and of
  /// the vertices of the parabolas through three successive single changes around a lowest
  /// one (as the shorthand's peak). Nothing unless it lies within two edge springs' forces of
  /// the row's own most tensile equilibrium `plain` (else the peak is elsewhere: at the onset
  /// of a let-go after a pinned phase, say).
  std::optional<ContactSnapshot> peak(const ContactSnapshot& plain) const;

  /// The state of `row`, at rest at this parameter, with its front between springs; sets the
  /// phase where the front is moving. Tries changes on `row` and puts it back exactly.
  std::optional<ContactSnapshot> at_rest(ProgramRow& row);
  /// at_rest where every spring in contact is pressed, none glued.
  static std::optional<ContactSnapshot> pressed_at_rest(ProgramRow& row);

  /// The fold of a run of single let-gos: spring k let go at t from `before`, `row` is the
  /// row after it (k - 1 glued, still at t) and its boundary is due too. The parabola
  /// through the let-go parameters of springs k + 1, k and k - 1 (the last root-found behind
  /// t along the stage's line) locates the fold between springs, and the three let-go
  /// equilibria are interpolated there.
  std::optional<ContactSnapshot> fold(ProgramRow& row, const StageLine& line, double t,
                                      const ContactSnapshot& before);
  /// The fold of a run of single glues, where the advancing front jumps in: spring k glued at
  /// t from `before`, `row` is the row after it (k glued, still at t) and spring k + 1 is due
  /// too. The gluing parameter of spring n along the advancing branch has its largest value
  /// there; the parabola through those of springs k - 1, k and k + 1 (the last root-found
  /// behind t along the stage's line) locates it between springs, and the three equilibria
  /// before those glues are interpolated there.
  std::optional<ContactSnapshot> advancing_fold(ProgramRow& row, const StageLine& line, double t,
                                                const ContactSnapshot& before);
  /// The stage parameter of the last fold that fold() or advancing_fold() located.
  double fold_parameter() const { return fold_parameter_; }
  /// at_rest of `row` moved along `line` to parameter t (its springs as they are), where the
  /// front's phase is found there; the kept phase stays as it was. A jump's landing state at
  /// its located fold: at the row's own jump parameter it carries the row's O(dx^2) sawtooth of
  /// that parameter, which no extrapolation removes.
  std::optional<ContactSnapshot> at_rest_at(ProgramRow& row, const StageLine& line, double t);

 private:
  /// The criterion's margin at the boundary spring of `row` (> 0: it holds).
  double let_go_margin(const ProgramRow& row) const;
  /// The equilibrium before a single change, on the branch of one kind of change.
  void branch_state(bool let_go, const ContactSnapshot& before);

  /// The last single change of a run: spring `spring` glued or let go at t from `before`.
  struct PreviousSingle {
    double t;
    std::int64_t spring;
    ContactSnapshot before;
    bool let_go;
  };
  const DetachmentCriterion* criterion_;
  std::optional<double> phase_;
  std::optional<PreviousSingle> previous_single_;
  double fold_parameter_ = 0.0;
  std::array<ContactSnapshot, 3> branch_{};
  int branch_size_ = 0;
  bool branch_let_go_ = false;
  std::optional<ContactSnapshot> peak_;
};

}  // namespace mdrsim
