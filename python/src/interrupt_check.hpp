// Ctrl-C during a run from Python: the engine's interrupt check raises KeyboardInterrupt.
#pragma once

namespace mdrsim::python {

/// Remembers the interpreter's main thread (the one that imports the module): only there does
/// Python handle signals.
void remember_main_thread();

/// While alive, runs of this thread (the GIL released) look for a pending signal every few
/// milliseconds (engine/events/progress_log.hpp) and stop with the exception its Python handler
/// raises: KeyboardInterrupt for Ctrl-C. Nothing on any other thread. Made with the GIL held.
class InterruptibleRun {
 public:
  InterruptibleRun();
  ~InterruptibleRun();
  InterruptibleRun(const InterruptibleRun&) = delete;
  InterruptibleRun& operator=(const InterruptibleRun&) = delete;

 private:
  void (*previous_)();
};

}  // namespace mdrsim::python
