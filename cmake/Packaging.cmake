# The Debian packages CPack makes from the install rules (cmake/Install.cmake):
#   cmake --build build/default --target package     (or: cd build/default && cpack -G DEB)
# gives impulse-lab_<version>_<arch>.deb (component Runtime: the program, its data, manual page and completion)
# and impulse-lab-dev_<version>_<arch>.deb (component Development: the engine and formats libraries, headers
# and the CMake package), both installing under /usr.

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME impulse-lab)
set(CPACK_PACKAGE_VENDOR "Impulse Lab contributors")
set(CPACK_PACKAGE_CONTACT "Impulse Lab maintainers <maintainers@users.noreply.h-seed-c81a80f4.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${CMAKE_BINARY_DIR}/packages)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # name_version_arch.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)

# The program: its shared libraries' packages found by dpkg-shlibdeps (SDL2, stb, the C++ runtime); the fonts
# that show Greek letters and maths symbols are recommended (without them the window says so and shows '?').
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME impulse-lab)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS "bash-completion")
# Rendering (the window, and headless PNGs through SDL's offscreen driver) loads EGL and Mesa at run time, which
# dpkg-shlibdeps cannot see.
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libegl1, libgl1-mesa-dri")
# The synopsis is CPACK_PACKAGE_DESCRIPTION_SUMMARY; these are the lines under it.
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION
    "impulse-lab resolves contacts the way chapter 14 of Millington's Game Physics Engine Development does, and
other ways (PGS, split impulse, soft step), and shows every intermediate value of every contact beside its
formula and equation. With a course of fourteen lessons, shipped scenes and cases, and coursework tools.")

# The libraries are static: a consumer compiles against the headers of Eigen and nlohmann-json.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME impulse-lab-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libeigen3-dev (>= 3.4), nlohmann-json3-dev (>= 3.11)")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION
    "The engine of impulse-lab as static libraries with headers: impulse::engine (bodies, contacts, the
chapter's derivation steps, the methods, the world and the recorder) and impulse::formats (scene, case and
trace JSON), with a CMake package: find_package(impulse-lab).")

# `--target package_source`: the source tree as a tarball, without build folders and git's files.
set(CPACK_SOURCE_GENERATOR TXZ)
set(CPACK_SOURCE_IGNORE_FILES "/build/" "/\\.git" "/\\.cache/")

include(CPack)
