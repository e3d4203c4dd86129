// How a program run stopped, and the status that its stop, its losses and its flight decide.
#pragma once

#include <cstdint>
#include <string>

#include "engine/base/zero_scale.hpp"
#include "engine/program/path_watch.hpp"
#include "engine/program/program_flight.hpp"
#include "engine/program/program_losses.hpp"
#include "engine/program/program_row.hpp"
#include "engine/result/run_result.hpp"
#include "engine/result/stop_reason.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

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
  bool stopped() const { return stop_ != Stop::none; }
  /// Whether the run stopped at a limit, for this reason.
  bool stopped_by(StopReason why) const { return stop_ == Stop::limit && limit_ == why; }
  void stop(StopReason why) {
    stop_ = Stop::limit;
    limit_ = why;
  }
  /// The changes at parameter t did not settle.
  void stop_unending(double t) {
    stop(StopReason::unending_cascade);
    unending_at_ = t;
  }
  /// A fixed load lost its hold (cannot_hold): the normal one where nothing is in contact
  /// and no machine spring holds it.
  void stop_lost_hold(const ProgramRow& row) {
    stop_ = row.in_contact() == 0 && !row.normal_has_stiffness() ? Stop::cannot_hold_normal
                                                                 : Stop::cannot_hold_tangential;
  }
  /// The cascades that lost the glue or the contact.
  ProgramLosses& losses() { return losses_; }

  /// Writes the status into `r`, with the critical point, its stage, whether the indenter
  /// slides away, and the warning that says why a run stopped early.
  void decide(const ProgramEnd& end, RunResult& r) const;
  /// The warning of a flight that ends the program before its last stage.
  static std::string skipped_stages(const ProgramEnd& end);

 private:
  /// Why a program stopped before its last stage's end: a fixed load with nothing to hold it
  /// (program_flight.hpp), or a limit (limit_).
  enum class Stop { none, cannot_hold_normal, cannot_hold_tangential, limit };

  /// The warning of a stop at a limit.
  std::string limit_warning(const ProgramEnd& end, const RunResult& r) const;
  /// The status where nothing stopped the run early, or a fixed load lost its hold.
  void decide_by_losses(const ProgramEnd& end, RunResult& r) const;

  Stop stop_ = Stop::none;
  StopReason limit_ = StopReason::overflow;
  double unending_at_ = 0.0;  ///< the parameter of an unending cascade
  ProgramLosses losses_;
};

}  // namespace mdrsim
