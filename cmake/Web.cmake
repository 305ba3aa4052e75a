# The web preset: everything compiled to WebAssembly by Debian's emscripten (docs/design.md, "The browser").
# Included by the top-level CMakeLists.txt when the toolchain is emscripten's.

# C++ exceptions carry every input error (InputError) to the place that reports it. emscripten 3.1.6's prebuilt
# libraries (Debian's frozen cache) have exceptions in JavaScript's style, not WebAssembly's.
add_compile_options(-fexceptions)
add_link_options(-fexceptions)

# nlohmann-json's CMake package puts /usr/include on the include path, where the host's C library would come before
# emscripten's own: a folder of the build that holds nothing but nlohmann's headers takes its place.
# The package's folder is PREFIX/share/cmake/nlohmann_json; its headers are PREFIX/include/nlohmann.
get_filename_component(impulse_nlohmann_prefix ${nlohmann_json_DIR}/../../.. ABSOLUTE)
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/host-headers)
file(CREATE_LINK ${impulse_nlohmann_prefix}/include/nlohmann ${CMAKE_BINARY_DIR}/host-headers/nlohmann SYMBOLIC)
set_target_properties(nlohmann_json::nlohmann_json PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
                                                              ${CMAKE_BINARY_DIR}/host-headers)

# What emscripten 3.1.6's libc++ 13 lacks of C++20 and the code uses, written to the standard (web/compat).
include_directories(BEFORE ${PROJECT_SOURCE_DIR}/web/compat)

# emscripten's JavaScript optimiser needs Debian's node-acorn (/usr/share/nodejs), which Debian's node finds by itself
# and a node from elsewhere does not: then the links are run with NODE_PATH naming that folder.
execute_process(COMMAND ${NODE_JS_EXECUTABLE} -e "require('acorn')" RESULT_VARIABLE impulse_acorn_missing
                OUTPUT_QUIET ERROR_QUIET)
if(impulse_acorn_missing AND EXISTS /usr/share/nodejs/acorn)
  set(CMAKE_CXX_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
endif()

include(${PROJECT_SOURCE_DIR}/web/imgui.cmake)  # imgui_web, stb_write_web
