// mdrsim._core's measured force curves (used by mdrsim.afm): read, and fitted by engine/fit.
#pragma once

#include <pybind11/pybind11.h>

namespace mdrsim::python {

/// mdrsim._core: MeasuredCurve, afm_read, afm_fit.
void bind_afm(pybind11::module_& m);

}  // namespace mdrsim::python
