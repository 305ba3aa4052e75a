#pragma once
// A file's whole text, as a test reads back what a command wrote (empty if it cannot be opened: the checks on the
// text then fail, naming what was expected), and whether a text has a part.

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

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace impulse::test
