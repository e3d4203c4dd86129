// MDRSIM_VERSION comes from CMakeLists.txt's project(VERSION), set on this library only.
#include "engine/events/program_version.hpp"

#ifndef MDRSIM_VERSION
#error "MDRSIM_VERSION must be defined by the build (engine/CMakeLists.txt)"
#endif

namespace mdrsim {

const char* program_version() { return MDRSIM_VERSION; }

}  // namespace mdrsim
