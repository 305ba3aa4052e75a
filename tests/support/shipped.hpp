#pragma once
// The scenes and cases shipped in scenes/, as the tests read them.

#include "formats/scene_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace impulse::test {

inline const std::string shipped_scenes = IMPULSE_SOURCE_DIR "/scenes/";
inline const std::string cases = shipped_scenes + "cases/";
inline const std::string ruler = cases + "ruler.json";  // the case most tests of files and commands open
inline const std::filesystem::path shipped_lessons = IMPULSE_SOURCE_DIR "/lessons";

// `name` relative to scenes/, without ".json": "stack_3", "cases/ruler".
inline Scene shipped(const std::string& name) {
    std::ifstream in(shipped_scenes + name + ".json");
    std::stringstream text;
    text << in.rdbuf();
    return formats::read_scene_text(text.str());
}

}  // namespace impulse::test
