// The logger the engine writes to: never standard output, which belongs to the program that
// links the engine (its JSON, its CSV), but spdlog's default logger once the program has set
// one (spdlog::set_default_logger), else a logger of the engine's own on standard error.
#pragma once

#include <spdlog/logger.h>

namespace mdrsim {

/// spdlog's default logger unless it is still spdlog's built-in one, which writes to standard
/// output; then a logger on standard error ("[mdrsim warning] ...") at the built-in's level,
/// so that spdlog::set_level still sets what the engine logs. Thread-safe and cheap: no lock.
spdlog::logger& engine_logger();

}  // namespace mdrsim
