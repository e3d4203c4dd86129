// Why a run stopped at a limit (status step-limit): the limit it met, or what kept it from
// going on. Each has its own name, as SUNDIALS returns a distinct code for each reason.
#pragma once

namespace mdrsim {

enum class StopReason {
  outgrew_row,            ///< the contact needed a spring beyond the end of its row
  max_steps,              ///< stepping took solver.max_steps steps
  max_events,             ///< a spring row took solver.max_events events
  max_events_per_spring,  ///< a program stage took more events per spring of its row than
                          ///< solver.max_events_per_spring: stick-slip without end
  overflow,               ///< forces, displacements or work left the range of a double
  unending_cascade,       ///< the changes at one parameter value did not settle (rounding)
  no_end,                 ///< a stage until separation with nothing on its path to part it
};

/// The reason's name, as the JSON, the CSV, the summary and Python spell it.
inline const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::outgrew_row:
      return "outgrew-row";
    case StopReason::max_steps:
      return "max-steps";
    case StopReason::max_events:
      return "max-events";
    case StopReason::max_events_per_spring:
      return "max-events-per-spring";
    case StopReason::overflow:
      return "overflow";
    case StopReason::unending_cascade:
      return "unending-cascade";
    case StopReason::no_end:
      return "no-end";
  }
  return "?";
}

}  // namespace mdrsim
