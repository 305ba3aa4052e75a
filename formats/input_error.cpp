#include "formats/input_error.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

namespace impulse::formats {

namespace {
std::string join(const std::string& where, const std::string& problem) {
    return where.empty() ? problem : where + ": " + problem;
}
}  // namespace

InputError::InputError(std::string where, std::string problem)
    : std::runtime_error(join(where, problem)), where_(std::move(where)), problem_(std::move(problem)) {}

std::string json_path_child(std::string_view parent, std::string_view key) {
    std::string path(parent);
    if (!path.empty()) path += '.';
    path += key;
    return path;
}

std::string json_path_index(std::string_view parent, std::size_t index) {
    return std::string(parent) + '[' + std::to_string(index) + ']';
}

std::string number_text(double value) {
    if (std::isnan(value)) return "nan";  // JSON has no word for these: its dump would say null
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    std::string text = nlohmann::json(value).dump();
    if (text.size() > 2 && text.compare(text.size() - 2, 2, ".0") == 0) text.resize(text.size() - 2);
    return text;
}

}  // namespace impulse::formats
