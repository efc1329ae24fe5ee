# Installation and the Debian package (cpack -G DEB, from the build tree):
#   /usr/bin/tquad                                the command
#   /usr/lib/templatequad/                        its CAD layer, STEP and IGES readers,
#                                                 loaded for CAD inputs (src/cli/cad_input.h)
#   /usr/lib/python3/dist-packages/tquad/         the module, for Debian's python3
#                                                 (FreeCAD's; on its sys.path)
#   /usr/share/freecad/Mod/TemplateQuad/          the workbench in FreeCAD's system
#                                                 add-on folder (package.xml, LICENSE,
#                                                 freecad_workbench/)
#   /usr/share/doc/templatequad/copyright         the licence
# so `apt install ./templatequad_<version>_<arch>.deb` is the whole installation.
include(GNUInstallDirs)

set(TQUAD_PYTHON_INSTALL_DIR "lib/python3/dist-packages/tquad"
    CACHE STRING "Where the tquad module installs, under the prefix (Debian's python3)")
set(TQUAD_FREECAD_MOD_DIR "share/freecad/Mod/TemplateQuad"
    CACHE STRING "Where the workbench installs, under the prefix (FreeCAD's system Mod folder)")

install(TARGETS tquad RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# bin/ and lib/templatequad/ side by side, as in the build tree (cad_input_loader.cpp).
install(TARGETS tquad_cad tquad_step tquad_iges LIBRARY DESTINATION lib/templatequad)
install(TARGETS tquad_python LIBRARY DESTINATION ${TQUAD_PYTHON_INSTALL_DIR})
install(FILES src/python/tquad/__init__.py src/python/tquad/__init__.pyi src/python/tquad/py.typed
        DESTINATION ${TQUAD_PYTHON_INSTALL_DIR})
install(FILES package.xml LICENSE DESTINATION ${TQUAD_FREECAD_MOD_DIR})
install(DIRECTORY freecad_workbench/freecad freecad_workbench/resources
        DESTINATION ${TQUAD_FREECAD_MOD_DIR}/freecad_workbench
        PATTERN "__pycache__" EXCLUDE)
install(FILES freecad_workbench/README.md DESTINATION ${TQUAD_FREECAD_MOD_DIR}/freecad_workbench)
install(FILES LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/templatequad RENAME copyright)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME templatequad)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "TemplateQuad contributors")
set(CPACK_PACKAGE_CONTACT "TemplateQuad contributors <maintainers@users.noreply.h-seed-c6177c92.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "all-quadrilateral FEM meshes of CAD faces, with a FreeCAD workbench")
set(CPACK_PACKAGE_DESCRIPTION
    "TemplateQuad meshes the faces of CAD parts (STEP, IGES, BREP) into conforming\n"
    "all-quadrilateral meshes by hierarchical templates: the tquad command, the tquad\n"
    "Python module and the TemplateQuad workbench of FreeCAD's FEM.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The OpenCASCADE and C++ runtime libraries come from dpkg-shlibdeps; the module
# needs numpy; FreeCAD is only recommended (the command and module work without it).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3 (>= 3.11), python3 (<< 3.12), python3-numpy")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "freecad, calculix-ccx")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
include(CPack)
