# Dear ImGui 1.86 for the web preset: its core and its OpenGL3 backend, compiled from Debian's `imgui` source package
# (libimgui-dev ships them only as an x86-64 library). scripts/install-deps unpacks it into debian-sources/, which git
# ignores; -DIMPULSE_IMGUI_SOURCE_DIR=FOLDER names another copy. The backend draws with OpenGL ES 3 (WebGL 2).
file(GLOB impulse_imgui_candidates ${PROJECT_SOURCE_DIR}/debian-sources/imgui-*/imgui.cpp)
set(impulse_imgui_default "")
if(impulse_imgui_candidates)
  list(GET impulse_imgui_candidates 0 impulse_imgui_first)
  get_filename_component(impulse_imgui_default ${impulse_imgui_first} DIRECTORY)
endif()
set(IMPULSE_IMGUI_SOURCE_DIR "${impulse_imgui_default}" CACHE PATH
    "Dear ImGui's sources: Debian's imgui source package, unpacked (scripts/install-deps puts it in debian-sources/)")
if(NOT EXISTS "${IMPULSE_IMGUI_SOURCE_DIR}/imgui.cpp")
  message(FATAL_ERROR "Dear ImGui's sources are missing: scripts/install-deps fetches Debian's imgui source package "
                      "into debian-sources/ (or name a copy with -DIMPULSE_IMGUI_SOURCE_DIR=FOLDER)")
endif()
set(imgui_dir ${IMPULSE_IMGUI_SOURCE_DIR})
add_library(imgui_web STATIC ${imgui_dir}/imgui.cpp ${imgui_dir}/imgui_draw.cpp ${imgui_dir}/imgui_tables.cpp
                             ${imgui_dir}/imgui_widgets.cpp ${imgui_dir}/backends/imgui_impl_opengl3.cpp)
target_include_directories(imgui_web SYSTEM PUBLIC ${imgui_dir} ${imgui_dir}/backends)
target_compile_definitions(imgui_web PUBLIC IMGUI_IMPL_OPENGL_ES3)
target_compile_options(imgui_web PRIVATE -w)  # third-party code: its warnings are not ours to fix

# stb's PNG writer (screenshots): Debian's libstb-dev header, whose implementation the desktop takes from libstb.so
# and the page compiles here.
add_library(stb_write_web STATIC ${PROJECT_SOURCE_DIR}/web/stb_image_write.cpp)
target_include_directories(stb_write_web SYSTEM PUBLIC /usr/include/stb)
target_compile_options(stb_write_web PRIVATE -w)
