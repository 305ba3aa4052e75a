# What `cmake --install` puts where, and the build folder's mirror of it. Every install rule of the project is in
# this file (the package made from them: cmake/Packaging.cmake); targets are named here, so moving their sources
# changes nothing below.
#
#   bin/impulse-lab                                  the program                          (component Runtime)
#   share/impulse-lab/{lessons,scenes,schemas,docs}  what it ships with                   (Runtime)
#   share/man/man1/impulse-lab.1                     the manual page, made by help2man    (Runtime)
#   share/bash-completion/completions/impulse-lab    bash completion                      (Runtime)
#   share/doc/impulse-lab/{README.md,LICENSE}                                             (Runtime)
#   lib/libimpulse_engine.a, lib/libimpulse_formats.a  the engine and its file formats    (Development)
#   include/impulse-lab/...                          their headers (#include "world/world.hpp",
#                                                    #include "formats/scene_file.hpp")
#   lib/cmake/impulse-lab/                           find_package(impulse-lab): impulse::engine, impulse::formats
#
# The program finds share/impulse-lab from its own location, bin/../share/impulse-lab (cli/data_folder.hpp), so
# the program and its data are installed under one prefix and the tree can be moved as a whole.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Fixed, not CMAKE_INSTALL_BINDIR/DATADIR: the program looks for its data at exactly ../share/impulse-lab.
set(IMPULSE_BIN_DESTINATION bin)
set(IMPULSE_DATA_DESTINATION share/impulse-lab)
set(IMPULSE_INCLUDE_DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/impulse-lab)
set(IMPULSE_CMAKE_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/impulse-lab)
set(IMPULSE_DATA_FOLDERS lessons scenes schemas docs)

# The build folder has the installed layout too: build/<preset>/share/impulse-lab holds links to the source tree's
# folders (relative links, so a checkout moved with its build folder still works), which is how a program run
# from build/<preset>/bin finds the checkout's lessons by the same rule as an installed one.
set(build_data_folder ${CMAKE_BINARY_DIR}/share/impulse-lab)
file(MAKE_DIRECTORY ${build_data_folder})
foreach(folder IN LISTS IMPULSE_DATA_FOLDERS)
  file(RELATIVE_PATH link_target ${build_data_folder} ${PROJECT_SOURCE_DIR}/${folder})
  file(REMOVE ${build_data_folder}/${folder})
  file(CREATE_LINK ${link_target} ${build_data_folder}/${folder} SYMBOLIC)
endforeach()

# The program and what it ships with (not in the engine-only build, which installs the libraries alone). The
# manual page and the completion script are generated into the build folder's share/ (cli/CMakeLists.txt), already
# in their installed layout.
if(NOT IMPULSE_ENGINE_ONLY)
install(TARGETS impulse-lab RUNTIME DESTINATION ${IMPULSE_BIN_DESTINATION} COMPONENT Runtime)
foreach(folder IN LISTS IMPULSE_DATA_FOLDERS)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${IMPULSE_DATA_DESTINATION} COMPONENT Runtime)
endforeach()
install(FILES ${CMAKE_BINARY_DIR}/share/man/man1/impulse-lab.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT Runtime)
install(FILES ${CMAKE_BINARY_DIR}/share/bash-completion/completions/impulse-lab DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        COMPONENT Runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/impulse-lab COMPONENT Runtime)
endif()

# The engine and its file formats as libraries with headers. The headers keep their folders under one include
# folder of their own, as the sources include them: the engine's by their folder inside engine/ ("world/world.hpp"),
# the formats' as "formats/name.hpp".
file(GLOB_RECURSE engine_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/engine/*.hpp)
target_sources(impulse_engine PUBLIC FILE_SET HEADERS BASE_DIRS ${PROJECT_SOURCE_DIR}/engine FILES ${engine_headers})
file(GLOB formats_headers CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/formats/*.hpp)
target_sources(impulse_formats PUBLIC FILE_SET HEADERS BASE_DIRS ${PROJECT_SOURCE_DIR} FILES ${formats_headers})

set_target_properties(impulse_engine PROPERTIES EXPORT_NAME engine)
set_target_properties(impulse_formats PROPERTIES EXPORT_NAME formats)
add_library(impulse::engine ALIAS impulse_engine)
add_library(impulse::formats ALIAS impulse_formats)

install(TARGETS impulse_engine impulse_formats EXPORT impulse-lab-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
        FILE_SET HEADERS DESTINATION ${IMPULSE_INCLUDE_DESTINATION} COMPONENT Development
        INCLUDES DESTINATION ${IMPULSE_INCLUDE_DESTINATION})
install(EXPORT impulse-lab-targets NAMESPACE impulse:: DESTINATION ${IMPULSE_CMAKE_DESTINATION}
        COMPONENT Development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/impulse-lab-config.cmake.in
                              ${CMAKE_BINARY_DIR}/cmake/impulse-lab-config.cmake
                              INSTALL_DESTINATION ${IMPULSE_CMAKE_DESTINATION})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/impulse-lab-config-version.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/impulse-lab-config.cmake
              ${CMAKE_BINARY_DIR}/cmake/impulse-lab-config-version.cmake
        DESTINATION ${IMPULSE_CMAKE_DESTINATION} COMPONENT Development)
