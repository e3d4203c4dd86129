# Shared by the install tests (cmake -P): where the prefix is, and how a downstream project is
# configured and built against it with nothing but the prefix on CMAKE_PREFIX_PATH.
set(prefix ${WORK_DIR}/prefix)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
endfunction()

# Configures and builds the project in `source` in `build` (emptied first).
function(build_downstream source build)
  file(REMOVE_RECURSE ${build})
  set(flags)
  if(SANITIZE)
    list(APPEND flags -DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE}
         -DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE})
  endif()
  # No package registry: the prefix is the only way to the package.
  run_step("configuring ${source}" ${CMAKE_COMMAND} -S ${source} -B ${build} -G ${GENERATOR}
           -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
           -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF ${flags})
  run_step("building ${source}" ${CMAKE_COMMAND} --build ${build} -j2)
endfunction()

# Builds examples/<name> against the prefix, runs it on its scene.toml and sets `out` in the
# caller to what it printed; fails unless it exits 0 and prints "status: <status>".
function(run_example name status)
  set(build ${WORK_DIR}/${name}-build)
  build_downstream(${SOURCE_DIR}/examples/${name} ${build})
  execute_process(COMMAND ${build}/${name} ${SOURCE_DIR}/examples/${name}/scene.toml
                  RESULT_VARIABLE code OUTPUT_VARIABLE printed ERROR_VARIABLE err)
  message(STATUS "${name}:\n${printed}${err}")
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${name} exited with ${code}")
  endif()
  if(NOT printed MATCHES "status: ${status}\n")
    message(FATAL_ERROR "${name}: expected status ${status}")
  endif()
  set(out "${printed}" PARENT_SCOPE)
endfunction()
