# SPDX-License-Identifier: GPL-3.0-or-later
# cmake -DBUILD_DIR= -DWORK_DIR= -DPLUGIN_DIR= -P install_check.cmake
# `cmake --install --component meshlab_plugin` puts the plugin into MeshLab's plugin directory
# (staged under DESTDIR here, so nothing lands in /usr), and the default install does not.
file(REMOVE_RECURSE "${WORK_DIR}")
function(install_into destdir)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env DESTDIR=${destdir} ${CMAKE_COMMAND} --install "${BUILD_DIR}" ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake --install ${ARGN} failed (${rc}):\n${out}\n${err}")
  endif()
endfunction()
install_into("${WORK_DIR}/component" --component meshlab_plugin)
if(NOT EXISTS "${WORK_DIR}/component${PLUGIN_DIR}/libfilter_elastica.so")
  message(FATAL_ERROR "--component meshlab_plugin did not install ${PLUGIN_DIR}/libfilter_elastica.so")
endif()
install_into("${WORK_DIR}/default" --prefix "${WORK_DIR}/prefix")
file(GLOB_RECURSE stray "${WORK_DIR}/default/*libfilter_elastica.so" "${WORK_DIR}/prefix/*libfilter_elastica.so")
if(stray)
  message(FATAL_ERROR "the default install also installed the plugin: ${stray}")
endif()
message(STATUS "plugin installs to ${PLUGIN_DIR} with --component meshlab_plugin only")
