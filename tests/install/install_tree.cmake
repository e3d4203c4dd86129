# Install.Tree: `cmake --install` of this build into an empty prefix (the fixture of the others).
include(${CMAKE_CURRENT_LIST_DIR}/downstream.cmake)
file(REMOVE_RECURSE ${prefix})
run_step("cmake --install" ${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix}
         --config ${BUILD_TYPE})
file(GLOB_RECURSE installed RELATIVE ${prefix} ${prefix}/*)
list(SORT installed)
list(JOIN installed "\n  " listing)
message(STATUS "installed into ${prefix}:\n  ${listing}")

# Only the command and the four libraries of mdrsim::engine: no test, bench, reference or CLI
# library, and no Python module.
file(GLOB binaries RELATIVE ${prefix} ${prefix}/bin/* ${prefix}/lib*/*.a ${prefix}/lib*/*.so*)
list(TRANSFORM binaries REPLACE "^lib[^/]*/" "lib/")
list(SORT binaries)
set(expected bin/mdrsim lib/libmdrsim_controllers.a lib/libmdrsim_detachment.a
    lib/libmdrsim_engine.a lib/libmdrsim_friction.a lib/libmdrsim_profiles.a)
if(NOT binaries STREQUAL expected)
  message(FATAL_ERROR "installed programs and libraries: ${binaries}\nexpected: ${expected}")
endif()
