// How a program run stopped, and the status that its stop, its losses and its flight decide.
#pragma once

#include <cstdint>

#include "engine/base/zero_scale.hpp"
#include "engine/program/path_watch.hpp"
#include "engine/program/program_flight.hpp"
#include "engine/program/program_losses.hpp"
#include "engine/program/program_row.hpp"
#include "engine/result/run_result.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

/// Why a program stopped before its last stage's end.
enum class ProgramStop {
  none,
  cannot_hold_normal,      ///< a fixed normal load with nothing to hold it (program_flight.hpp)
  cannot_hold_tangential,  ///< a fixed tangential load with nothing to hold it
  outgrew_row,             ///< the contact needs a spring beyond the row's last
  no_end,                  ///< a stage until separation with nothing on its path to part it
  endless_stick_slip,      ///< a stage took more than kSweepsPerStage events per spring
  max_steps,               ///< stepping reached solver.max_steps
  overflow,                ///< forces, displacements or work left the range of a double
  unending_cascade,        ///< the changes at one parameter value did not settle
};

/// What the outcome reads of the run where it stopped.
struct ProgramEnd {
  const Scene& scene;
  const Stage& stage;  ///< the stage under way
  const ProgramRow& row;
  const AxisMotion& normal;  ///< the stage's normal held value
  std::int64_t max_springs;  ///< where the row ends
  const ZeroScale& zero;
  const PathWatch& watch;
  const Flight& flight;
};

class ProgramOutcome {
 public:
  bool stopped() const { return stop_ != ProgramStop::none; }
  ProgramStop stop() const { return stop_; }
  void stop(ProgramStop why) { stop_ = why; }
  /// A fixed load lost its hold (cannot_hold): the normal one where nothing is in contact
  /// and no machine spring holds it.
  void stop_lost_hold(const ProgramRow& row) {
    stop_ = row.in_contact() == 0 && !row.normal_has_stiffness()
                ? ProgramStop::cannot_hold_normal
                : ProgramStop::cannot_hold_tangential;
  }
  /// The changes at parameter t did not settle.
  void stop_unending(double t) {
    stop_ = ProgramStop::unending_cascade;
    unending_at_ = t;
  }
  /// The cascades that lost the glue or the contact.
  ProgramLosses& losses() { return losses_; }

  /// Writes the status into `r`, with the critical point, its stage, whether the indenter
  /// slides away, and the warning that says why a run stopped early.
  void decide(const ProgramEnd& end, RunResult& r) const;
  /// The warning of a flight that ends the program before its last stage.
  static std::string skipped_stages(const ProgramEnd& end);

 private:
  /// The status where nothing stopped the run early, or a fixed load lost its hold.
  void decide_by_losses(const ProgramEnd& end, RunResult& r) const;

  ProgramStop stop_ = ProgramStop::none;
  double unending_at_ = 0.0;  ///< the parameter of an unending cascade
  ProgramLosses losses_;
};

}  // namespace mdrsim
