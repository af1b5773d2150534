# SPDX-License-Identifier: GPL-3.0-or-later
# Locates the real sample meshes that scripts/setup.sh unpacks from Debian's libcgal-demo package
# (elephant.off, elephant-with-holes.off, bunny00.off) into its cache.
#
# Input (cache variable, optional): CGAL_SAMPLE_MESH_DIR, a directory holding those files.
# Default search: $ELASTICA_CACHE_DIR, then ${XDG_CACHE_HOME:-$HOME/.cache}/elastica, for the
# newest cgal-data-<version>/meshes that setup.sh completed.
# Output: CgalSampleMeshes_FOUND, CGAL_SAMPLE_MESH_DIR.
if(NOT CGAL_SAMPLE_MESH_DIR)
  include(${CMAKE_CURRENT_LIST_DIR}/ElasticaCacheRoots.cmake)
  elastica_cache_roots(_csm_roots)
  foreach(_root IN LISTS _csm_roots)
    file(GLOB _csm_stamps "${_root}/cgal-data-*/.elastica-complete")
    if(_csm_stamps)
      list(SORT _csm_stamps COMPARE NATURAL ORDER DESCENDING)
      list(GET _csm_stamps 0 _csm_stamp)
      get_filename_component(_csm_dir "${_csm_stamp}" DIRECTORY)
      set(CGAL_SAMPLE_MESH_DIR "${_csm_dir}/meshes" CACHE PATH "Sample meshes from Debian's libcgal-demo (scripts/setup.sh)")
      break()
    endif()
  endforeach()
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CgalSampleMeshes
  REQUIRED_VARS CGAL_SAMPLE_MESH_DIR
  FAIL_MESSAGE "sample meshes not found: run scripts/setup.sh (unpacks three meshes from Debian's libcgal-demo) or pass -DCGAL_SAMPLE_MESH_DIR=<dir with elephant.off, elephant-with-holes.off and bunny00.off>")
