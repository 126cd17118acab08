# What `cmake --install build --prefix P` puts under P, and the Debian package built from it (cpack -G DEB in
# the build folder); docs/install.md describes the layout:
#   bin/                      radx, radx-starter, radx-engine
#   share/radx/decks/         the embedded default deck's source folder (RADX_DEFAULT_DECK_DIR of apps/)
#   share/radx/paraview/      the ParaView scripts of scripts/paraview/, when the folder has any
#   share/doc/radx/           README.md, LICENSE and docs/
#   include/radx/, lib/       the libraries and their headers, for another CMake project:
#   lib/cmake/radx/           find_package(radx) -> radx::model, radx::parser, radx::solver, radx::contact,
#                             radx::io (and radx::options, the include path they share)
# Nothing installed is read from the source or build tree at run time: the default deck and the energy-plot
# script are compiled into the executables; the energy chart runs /usr/bin/python3 with matplotlib.
include(CMakePackageConfigHelpers)
# `cmake --install` and cpack take what the build made and build nothing themselves: the test suite installs
# and packages while other tests run the executables of the same build folder.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

install(TARGETS radx radx-starter radx-engine RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

# The folder of the deck compiled into the executables, as apps/CMakeLists.txt names it.
get_directory_property(RADX_DEFAULT_DECK_DIR DIRECTORY ${PROJECT_SOURCE_DIR}/apps DEFINITION RADX_DEFAULT_DECK_DIR)
install(DIRECTORY ${RADX_DEFAULT_DECK_DIR} DESTINATION ${CMAKE_INSTALL_DATADIR}/radx/decks)
# Globbed at build time too (CONFIGURE_DEPENDS): the folder may not exist yet, and a script added to it is
# installed without a manual reconfigure.
file(GLOB RADX_PARAVIEW_SCRIPTS LIST_DIRECTORIES false CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/scripts/paraview/*)
if(RADX_PARAVIEW_SCRIPTS)
  install(FILES ${RADX_PARAVIEW_SCRIPTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/radx/paraview)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The libraries, named radx::<what> for a consumer. radx_options carries the include path (include/radx,
# where the headers keep their paths from the repository root) and nothing else outside this build.
set(RADX_EXPORTED_LIBRARIES radx_options radx_model radx_parser radx_solver radx_contact radx_io)
foreach(lib IN LISTS RADX_EXPORTED_LIBRARIES)
  string(REPLACE "radx_" "" export_name ${lib})
  set_target_properties(${lib} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
install(TARGETS ${RADX_EXPORTED_LIBRARIES} EXPORT radxTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/radx)
foreach(dir IN ITEMS solver parser contact io)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/radx/${dir}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
set(RADX_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/radx)
install(EXPORT radxTargets NAMESPACE radx:: DESTINATION ${RADX_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/radxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/radxConfig.cmake INSTALL_DESTINATION ${RADX_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/radxConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/radxConfig.cmake ${PROJECT_BINARY_DIR}/radxConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/FindCHOLMOD.cmake ${PROJECT_SOURCE_DIR}/cmake/FindMETIS.cmake DESTINATION ${RADX_CMAKE_DIR})

# The Debian package: one package, radx, with all of the above under /usr. Its Depends come from the
# executables' shared libraries (dpkg-shlibdeps: libhdf5, CHOLMOD, libstdc++, ...); the energy chart needs
# Python's matplotlib (a run without it warns and writes the CSV only), and building against the libraries
# needs the -dev packages of their dependencies.
set(CPACK_PACKAGE_NAME radx)
set(CPACK_PACKAGE_VENDOR radx)
set(CPACK_PACKAGE_CONTACT "radx maintainers <radx@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libeigen3-dev, libhdf5-dev, libmetis-dev, libsuitesparse-dev, python3-paraview")
include(CPack)
