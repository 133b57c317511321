# The install tree and the Debian package.
#
# `cmake --install <build> --prefix <dir>` makes a tree that runs from
# anywhere: the programs in bin/, the data they ship in share/neptus-qt/ (found
# beside bin/, engine/core/DataFiles.h), a desktop entry. The QML modules are
# compiled into the programs. `cpack -G DEB` (in the build folder) packs that
# tree for Debian 13: library dependencies found by dpkg-shlibdeps, and the
# run-time packages no library names (QML modules, Qt plugins) from
# tools/runtime-packages.txt.
include(GNUInstallDirs)

install(TARGETS neptus neptus-msg neptus-sim neptus-model-import neptus-script-host neptus-xslt neptus-mission neptus-log neptus-logd RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
foreach(entry ${NEPTUS_DATA_FOLDERS})
  string(REPLACE ":" ";" entry "${entry}")
  list(GET entry 0 source)
  list(GET entry 1 target)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${source}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/neptus-qt/${target})
endforeach()
install(FILES ${PROJECT_SOURCE_DIR}/tools/neptus-qt.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
# DDS Security keys (docs/dds-security.md); finds share/neptus-qt/msgdefs beside bin/.
install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/dds-keys DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME neptus-dds-keys)

file(STRINGS ${PROJECT_SOURCE_DIR}/tools/runtime-packages.txt runtime_lines)
set(runtime_packages "")
foreach(line ${runtime_lines})
  string(REGEX REPLACE "#.*" "" line "${line}")
  string(STRIP "${line}" line)
  if(line)
    list(APPEND runtime_packages ${line})
  endif()
endforeach()
list(JOIN runtime_packages ", " runtime_depends)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME neptus-qt)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "Neptus-Qt developers <neptus-qt@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "A console for the whole life cycle of missions run by teams of unmanned vehicles: IMC over UDP and Cyclone DDS, a variable tree, alarms and alarm scripts, maps, 3D, consoles as QML files.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${runtime_depends}")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "openssl") # neptus-dds-keys
set(CPACK_STRIP_FILES ON)
include(CPack)
