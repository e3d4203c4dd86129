// The shorthand's path as a program's three stages (docs/programs.md "The shorthand as a program"):
// the work of each stage and the jumps of the pull-off, recorded as the pull-off loop runs.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "controllers/controller.hpp"
#include "engine/model/contact.hpp"
#include "engine/pull_off/pull_off_method.hpp"
#include "engine/result/program_records.hpp"

namespace mdrsim {

class ShorthandPath {
 public:
  /// The controllers' constraints: compliant drives through a spring, so that its driving
  /// point is the held value; fixed load moves the indenter at constant force.
  ShorthandPath(const AffineConstraint& normal, const AffineConstraint& tangential);

  /// Stage `preload`: the row pressed in at fixed grips to the preload depth, each spring
  /// touching at d = g_i: the work E* dx sum (d_p - g_i)^2, exactly.
  void preload(const Contact& contact);
  /// Stage `tangential`: u_x ramped from 0 with the springs as they are, F_x = K u_x: the work
  /// F_x u_x / 2, plus F_x^2 / (2 k) through a compliant machine of stiffness k [N/m].
  void tangential(const Contact& contact, std::optional<double> machine_stiffness);
  /// One advance of the pull-off method, with the contact as it left it; `equilibrium`: its
  /// equilibrium_before is one (not the state a shear broke at application). O(1): states are
  /// kept, and turned into snapshots only for the jumps and the stage's end.
  void advanced(const Contact& contact, const AdvanceOutcome& out, bool equilibrium);
  /// Closes the pull-off stage and hands over the records; returns how it ended. After a
  /// flight the stage ends at the last equilibrium, with the work up to it.
  JumpEnd finish(const Contact& contact, std::vector<StageRecord>& stages,
                 std::vector<JumpRecord>& jumps, std::optional<AxisWork>& work);

 private:
  /// The snapshot of a state; with no spring left, the last indentation at zero force.
  ContactSnapshot snapshot(const Contact& contact, const Contact::State& state) const;
  void add_work(const Contact& contact, const Contact::State& to);
  /// Adds the work of the states held back, in the order they came.
  void add_held_work(const Contact& contact);
  void close_cascade(const Contact& contact);

  AffineConstraint normal_;
  AffineConstraint tangential_;
  bool tangential_fixed_load_;  ///< u_x moves at constant F_x as springs let go
  /// Under a fixed load the states after let-gos at one held force wait for their work: a
  /// flight's never counts, as the stage ends at the last equilibrium, and most cascades there
  /// are flights. They are the first one and those the row reaches from it by letting go of one
  /// boundary spring after another (last_ is the last), so they are kept as the first and their
  /// count, and made again by those let-gos where their work counts after all.
  bool holds_normal_force_;
  Contact::State held_first_{};
  std::int64_t held_count_ = 0;  ///< the states held back: held_first_ to last_
  std::vector<StageRecord> stages_;
  std::vector<JumpRecord> jumps_;
  AxisWork pull_off_work_;
  AxisWork work_at_equilibrium_;          ///< the pull-off's work up to the last equilibrium
  double tangential_displacement_ = 0.0;  ///< u_x at the last state with springs [m]
  double force_ = 0.0;                    ///< at the last state of the path [N]
  double driving_ = 0.0;  ///< the driving point there: d, or the held value through a spring
  double last_indentation_ = 0.0;  ///< of the last state with springs [m]
  Contact::State last_{};          ///< the state after the last advance

  /// The let-gos since the last equilibrium: that equilibrium, the springs and the shear.
  struct Cascade {
    Contact::State critical;
    std::int64_t springs = 0;
    bool by_shear = false;
  };
  std::optional<Cascade> cascade_;
};

}  // namespace mdrsim
