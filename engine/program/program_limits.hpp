// The limits a program row's loop looks at as its events add up (solver.max_events and
// solver.max_events_per_spring), and when it says how far it is: one compare per change in
// the loop, as Boost.Odeint's max_step_checker is one call.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>

#include "engine/events/progress_log.hpp"
#include "engine/result/stop_reason.hpp"
#include "engine/scene/scene.hpp"

namespace mdrsim {

class EventLimits {
 public:
  /// `row_springs`: the springs the row may use (ProgramRowSpec::max_springs).
  EventLimits(const SolverOptions& solver, std::int64_t row_springs)
      : stage_events_(solver.max_events_per_spring * (row_springs + 1)),
        run_limit_(solver.max_events - 1) {}

  /// The events past which the loop looks before a stage's count starts.
  std::int64_t before_stage() const { return std::min(run_limit_, next_progress_); }
  /// The stage under way counts its events from `events`.
  void start_stage(std::int64_t events) {
    stage_limit_ = events + stage_events_;
    look_at_ = std::min(stage_limit_, before_stage());
  }
  /// The loop looks once its events pass this.
  std::int64_t look_at() const { return look_at_; }
  /// Looked at: the limit the events met, if any (the stage's first).
  std::optional<StopReason> passed(std::int64_t events) const {
    if (events > stage_limit_) return StopReason::max_events_per_spring;
    if (events > run_limit_) return StopReason::max_events;
    return std::nullopt;
  }
  /// Looked at, within the limits: whether the progress line is due (its interval passed).
  /// Asked every 65536 events, out of the loop's way.
  bool progress_due(std::int64_t events) {
    next_progress_ = events + (1 << 16);
    look_at_ = std::min(stage_limit_, before_stage());
    return progress_.interval_passed();
  }

 private:
  std::int64_t stage_events_;
  std::int64_t run_limit_;  ///< more events than this meet solver.max_events
  std::int64_t stage_limit_ = 0;
  std::int64_t next_progress_ = 1 << 16;
  std::int64_t look_at_ = 0;
  ProgressLog progress_;
};

}  // namespace mdrsim
