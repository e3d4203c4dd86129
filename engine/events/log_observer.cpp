// Levels chosen so that info shows the preload, the tangential load and the critical point.
#include "engine/events/log_observer.hpp"

#include <spdlog/common.h>

#include "engine/base/engine_logger.hpp"
#include "engine/events/event_format.hpp"

namespace mdrsim {

void LogObserver::on_event(const Event& event) {
  switch (event.kind) {
    case EventKind::preload_reached:
    case EventKind::tangential_applied:
    case EventKind::instability:
      engine_logger().info("{}", event);
      break;
    case EventKind::finished:
      if (event.status != RunStatus::instability) engine_logger().info("{}", event);
      break;
    case EventKind::stage_end:
    case EventKind::jump:
      engine_logger().info("{}", event);
      break;
    case EventKind::spring_detached:
    case EventKind::spring_glued:
    case EventKind::spring_touched:
    case EventKind::spring_lifted:
    case EventKind::spring_slipped:
    case EventKind::spring_stuck:
      engine_logger().debug("{}", event);
      break;
    case EventKind::step_accepted:
    case EventKind::step_halved:
    case EventKind::sample:
      engine_logger().trace("{}", event);
      break;
  }
}

bool LogObserver::wants(EventKind kind) const {
  switch (kind) {
    case EventKind::spring_detached:
    case EventKind::spring_glued:
    case EventKind::spring_touched:
    case EventKind::spring_lifted:
    case EventKind::spring_slipped:
    case EventKind::spring_stuck:
      return engine_logger().should_log(spdlog::level::debug);
    case EventKind::step_accepted:
    case EventKind::step_halved:
    case EventKind::sample:
      return engine_logger().should_log(spdlog::level::trace);
    default:
      // At --log-level warn or above nothing is logged: a run under rtol then need not run
      // its finest row again only to give these events (program_resolution.cpp).
      return engine_logger().should_log(spdlog::level::info);
  }
}

}  // namespace mdrsim
