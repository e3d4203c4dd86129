// What happens during a run: the events observers receive.
#pragma once

#include <cstdint>
#include <string_view>

#include "engine/model/contact_snapshot.hpp"

namespace mdrsim {

enum class RunStatus {
  instability,     ///< the contact jumps off; the critical point is its last equilibrium
  shear_off,       ///< the tangential load alone breaks the glued contact
  no_instability,  ///< the contact peels off smoothly to zero force
  step_limit,      ///< the run stopped at a limit before the contact came off
                   ///< (RunResult::stop_reason says which)
  completed,       ///< a program's last stage ran to its end with the contact in place
};

enum class EventKind {
  preload_reached,     ///< the indenter is pressed in and the contact glued
  tangential_applied,  ///< the tangential load is applied at the preload
  spring_detached,     ///< the boundary spring lets go
  step_accepted,       ///< stepping: an increment of the control value is taken
  step_halved,         ///< stepping: an increment detached several springs and is halved
  instability,         ///< the critical point: the last equilibrium before the final jump
  finished,            ///< the run ends, with its status
  // Loading programs (docs/programs.md):
  spring_glued,    ///< the spring just outside the glued contact glues (the advancing front)
  spring_touched,  ///< a spring without glue is pressed against the indenter
  spring_lifted,   ///< a spring without glue leaves the indenter
  stage_end,       ///< a stage reaches its end (or separation)
  jump,            ///< a cascade at one value of the stage parameter; state after it
  sample,          ///< the continuum route's branch at one contact radius (--trajectory)
  // Friction (docs/friction.md):
  spring_slipped,  ///< a sticking spring in contact reaches its slip limit and slides
  spring_stuck,    ///< a sliding spring's slip would reverse: it sticks again (the last kind)
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
  /// The stage the event belongs to; empty for the shorthand, whose writers name the stage
  /// by the event kind.
  std::string_view stage;
};

const char* to_string(RunStatus status);
/// The stage an event belongs to: a program's events name theirs; the shorthand's are named
/// by kind (docs): preload, tangential, pull-off.
std::string_view stage_name(const Event& event);
const char* to_string(EventKind kind);

}  // namespace mdrsim
