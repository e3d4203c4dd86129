# cmake --install: the mdrsim command (bin/), the static libraries of the engine and the parts
# (lib/), the public headers (include/mdrsim/, public_headers.cmake) and the CMake package
# (lib/cmake/mdrsim/). Tests, bench, mdrsim_reference, mdrsim_cli and the Python module are
# not installed. Included from the top-level CMakeLists.txt, after every target exists.
include(CMakePackageConfigHelpers)
include(${CMAKE_CURRENT_LIST_DIR}/public_headers.cmake)

set(mdrsim_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/mdrsim)
set(mdrsim_exported mdrsim_vocabulary mdrsim_profiles mdrsim_detachment mdrsim_controllers
                    mdrsim_friction mdrsim_engine)

# The names a downstream project links, also usable in-tree: mdrsim_engine is mdrsim::engine.
foreach(target IN LISTS mdrsim_exported)
  string(REPLACE "mdrsim_" "" short ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${short})
  add_library(mdrsim::${short} ALIAS ${target})
endforeach()

install(TARGETS mdrsim RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${mdrsim_exported} EXPORT mdrsimTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(header IN LISTS MDRSIM_PUBLIC_HEADERS)
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/mdrsim/${folder})
endforeach()

install(EXPORT mdrsimTargets NAMESPACE mdrsim:: DESTINATION ${mdrsim_package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/mdrsimConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/mdrsimConfig.cmake
                              INSTALL_DESTINATION ${mdrsim_package_dir})
# 0.x: a minor version may change the API, so find_package(mdrsim 0.1) accepts 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/mdrsimConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/mdrsimConfig.cmake
              ${PROJECT_BINARY_DIR}/mdrsimConfigVersion.cmake
        DESTINATION ${mdrsim_package_dir})
