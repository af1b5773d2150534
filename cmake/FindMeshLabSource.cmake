# SPDX-License-Identifier: GPL-3.0-or-later
# Locates the source tree of Debian's `meshlab` source package, fetched by scripts/setup.sh.
#
# Inputs (cache variables, all optional):
#   MESHLAB_SOURCE_DIR  a MeshLab source tree (holds vcglib/ or src/vcglib/, and src/common/)
#   VCGLIB_DIR          a vcglib checkout, if it is not inside MESHLAB_SOURCE_DIR
# Default search: $ELASTICA_CACHE_DIR, then ${XDG_CACHE_HOME:-$HOME/.cache}/elastica, for
# meshlab-src-<version of the installed meshlab package>, else the newest meshlab-src-*.
# Outputs:
#   MeshLabSource_FOUND, VCGLIB_DIR, MESHLAB_SOURCE_DIR (may stay empty: only the plugin needs it)
#   target vcglib::vcglib (INTERFACE, SYSTEM includes: vcglib is not warning-clean)
#   VCGLIB_PLY_SOURCE    wrap/ply/plylib.cpp, to compile into anything doing PLY I/O
include(${CMAKE_CURRENT_LIST_DIR}/ElasticaCacheRoots.cmake)
elastica_cache_roots(_ml_roots)

if(NOT MESHLAB_SOURCE_DIR AND NOT VCGLIB_DIR)
  execute_process(COMMAND dpkg-query -W -f=\${Version} meshlab
                  OUTPUT_VARIABLE _ml_version ERROR_QUIET RESULT_VARIABLE _ml_rc)
  foreach(_root IN LISTS _ml_roots)
    if(_ml_rc EQUAL 0 AND EXISTS "${_root}/meshlab-src-${_ml_version}/.elastica-complete")
      set(_found "${_root}/meshlab-src-${_ml_version}")
      break()
    endif()
    file(GLOB _cands LIST_DIRECTORIES true "${_root}/meshlab-src-*")
    if(_cands)
      list(SORT _cands COMPARE NATURAL ORDER DESCENDING)
      list(GET _cands 0 _found)
      break()
    endif()
  endforeach()
  if(_found)
    set(MESHLAB_SOURCE_DIR "${_found}" CACHE PATH "MeshLab source tree (Debian source package)")
  endif()
endif()

if(NOT VCGLIB_DIR AND MESHLAB_SOURCE_DIR)
  if(EXISTS "${MESHLAB_SOURCE_DIR}/vcglib")
    set(VCGLIB_DIR "${MESHLAB_SOURCE_DIR}/vcglib" CACHE PATH "vcglib source tree")
  else()  # MeshLab 2021 and later keep it under src/
    set(VCGLIB_DIR "${MESHLAB_SOURCE_DIR}/src/vcglib" CACHE PATH "vcglib source tree")
  endif()
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MeshLabSource
  REQUIRED_VARS VCGLIB_DIR
  FAIL_MESSAGE "vcglib not found: run scripts/setup.sh (fetches Debian's meshlab source package) or pass -DMESHLAB_SOURCE_DIR=<tree> / -DVCGLIB_DIR=<vcglib>")
if(MeshLabSource_FOUND AND NOT EXISTS "${VCGLIB_DIR}/vcg/complex/complex.h")
  message(FATAL_ERROR "VCGLIB_DIR=${VCGLIB_DIR} does not contain vcg/complex/complex.h")
endif()

if(MeshLabSource_FOUND AND NOT TARGET vcglib::vcglib)
  add_library(vcglib::vcglib INTERFACE IMPORTED)
  set_target_properties(vcglib::vcglib PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${VCGLIB_DIR}")
  # Use the system Eigen (the Debian tree does not bundle one).
  target_link_libraries(vcglib::vcglib INTERFACE Eigen3::Eigen)
  set(VCGLIB_PLY_SOURCE "${VCGLIB_DIR}/wrap/ply/plylib.cpp")
endif()
