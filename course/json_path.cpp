#include "course/json_path.hpp"

#include "formats/input_error.hpp"

#include <charconv>
#include <limits>

namespace impulse::course {

bool key_at(const std::vector<PathToken>& path, std::size_t i, std::string_view key) {
    const auto* k = i < path.size() ? std::get_if<std::string>(&path[i]) : nullptr;
    return k && *k == key;
}

std::optional<std::size_t> index_at(const std::vector<PathToken>& path, std::size_t i) {
    if (i >= path.size() || !std::holds_alternative<std::size_t>(path[i])) return std::nullopt;
    return std::get<std::size_t>(path[i]);
}

namespace {

bool is_key_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

[[noreturn]] void malformed(std::string_view path, std::string_view where, const std::string& why) {
    throw formats::InputError(std::string(where), "\"" + std::string(path) +
                                                      "\" is not a path such as "
                                                      "frames[0].contacts[0].basis[1]: " +
                                                      why);
}

}  // namespace

std::vector<PathToken> parse_json_path(std::string_view path, std::string_view where) {
    std::vector<PathToken> tokens;
    if (path.empty()) malformed(path, where, "it is empty");
    std::size_t at = 0;
    while (at < path.size()) {
        if (path[at] == '[') {
            const std::size_t close = path.find(']', at);
            if (close == std::string_view::npos) malformed(path, where, "a '[' is not closed");
            const std::string_view digits = path.substr(at + 1, close - at - 1);
            std::size_t index = 0;
            const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
            if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
                malformed(path, where, "\"[" + std::string(digits) + "]\" is not an index");
            tokens.emplace_back(index);
            at = close + 1;
            continue;
        }
        if (path[at] == '.') {
            if (tokens.empty() || at + 1 == path.size()) malformed(path, where, "a '.' has no key on one side");
            ++at;
        } else if (!tokens.empty()) {
            malformed(path, where, "a key must follow '.'");
        }
        const std::size_t start = at;
        while (at < path.size() && is_key_char(path[at])) ++at;
        if (at == start) malformed(path, where, "'" + std::string(1, path[at]) + "' cannot start a key");
        tokens.emplace_back(std::string(path.substr(start, at - start)));
    }
    return tokens;
}

const formats::json* value_at(const formats::json& document, const std::vector<PathToken>& tokens) {
    const formats::json* here = &document;
    for (const PathToken& token : tokens) {
        if (const auto* key = std::get_if<std::string>(&token)) {
            if (!here->is_object()) return nullptr;
            const auto found = here->find(*key);
            if (found == here->end()) return nullptr;
            here = &*found;
        } else {
            const std::size_t index = std::get<std::size_t>(token);
            if (!here->is_array() || index >= here->size()) return nullptr;
            here = &(*here)[index];
        }
    }
    return here;
}

std::vector<std::size_t> document_position(const formats::json& document, const std::vector<PathToken>& tokens) {
    constexpr std::size_t absent = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> position;
    const formats::json* here = &document;
    for (const PathToken& token : tokens) {
        if (!here) {
            position.push_back(absent);
            continue;
        }
        if (const auto* key = std::get_if<std::string>(&token)) {
            std::size_t order = 0;
            const formats::json* next = nullptr;
            if (here->is_object())
                for (auto it = here->begin(); it != here->end(); ++it, ++order)
                    if (it.key() == *key) {
                        next = &it.value();
                        break;
                    }
            position.push_back(next ? order : absent);
            here = next;
        } else {
            const std::size_t index = std::get<std::size_t>(token);
            position.push_back(index);
            here = here->is_array() && index < here->size() ? &(*here)[index] : nullptr;
        }
    }
    return position;
}

}  // namespace impulse::course
