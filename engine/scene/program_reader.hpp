// Reads a loading program ([[loading.stage]], loading.rebinding) and keeps the shorthand and the
// program apart (docs/programs.md).
#pragma once

#include <string_view>

#include "controllers/controller_registry.hpp"
#include "engine/scene/program.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/toml_reader.hpp"

namespace mdrsim {

/// Whether the [loading] table is a program: it holds `stage`.
inline bool is_program(const TomlReader& loading) { return loading.has("stage"); }

/// Reads the program of a [loading] table that holds `stage`: every stage checked, each axis's
/// controller followed through the stages from fixed-grips at the start.
Program read_program(TomlReader& loading, const ControllerRegistry& controllers);

/// Declares the shorthand's [loading] keys and refuses what applies to programs only:
/// loading.rebinding and a positive material.approach_work_of_adhesion.
void check_shorthand_keys(TomlReader& loading, TomlReader& material, const Material& values);

/// Refuses `key` of `table` (a time key of the material or the criterion: the bulk's relaxation,
/// the edge's rate law) unless the scene runs a timed program: `program` null for the shorthand.
void require_timed_program(const TomlReader& table, std::string_view key, const Program* program);

}  // namespace mdrsim
