# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DBUILD_DIR=<build> -DPROBES=<probes.txt> -P check_tier_includes.cmake (ctest tier_includes;
# see CMakeLists.txt here). Each line of PROBES: "<target> build" or "<target> fail <header>".
file(STRINGS "${PROBES}" probes)
set(failures "")
foreach(line IN LISTS probes)
  string(REPLACE " " ";" words "${line}")
  list(GET words 0 target)
  list(GET words 1 expect)
  execute_process(COMMAND ${CMAKE_COMMAND} --build "${BUILD_DIR}" --target ${target}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(expect STREQUAL "build")
    if(rc EQUAL 0)
      message(STATUS "${target}: builds, as it must")
    else()
      string(APPEND failures "${target} must build and did not:\n${out}\n${err}\n")
    endif()
  else()
    list(GET words 2 header)
    # The upward header itself must be what is missing (GCC: "<h>: No such file or directory";
    # clang: "'<h>' file not found"), not some other error.
    string(REGEX MATCH "${header}'?:? (No such file or directory|file not found)" missing "${out}${err}")
    if(NOT rc EQUAL 0 AND missing)
      message(STATUS "${target}: fails, as it must (${header} not found)")
    else()
      string(APPEND failures "${target} must fail for want of ${header} and did not (exit ${rc}):\n${out}\n${err}\n")
    endif()
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "${failures}")
endif()
