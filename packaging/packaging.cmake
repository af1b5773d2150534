# SPDX-License-Identifier: GPL-3.0-or-later
# Debian packages of the build (CPack's DEB generator), one per face:
#
#   elastica                 the command, /usr/bin/elastica
#   meshlab-plugin-elastica  the MeshLab plugin, in MeshLab's plugin folder, for the MeshLab it was built
#                            against (Depends on that MeshLab version)
#   python3-elastica         the Python module for the system Python, /usr/lib/python3/dist-packages
#   blender-addon-elastica   the Blender add-on, where Debian's Blender finds system add-ons
#
#   cd build && cpack        -> build/packages/*.deb   (scripts/ci-packages.sh does this, runs lintian, installs and uses them)
#
# Each package is its own install component (deb_*), outside the default install: `cmake --install`
# is unchanged. Dependencies on shared libraries come from dpkg-shlibdeps; the rest are written here.
# The version is the project's (project(VERSION) in CMakeLists.txt).
set(ELASTICA_DEB_PACKAGES elastica)
set(_doc share/doc)

# What the packages are built from, for the changelog entry: the commit and its date (from git, or
# -DELASTICA_SOURCE_COMMIT= where the tree has no git, as in scripts/meshlab2022.sh's root).
execute_process(COMMAND git -C "${PROJECT_SOURCE_DIR}" log -1 --format=%h%n%aD%n%an%n%ae
                OUTPUT_VARIABLE _git OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE _git_rc)
if(_git_rc EQUAL 0 AND _git)
  string(REPLACE "\n" ";" _git "${_git}")
  list(GET _git 0 _commit)
  list(GET _git 1 _date)
  list(GET _git 2 _name)
  list(GET _git 3 _mail)
else()
  set(_commit "${ELASTICA_SOURCE_COMMIT}")
  string(TIMESTAMP _date "%a, %d %b %Y %H:%M:%S +0000" UTC)
  set(_name "Elastica contributors")
  set(_mail "elastica@invalid")
endif()
if(NOT _commit)
  set(_commit unknown)
endif()
set(ELASTICA_DEB_MAINTAINER "${_name} <${_mail}>" CACHE STRING
    "Maintainer field of the Debian packages (default: the author of the commit they are built from)")

# ---- the packages' contents
# The command.
if(TARGET elastica)
  install(TARGETS elastica RUNTIME DESTINATION bin COMPONENT deb_cli EXCLUDE_FROM_ALL)
  # Its manual page (a summary; `elastica COMMAND --help` has the options).
  configure_file("${CMAKE_CURRENT_LIST_DIR}/elastica.1" "${PROJECT_BINARY_DIR}/packaging/elastica.1" COPYONLY)
  execute_process(COMMAND gzip -9nf "${PROJECT_BINARY_DIR}/packaging/elastica.1" RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "gzip failed on packaging/elastica.1")
  endif()
  install(FILES "${PROJECT_BINARY_DIR}/packaging/elastica.1.gz" DESTINATION share/man/man1 COMPONENT deb_cli EXCLUDE_FROM_ALL)
  list(APPEND _components deb_cli)
endif()
# The MeshLab plugin, in the folder MeshLab looks in (MESHLAB_PLUGIN_INSTALL_DIR, under /usr).
if(TARGET filter_elastica)
  string(REGEX REPLACE "^/usr/" "" _plugin_dir "${MESHLAB_PLUGIN_INSTALL_DIR}")
  if(IS_ABSOLUTE "${_plugin_dir}")
    message(FATAL_ERROR "MESHLAB_PLUGIN_INSTALL_DIR (${MESHLAB_PLUGIN_INSTALL_DIR}) is not under /usr: no package for it")
  endif()
  install(TARGETS filter_elastica LIBRARY DESTINATION "${_plugin_dir}" COMPONENT deb_meshlab EXCLUDE_FROM_ALL)
  list(APPEND _components deb_meshlab)
endif()
# The Python module, where Debian's Python 3 keeps extension modules of packages.
if(TARGET elastica_python)
  install(TARGETS elastica_python LIBRARY DESTINATION lib/python3/dist-packages COMPONENT deb_python EXCLUDE_FROM_ALL)
  list(APPEND _components deb_python)
  # The add-on: pure Python, on the module above. Debian's Blender reads system add-ons from
  # /usr/share/blender/scripts/addons (its own add-ons live there, in package blender-data).
  install(DIRECTORY "${PROJECT_SOURCE_DIR}/blender_addon/elastica_blender" DESTINATION share/blender/scripts/addons
          COMPONENT deb_blender EXCLUDE_FROM_ALL FILES_MATCHING PATTERN "*.py" PATTERN "__pycache__" EXCLUDE)
  list(APPEND _components deb_blender)
endif()

set(_pkg_deb_cli elastica)
set(_pkg_deb_meshlab meshlab-plugin-elastica)
set(_pkg_deb_python python3-elastica)
set(_pkg_deb_blender blender-addon-elastica)

# Every package carries its copyright file and a changelog (Debian policy 12.5, 12.7).
set(_changelog "${PROJECT_BINARY_DIR}/packaging/changelog")
foreach(component IN LISTS _components)
  set(pkg ${_pkg_${component}})
  file(WRITE "${_changelog}.${pkg}"
"${pkg} (${PROJECT_VERSION}) unstable; urgency=medium

  * Built from the Elastica source tree at commit ${_commit}.

 -- ${ELASTICA_DEB_MAINTAINER}  ${_date}
")
  execute_process(COMMAND gzip -9nf "${_changelog}.${pkg}" RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "gzip failed on ${_changelog}.${pkg}")
  endif()
  install(FILES "${_changelog}.${pkg}.gz" DESTINATION ${_doc}/${pkg} RENAME changelog.gz COMPONENT ${component} EXCLUDE_FROM_ALL)
  install(FILES "${CMAKE_CURRENT_LIST_DIR}/copyright" DESTINATION ${_doc}/${pkg} COMPONENT ${component} EXCLUDE_FROM_ALL)
endforeach()

# ---- CPack
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME elastica)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "${ELASTICA_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DIRECTORY "${PROJECT_BINARY_DIR}/packages")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_COMPONENTS_ALL ${_components})
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
# Each package's description: its first line is the synopsis (CPack adds the project's summary line
# unless this one is empty), the rest is formatted by CPack (a blank line becomes " .").
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "")
set(_about "Elastica makes triangle meshes fair (smooth, round, free of bumps) with the
discrete elastica flow of Yoshizawa and Belyaev (2002), a gradient descent of
the total curvature, and fills the holes of scans with patches that continue
the surface's curvature.")

set(CPACK_DEBIAN_DEB_CLI_PACKAGE_NAME elastica)
set(CPACK_DEBIAN_DEB_CLI_DESCRIPTION "fair triangle meshes with the discrete elastica flow
${_about}

This package holds the command elastica: fair, fill, curvature, subdivide,
generate, and run (MeshLab filter scripts without MeshLab).")

if(TARGET filter_elastica)
  # The plugin is built against one MeshLab (its source tree and libmeshlab-common.so): it depends on
  # that MeshLab's upstream version, any Debian revision. MeshLab 2022.02 and later also refuse a
  # plugin built for another version themselves.
  execute_process(COMMAND dpkg-query -W -f=\${Version} meshlab OUTPUT_VARIABLE _ml_deb_version ERROR_QUIET)
  string(REGEX REPLACE "^[0-9]+:" "" _ml_upstream "${_ml_deb_version}")
  string(REGEX REPLACE "-[^-]*$" "" _ml_upstream "${_ml_upstream}")
  string(REGEX MATCH "^[0-9]+\\.[0-9]+" _ml_release "${_ml_upstream}")
  if(NOT _ml_upstream)
    message(WARNING "meshlab is not installed (dpkg-query): the plugin's package will not name its MeshLab version")
    set(_ml_depends "meshlab")
  else()
    # >= the upstream version, << that version followed by "+~": every Debian revision of it
    # (2020.09+dfsg1-2, -2+deb12u1), not the next upstream release.
    set(_ml_depends "meshlab (>= ${_ml_upstream}), meshlab (<< ${_ml_upstream}+~)")
  endif()
  set(ELASTICA_MESHLAB_UPSTREAM_VERSION "${_ml_upstream}" CACHE INTERNAL "")
  set(CPACK_DEBIAN_DEB_MESHLAB_PACKAGE_NAME meshlab-plugin-elastica)
  set(CPACK_DEBIAN_DEB_MESHLAB_PACKAGE_DEPENDS "${_ml_depends}")
  # libmeshlab-common.so is MeshLab's private library: dpkg-shlibdeps finds it there and names meshlab.
  get_filename_component(_ml_libdir "${MESHLAB_COMMON_LIBRARY}" DIRECTORY)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${_ml_libdir}")
  set(CPACK_DEBIAN_DEB_MESHLAB_DESCRIPTION "discrete elastica filters for MeshLab ${_ml_release}
${_about}

This package adds to MeshLab the filters Discrete Elastica Fairing, Fill Holes
with Discrete Elastica and Discrete Elastica Curvature. It is built for
MeshLab ${_ml_release} (Debian's meshlab ${_ml_upstream}) only.")
endif()

if(TARGET elastica_python)
  string(REGEX MATCH "^[0-9]+\\.[0-9]+" _py "${Python_VERSION}")
  math(EXPR _py_next "${Python_VERSION_MINOR} + 1")
  set(CPACK_DEBIAN_DEB_PYTHON_PACKAGE_NAME python3-elastica)
  set(CPACK_DEBIAN_DEB_PYTHON_PACKAGE_DEPENDS "python3 (>= ${_py}), python3 (<< ${Python_VERSION_MAJOR}.${_py_next}), python3-numpy")
  set(CPACK_DEBIAN_DEB_PYTHON_PACKAGE_SECTION python)
  set(CPACK_DEBIAN_DEB_PYTHON_DESCRIPTION "discrete elastica flow for NumPy triangle meshes (Python 3)
${_about}

This package holds the Python module elastica (read, write, fair, fill_holes,
curvature on NumPy arrays) for Python ${_py}.")

  set(CPACK_DEBIAN_DEB_BLENDER_PACKAGE_NAME blender-addon-elastica)
  set(CPACK_DEBIAN_DEB_BLENDER_PACKAGE_ARCHITECTURE all)
  set(CPACK_DEBIAN_DEB_BLENDER_PACKAGE_DEPENDS "blender, python3-elastica (= ${PROJECT_VERSION}), python3-numpy")
  # A __pycache__ left beside the add-on by Python run on it is removed before the files go.
  set(CPACK_DEBIAN_DEB_BLENDER_PACKAGE_CONTROL_EXTRA "${CMAKE_CURRENT_LIST_DIR}/blender-addon-elastica/prerm")
  set(CPACK_DEBIAN_DEB_BLENDER_PACKAGE_CONTROL_STRICT_PERMISSION ON)
  set(CPACK_DEBIAN_DEB_BLENDER_DESCRIPTION "discrete elastica fairing and hole filling for Blender
${_about}

This package adds the Blender add-on Elastica (enable it in Preferences,
Add-ons): Mesh > Clean Up > Elastica Fairing, Elastica Fill Holes, Elastica
Curvature.")
endif()

include(CPack)
