// A skipped row is held until the next event says whether it opened or closed a cascade.
#include "engine/output/trajectory_stride.hpp"

namespace mdrsim::cli {

bool is_ordinary(EventKind kind) {
  switch (kind) {
    case EventKind::spring_detached:
    case EventKind::step_accepted:
    case EventKind::step_halved:
    case EventKind::spring_glued:
    case EventKind::spring_touched:
    case EventKind::spring_lifted:
    case EventKind::spring_slipped:
    case EventKind::spring_stuck:
    case EventKind::sample:
      return true;
    case EventKind::preload_reached:
    case EventKind::tangential_applied:
    case EventKind::instability:
    case EventKind::finished:
    case EventKind::stage_end:
    case EventKind::jump:
      return false;
  }
  return false;
}

TrajectoryStride::TrajectoryStride(Observer& inner, std::int64_t stride)
    : inner_(&inner), stride_(stride < 1 ? 1 : stride) {}

void TrajectoryStride::finish() {
  if (!held_) return;
  inner_->on_event(*held_);
  held_.reset();
}

void TrajectoryStride::on_event(const Event& event) {
  if (event.kind == EventKind::finished) {
    finish();
    inner_->on_event(event);
    return;
  }
  // The held row is the one just before this event: a cascade's first when this one is in
  // the cascade and it was not, its last when it was and this one is not.
  if (held_ && event.in_cascade != previous_in_cascade_) finish();
  held_.reset();
  previous_in_cascade_ = event.in_cascade;
  if (!is_ordinary(event.kind) || ordinary_++ % stride_ == 0) {
    inner_->on_event(event);
    return;
  }
  held_stage_.assign(event.stage.begin(), event.stage.end());
  held_ = event;
  held_->stage = held_stage_;
}

}  // namespace mdrsim::cli
