// --trajectory-stride: every K-th ordinary row of the trajectory, and every row that matters.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "engine/events/observer.hpp"

namespace mdrsim::cli {

/// Passes to `inner` the 1st, (K+1)-th, (2K+1)-th, ... ordinary event (a spring that
/// detaches, glues, touches or lifts, a step), and always: the events of special kinds (the
/// preload, the tangential load, a stage's end, a jump, the critical state, the end), the
/// first and the last row of a cascade (the row before the first in_cascade row, the last
/// in_cascade row) and the run's last row. Stride 1 passes everything.
class TrajectoryStride final : public Observer {
 public:
  TrajectoryStride(Observer& inner, std::int64_t stride);
  void on_event(const Event& event) override;
  bool wants(EventKind kind) const override { return inner_->wants(kind); }
  /// Passes the held row on, as the run's last one (also done at the `finished` event).
  void finish();

 private:
  Observer* inner_;
  std::int64_t stride_;
  std::int64_t ordinary_ = 0;  ///< ordinary events seen
  bool previous_in_cascade_ = false;
  std::optional<Event> held_;  ///< the last event, when skipped: it may end a cascade
  std::string held_stage_;     ///< held_->stage points here
};

/// Whether rows of this kind are thinned by the stride.
bool is_ordinary(EventKind kind);

}  // namespace mdrsim::cli
