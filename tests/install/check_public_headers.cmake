# Install.PublicHeaders: the installed headers are exactly the stable API of
# engine/install/public_headers.cmake; the set is closed (each header's includes of mdrsim are
# installed too) and each one compiles on its own against the installed tree. Lists the
# headers left private.
include(${CMAKE_CURRENT_LIST_DIR}/downstream.cmake)
include(${SOURCE_DIR}/engine/install/public_headers.cmake)
set(include_dir ${prefix}/include/mdrsim)

file(GLOB_RECURSE installed RELATIVE ${include_dir} ${include_dir}/*)
set(intended ${MDRSIM_PUBLIC_HEADERS})
list(SORT installed)
list(SORT intended)
if(NOT installed STREQUAL intended)
  set(extra ${installed})
  list(REMOVE_ITEM extra ${intended})
  set(missing ${intended})
  list(REMOVE_ITEM missing ${installed})
  message(FATAL_ERROR "installed headers differ from the stable API\n"
                      "  installed, not public: ${extra}\n  public, not installed: ${missing}")
endif()
list(LENGTH installed count)
message(STATUS "${count} public headers installed under ${include_dir}:")
foreach(header IN LISTS installed)
  message(STATUS "  ${header}")
endforeach()

# The headers of the library folders that stay private.
file(GLOB_RECURSE all_headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/engine/*.hpp
     ${SOURCE_DIR}/profiles/*.hpp ${SOURCE_DIR}/detachment/*.hpp ${SOURCE_DIR}/controllers/*.hpp)
set(private ${all_headers})
list(REMOVE_ITEM private ${intended})
list(SORT private)
list(LENGTH private count)
message(STATUS "${count} private headers, not installed:")
foreach(header IN LISTS private)
  message(STATUS "  ${header}")
endforeach()

# Closed: every quoted include of an installed header is installed (checked by name here, for
# a clear message; the compilation below checks it again).
set(open)
foreach(header IN LISTS installed)
  file(STRINGS ${include_dir}/${header} includes REGEX "^#include \"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${include_dir}/${included})
      list(APPEND open "${header} includes ${included}")
    endif()
  endforeach()
endforeach()
if(open)
  list(JOIN open "\n  " open)
  message(FATAL_ERROR "public headers include private ones:\n  ${open}")
endif()

# The package names no path of the source or build tree: it works from the prefix alone.
file(GLOB_RECURSE package_files ${prefix}/*.cmake)
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(tree IN ITEMS ${SOURCE_DIR} ${BINARY_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} names ${tree}")
    endif()
  endforeach()
endforeach()

# Each header alone in a translation unit of a downstream project, warnings as errors.
set(project ${WORK_DIR}/headers)
file(REMOVE_RECURSE ${project})
set(sources)
foreach(header IN LISTS installed)
  string(MAKE_C_IDENTIFIER ${header} name)
  file(WRITE ${project}/${name}.cpp "#include \"${header}\"\n")
  list(APPEND sources ${name}.cpp)
endforeach()
list(JOIN sources " " sources)
file(WRITE ${project}/CMakeLists.txt "
cmake_minimum_required(VERSION 3.25)
project(mdrsim_public_headers LANGUAGES CXX)
find_package(mdrsim CONFIG REQUIRED)
add_library(public_headers OBJECT ${sources})
target_link_libraries(public_headers PRIVATE mdrsim::engine)
target_compile_options(public_headers PRIVATE -Wall -Wextra -Wpedantic -Werror)
")
build_downstream(${project} ${WORK_DIR}/headers-build)
message(STATUS "each public header compiles on its own against ${include_dir}")
