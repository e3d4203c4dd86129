// Names of statuses and event kinds, as they appear in JSON, CSV and logs.
#include "engine/events/event.hpp"

namespace mdrsim {

const char* to_string(RunStatus status) {
  switch (status) {
    case RunStatus::instability:
      return "instability";
    case RunStatus::shear_off:
      return "shear-off";
    case RunStatus::no_instability:
      return "no-instability";
    case RunStatus::step_limit:
      return "step-limit";
    case RunStatus::completed:
      return "completed";
  }
  return "?";
}

const char* to_string(EventKind kind) {
  switch (kind) {
    case EventKind::preload_reached:
      return "preload";
    case EventKind::tangential_applied:
      return "tangential";
    case EventKind::spring_detached:
      return "detached";
    case EventKind::step_accepted:
      return "step";
    case EventKind::step_halved:
      return "halved";
    case EventKind::instability:
      return "instability";
    case EventKind::finished:
      return "finished";
    case EventKind::spring_glued:
      return "glued";
    case EventKind::spring_touched:
      return "touched";
    case EventKind::spring_lifted:
      return "lifted";
    case EventKind::stage_end:
      return "stage-end";
    case EventKind::jump:
      return "jump";
    case EventKind::sample:
      return "sample";
    case EventKind::spring_slipped:
      return "slip";
    case EventKind::spring_stuck:
      return "stick";
  }
  return "?";
}

std::string_view stage_name(const Event& event) {
  if (!event.stage.empty()) return event.stage;
  switch (event.kind) {
    case EventKind::preload_reached:
      return "preload";
    case EventKind::tangential_applied:
      return "tangential";
    default:
      return "pull-off";
  }
}

}  // namespace mdrsim
