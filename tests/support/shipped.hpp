#pragma once
// The scenes and cases shipped in scenes/, as the tests read them.

#include "formats/scene_file.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace impulse::test {

// `name` relative to scenes/, without ".json": "stack_3", "cases/ruler".
inline Scene shipped(const std::string& name) {
    std::ifstream in(IMPULSE_SOURCE_DIR "/scenes/" + name + ".json");
    std::stringstream text;
    text << in.rdbuf();
    return formats::read_scene_text(text.str());
}

}  // namespace impulse::test
