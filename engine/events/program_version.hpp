// The version of mdrsim that produced an output (CMake's project version).
#pragma once

namespace mdrsim {

/// "MAJOR.MINOR.PATCH", as `mdrsim --version` prints it and the JSON result carries it.
const char* program_version();

}  // namespace mdrsim
