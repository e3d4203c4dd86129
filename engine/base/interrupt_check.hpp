// The caller's interrupt check (Python's Ctrl-C), polled by the engine's long loops.
#pragma once

namespace mdrsim {

/// Called by the runs of this thread every 65536 events or so (a few milliseconds), and every
/// 2^20 springs of an O(N) set-up pass; throws to stop the run. Null: none (the command stops
/// on a signal by ending the process).
using InterruptCheck = void (*)();
inline thread_local InterruptCheck interrupt_check = nullptr;

/// Runs this thread's interrupt check, if there is one.
inline void poll_interrupt() {
  if (interrupt_check != nullptr) interrupt_check();
}

}  // namespace mdrsim
