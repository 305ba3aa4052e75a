#pragma once
// A file's whole text, as a test reads back what a command wrote (empty if it cannot be opened: the checks on the
// text then fail, naming what was expected).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace impulse::test {

inline std::string read_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace impulse::test
