# fmt, spdlog and toml++ compiled into what links them, so that the Python module and the mdrsim
# command in its wheel need no shared library of theirs at run time (docs/python.md "Installing").
# Debian ships the three as shared libraries only (no .a), and each builds header-only as well.
# Included before their find_package calls: fmt's and toml++'s config files define nothing when
# fmt::fmt or tomlplusplus::tomlplusplus exists, and spdlog's export file returns early when both
# of its targets do, so the engine's CMakeLists link these under the usual names.
find_package(Threads REQUIRED)
find_path(MDRSIM_FMT_INCLUDE_DIR fmt/format.h REQUIRED)
find_path(MDRSIM_SPDLOG_INCLUDE_DIR spdlog/spdlog.h REQUIRED)
find_path(MDRSIM_TOMLPLUSPLUS_INCLUDE_DIR toml++/toml.h REQUIRED)

foreach(name IN ITEMS fmt::fmt fmt::fmt-header-only)
  add_library(${name} INTERFACE IMPORTED)
  set_target_properties(${name} PROPERTIES INTERFACE_COMPILE_DEFINITIONS FMT_HEADER_ONLY=1
                        INTERFACE_INCLUDE_DIRECTORIES ${MDRSIM_FMT_INCLUDE_DIR})
endforeach()
# SPDLOG_FMT_EXTERNAL: Debian's spdlog carries no fmt of its own.
foreach(name IN ITEMS spdlog::spdlog spdlog::spdlog_header_only)
  add_library(${name} INTERFACE IMPORTED)
  set_target_properties(${name} PROPERTIES INTERFACE_COMPILE_DEFINITIONS SPDLOG_FMT_EXTERNAL
                        INTERFACE_INCLUDE_DIRECTORIES ${MDRSIM_SPDLOG_INCLUDE_DIR}
                        INTERFACE_LINK_LIBRARIES "fmt::fmt;Threads::Threads")
endforeach()
add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
set_target_properties(tomlplusplus::tomlplusplus PROPERTIES INTERFACE_COMPILE_DEFINITIONS
                      TOML_HEADER_ONLY=1 INTERFACE_INCLUDE_DIRECTORIES ${MDRSIM_TOMLPLUSPLUS_INCLUDE_DIR})
