// Detachment criteria and profiles written in Python, each registered by one call.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "engine/scene/registries.hpp"

namespace mdrsim::python {

/// The registries scenes are built from: the built-in parts and those registered from
/// Python. Replaced, never changed, by a registration; read with the GIL held.
std::shared_ptr<const Registries> current_registries();

/// mdrsim._core: Material, register_criterion, register_profile, part_names.
void bind_parts(pybind11::module_& m);

}  // namespace mdrsim::python
