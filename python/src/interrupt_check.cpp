// The check takes the GIL for PyErr_CheckSignals, on the main thread only, every 65536 events.
#include "python/src/interrupt_check.hpp"

#include <pybind11/pybind11.h>

#include "engine/events/progress_log.hpp"

namespace py = pybind11;

namespace mdrsim::python {
namespace {

unsigned long main_thread = 0;  // NOLINT: written once, at import

void check_signals() {
  py::gil_scoped_acquire gil;
  // Runs the Python handlers of the signals that came; one that raises leaves its exception.
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace

void remember_main_thread() { main_thread = PyThread_get_thread_ident(); }

InterruptibleRun::InterruptibleRun() : previous_(interrupt_check) {
  if (PyThread_get_thread_ident() == main_thread) interrupt_check = &check_signals;
}

InterruptibleRun::~InterruptibleRun() { interrupt_check = previous_; }

}  // namespace mdrsim::python
