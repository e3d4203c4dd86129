// The limits a program row's loop looks at as its events add up, and when it says how far it
// is: one compare per change in the loop, as Boost.Odeint's max_step_checker is one call.
#pragma once

#include <algorithm>
#include <cstdint>

#include "engine/events/progress_log.hpp"

namespace mdrsim {

/// Events per spring of the row a stage may take: a stage sweeps its row a few times at most,
/// but stick-slip (rebinding under a shear ramp) changes the edge spring once per slip, and a
/// large ramp slips without end.
inline constexpr std::int64_t kSweepsPerStage = 64;

class EventLimits {
 public:
  /// `row_springs`: the springs the row may use (ProgramRowSpec::max_springs).
  explicit EventLimits(std::int64_t row_springs)
      : stage_events_(kSweepsPerStage * (row_springs + 1)) {}

  /// The events past which the loop looks before a stage's count starts: the progress line's.
  std::int64_t progress_at() const { return next_progress_; }
  /// The stage under way counts its events from `events`.
  void start_stage(std::int64_t events) {
    stage_limit_ = events + stage_events_;
    look_at_ = std::min(stage_limit_, next_progress_);
  }
  /// The loop looks once its events pass this.
  std::int64_t look_at() const { return look_at_; }
  /// Looked at: whether the stage took too many events.
  bool stage_passed(std::int64_t events) const { return events > stage_limit_; }
  /// Looked at, within the limit: whether the progress line is due (its interval passed).
  /// Asked every 65536 events, out of the loop's way.
  bool progress_due(std::int64_t events) {
    next_progress_ = events + (1 << 16);
    look_at_ = std::min(stage_limit_, next_progress_);
    return progress_.interval_passed();
  }

 private:
  std::int64_t stage_events_;
  std::int64_t stage_limit_ = 0;
  std::int64_t next_progress_ = 1 << 16;
  std::int64_t look_at_ = 0;
  ProgressLog progress_;
};

}  // namespace mdrsim
