# Install.CustomFrictionLawExample: examples/custom_friction_law built against the installed
# package and run; its tangential force against the independent integral it prints.
include(${CMAKE_CURRENT_LIST_DIR}/downstream.cmake)
run_example(custom_friction_law completed)
if(NOT out MATCHES "relative difference: ([0-9.e+-]+)\n")
  message(FATAL_ERROR "custom_friction_law printed no relative difference")
endif()
set(difference ${CMAKE_MATCH_1})
# 4000 springs: the row's F_x is a right-endpoint sum of a line load that falls from mu_out E* d
# to 0 with a step at r_in, within 2 dx times its variation of the integral (1.5e-3 relative
# here; docs/friction.md); measured 1.1e-4.
if(NOT difference LESS 1.5e-3)
  message(FATAL_ERROR "custom_friction_law: F_x apart from the integral by ${difference}")
endif()
message(STATUS "F_x within ${difference} of 2 int min(G* u, mu(x) E* (d - x^2/R)) dx")
