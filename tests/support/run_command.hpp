// Runs the built mdrsim binary in a shell and captures its exit code and output.
#pragma once

#include <string>

namespace mdrsim::test {

struct CommandResult {
  int exit_code;
  std::string out;  ///< standard output
  std::string err;  ///< standard error
};

/// Runs `mdrsim ARGS` (ARGS as shell words) from the source folder, standard input empty or
/// read from the file `input`.
CommandResult run_mdrsim(const std::string& args, const std::string& input = "/dev/null");

/// A fresh empty folder under the system's temp folder.
std::string make_temp_dir();

}  // namespace mdrsim::test
