// mdrsim._core.SweepPlan: a sweep's rows built, run and written by the command's own code.
#pragma once

#include <pybind11/pybind11.h>

namespace mdrsim::python {

/// mdrsim._core: SweepPlan (used by mdrsim.sweep).
void bind_sweep(pybind11::module_& m);

}  // namespace mdrsim::python
