# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install build --prefix PREFIX` and the Debian package (`cpack -G DEB` in build/): the
# programs, the image codec module, the Python package, the scenes and metrics, the docs, man
# pages and bash completion made by the program itself, the workbench's desktop entry, icon and
# AppStream metadata, and the CMake package (find_package(Lightcone)). Relocatable: nothing
# installed carries an RPATH or a path of the build tree; the programs find the codec and data
# from their own file (readers/io/install_layout). tests/install/ checks all of it.
set(LIGHTCONE_INSTALL_DOCDIR ${CMAKE_INSTALL_DATADIR}/doc/lightcone)
set(LIGHTCONE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Lightcone)

install(TARGETS lightcone RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS lightcone_oiio_codec LIBRARY DESTINATION ${LIGHTCONE_INSTALL_PRIVATE_LIBDIR})
if(TARGET lightcone_gui)
  install(TARGETS lightcone_gui RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  set(desktop ${PROJECT_SOURCE_DIR}/app/gui/desktop)
  install(FILES ${desktop}/io.github.lightcone.Workbench.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES ${desktop}/io.github.lightcone.Workbench.svg
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
  install(FILES ${desktop}/io.github.lightcone.Workbench.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
endif()

# Scenes and metrics, found by bare name: `lightcone render default.json -o out.png`.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${LIGHTCONE_INSTALL_DATA_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${LIGHTCONE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${LIGHTCONE_INSTALL_DOCDIR}/docs)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${LIGHTCONE_INSTALL_DOCDIR}/examples)

# Man pages and bash completion, written by the program from its own declarations.
set(generated ${PROJECT_BINARY_DIR}/share)
add_custom_command(OUTPUT ${generated}/man1.stamp ${generated}/bash-completion/lightcone
  COMMAND ${CMAKE_COMMAND} -E rm -rf ${generated}/man1
  COMMAND lightcone help --man ${generated}/man1
  COMMAND ${CMAKE_COMMAND} -E make_directory ${generated}/bash-completion
  COMMAND ${CMAKE_COMMAND} -E env sh -c "'$<TARGET_FILE:lightcone>' completion bash > '${generated}/bash-completion/lightcone'"
  COMMAND ${CMAKE_COMMAND} -E touch ${generated}/man1.stamp
  DEPENDS lightcone VERBATIM COMMENT "Man pages and bash completion from lightcone's declarations")
add_custom_target(lightcone_man_pages ALL DEPENDS ${generated}/man1.stamp)
install(DIRECTORY ${generated}/man1/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${generated}/bash-completion/lightcone DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)

# The Python package: import lightcone with PYTHONPATH=PREFIX/lib/python3/dist-packages (the
# Debian package's /usr needs none). lightcone.filters (lightconeFilters) is installed there by
# vtk_module_wrap_python (root CMakeLists).
if(TARGET lightcone_python)
  install(TARGETS lightcone_python LIBRARY DESTINATION ${LIGHTCONE_INSTALL_PYTHON_DIR}/lightcone)
  install(FILES ${PROJECT_SOURCE_DIR}/python/lightcone/__init__.py DESTINATION ${LIGHTCONE_INSTALL_PYTHON_DIR}/lightcone)
  if(TARGET lightcone_filters_python)
    install(FILES ${PROJECT_SOURCE_DIR}/python/lightcone/filters.py DESTINATION ${LIGHTCONE_INSTALL_PYTHON_DIR}/lightcone)
  endif()
endif()

# find_package(Lightcone): Lightcone::lightcone_core (core/CMakeLists) and, in VTK builds,
# Lightcone::lightcone_filters (vtk_module_build in the root CMakeLists installs that export).
include(CMakePackageConfigHelpers)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/LightconeConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake-package/LightconeConfig.cmake INSTALL_DESTINATION ${LIGHTCONE_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/cmake-package/LightconeConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake-package/LightconeConfig.cmake
              ${PROJECT_BINARY_DIR}/cmake-package/LightconeConfigVersion.cmake
        DESTINATION ${LIGHTCONE_INSTALL_CMAKEDIR})
if(NOT LIGHTCONE_WITH_VTK)  # else VTK's module system installs the export with the filters in it
  install(EXPORT LightconeTargets NAMESPACE Lightcone:: FILE Lightcone-targets.cmake
          DESTINATION ${LIGHTCONE_INSTALL_CMAKEDIR})
endif()

# The Debian package: `cpack -G DEB` in build/ -> lightcone_VERSION_ARCH.deb, installable with
# `apt install ./lightcone_*.deb`; its library dependencies come from dpkg-shlibdeps.
set(CPACK_PACKAGE_NAME lightcone)
set(CPACK_PACKAGE_VENDOR "Lightcone developers")
set(CPACK_PACKAGE_CONTACT "Lightcone developers <lightcone@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "what an observer sees in a relativistic spacetime")
set(CPACK_PACKAGE_DESCRIPTION "Lightcone traces light through the Goedel universe, black-hole spacetimes and
any metric typed as a formula, and shows what an observer sees beside the light rays that
make the image. A command line program (lightcone), a Qt workbench (lightcone-gui), a Python
module and VTK filters.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The Python module needs numpy; the filters' Python wrapping needs VTK's; the sky texture
# "earth" names xplanet's maps. Not libraries, so dpkg-shlibdeps cannot find them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-vtk9")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "xplanet-images, fonts-dejavu-core, ffmpeg, xvfb")
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/lightcone")
set(CPACK_DEBIAN_COMPRESSION_TYPE gzip)  # xz took minutes on 2 cores for little gain
include(CPack)
