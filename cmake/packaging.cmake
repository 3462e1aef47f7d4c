# Installing and packaging: `cmake --install build` (prefix /usr for a system install) puts
#   bin/cadmedial                                   the command-line program
#   lib/python3/dist-packages/cadmedial/            the Python package with _core*.so, for
#                                                   /usr/bin/python3 (Debian's own path)
#   share/freecad/Mod/MedialAxis/                   the FreeCAD addon (Init.py, InitGui.py,
#                                                   package.xml, Resources/icons): where Debian's
#                                                   FreeCAD 0.20 looks for system workbenches
# and `cpack -G DEB` (in build/) makes freecad-medialaxis_<version>_<arch>.deb of the same, which
# depends on Debian's freecad and on the OpenCASCADE/TBB/GMP libraries the binaries link
# (found by dpkg-shlibdeps). tools/check_deb.sh builds, inspects and tries the package.
set(CADMEDIAL_PYTHON_DIR "lib/python3/dist-packages" CACHE STRING
    "Where the Python package goes, under the install prefix")
set(CADMEDIAL_ADDON_DIR "share/freecad/Mod/MedialAxis" CACHE STRING
    "Where the FreeCAD addon goes, under the install prefix")

install(TARGETS cadmedial RUNTIME DESTINATION bin COMPONENT medialaxis)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/python/cadmedial DESTINATION ${CADMEDIAL_PYTHON_DIR}
        COMPONENT medialaxis
        FILES_MATCHING PATTERN "*.py" PATTERN "*.pyi" PATTERN "py.typed" PATTERN "__pycache__" EXCLUDE)
if(TARGET _core)
  install(TARGETS _core LIBRARY DESTINATION ${CADMEDIAL_PYTHON_DIR}/cadmedial COMPONENT medialaxis)
endif()
install(FILES ${CMAKE_SOURCE_DIR}/Init.py ${CMAKE_SOURCE_DIR}/InitGui.py ${CMAKE_SOURCE_DIR}/package.xml
        DESTINATION ${CADMEDIAL_ADDON_DIR} COMPONENT medialaxis)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/Resources/icons DESTINATION ${CADMEDIAL_ADDON_DIR}/Resources
        COMPONENT medialaxis FILES_MATCHING PATTERN "*.svg")
# The package finds its icons beside itself when the addon folder is elsewhere (icons.py).
install(DIRECTORY ${CMAKE_SOURCE_DIR}/Resources/icons DESTINATION ${CADMEDIAL_PYTHON_DIR}/cadmedial/Resources
        COMPONENT medialaxis FILES_MATCHING PATTERN "*.svg")

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "freecad-medialaxis")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Medial axis of CAD solids: FreeCAD workbench, command-line program and Python package")
set(CPACK_PACKAGE_CONTACT "cadmedial team <cadmedial@example.invalid>")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Beside the shared libraries dpkg-shlibdeps finds: FreeCAD itself and numpy for the package.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "freecad (>= 0.20), python3 (>= 3.11), python3 (<< 3.12), python3-numpy")
# Only the program, the package and the addon: not the tests' or benchmarks' files.
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};${PROJECT_NAME};medialaxis;/")
include(CPack)
