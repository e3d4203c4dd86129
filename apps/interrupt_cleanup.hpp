// SIGINT and SIGTERM during `run`: the unfinished output files are removed, exit 130 or 143.
#pragma once

#include <string>

namespace mdrsim::cli {

/// Installs handlers for SIGINT and SIGTERM that unlink every registered path, say so on
/// standard error and end the process with 128 + the signal number (130, 143). A signal that
/// was ignored when mdrsim started stays ignored.
void install_interrupt_cleanup();

/// Registers a file for the handlers to remove; returns its slot for forget_on_interrupt, or
/// -1 when none is free (then the file stays behind if a signal comes).
int remove_on_interrupt(const std::string& path);
void forget_on_interrupt(int slot);

}  // namespace mdrsim::cli
