// What happens during a run: the events observers receive.
#pragma once

#include <cstdint>

#include "engine/model/contact_snapshot.hpp"

namespace mdrsim {

enum class RunStatus {
  instability,     ///< the contact jumps off; the critical point is its last equilibrium
  shear_off,       ///< the tangential load alone breaks the glued contact
  no_instability,  ///< the contact peels off smoothly to zero force
  step_limit,      ///< stepping reached solver.max_steps before the contact came off
};

enum class EventKind {
  preload_reached,     ///< the indenter is pressed in and the contact glued
  tangential_applied,  ///< the tangential load is applied at the preload
  spring_detached,     ///< the boundary spring lets go
  step_accepted,       ///< stepping: an increment of the control value is taken
  step_halved,         ///< stepping: an increment detached several springs and is halved
  instability,         ///< the critical point: the last equilibrium before the final jump
  finished,            ///< the run ends, with its status
};

struct Event {
  EventKind kind;
  /// For spring_detached, the state as the boundary spring lets go, before it is removed;
  /// for instability, the critical point; otherwise the state after the event.
  ContactSnapshot state;
  std::int64_t spring = 0;  ///< spring_detached: index of the spring, 1 = innermost
  bool in_cascade = false;  ///< spring_detached: at the control value of the previous detachment
  double step = 0.0;        ///< step_accepted, step_halved: the increment [control units]
  RunStatus status = RunStatus::instability;  ///< instability, finished
};

const char* to_string(RunStatus status);
const char* to_string(EventKind kind);

}  // namespace mdrsim
