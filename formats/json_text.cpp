#include "formats/json_text.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <vector>

namespace impulse::formats {

namespace {

using json = nlohmann::ordered_json;

// Where the parser is inside the document, to name the path of a duplicate key.
struct Level {
    bool is_array;
    std::size_t index = 0;       // next element's index, for arrays
    std::string key;             // current key, for objects
    std::set<std::string> keys;  // keys seen so far, for objects
};

// The path of the innermost open level, or with `pending`, of the value being read inside it.
std::string path_of(const std::vector<Level>& levels, bool pending = false) {
    std::string path;
    for (std::size_t i = 0; i + (pending ? 0 : 1) < levels.size(); ++i) {
        const Level& level = levels[i];
        path = level.is_array ? json_path_index(path, level.index) : json_path_child(path, level.key);
    }
    return path;
}

// After a complete value inside an array, the next element gets the next index.
void value_done(std::vector<Level>& levels) {
    if (!levels.empty() && levels.back().is_array) ++levels.back().index;
}

}  // namespace

json parse_json_text(std::string_view text) {
    std::vector<Level> levels;
    const json::parser_callback_t track = [&levels](int depth, json::parse_event_t event, json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start:
                levels.push_back(Level{event == json::parse_event_t::array_start, 0, {}, {}});
                if (depth >= max_json_depth) {
                    levels.back().is_array = false;
                    throw InputError(path_of(levels),
                                     "nested too deeply (more than " + std::to_string(max_json_depth) + " levels)");
                }
                break;
            case json::parse_event_t::key: {
                Level& level = levels.back();
                level.key = parsed.get<std::string>();
                if (!level.keys.insert(level.key).second) {
                    levels.push_back(Level{false, 0, {}, {}});  // so path_of includes the key itself
                    throw InputError(path_of(levels), "key given twice in the same object");
                }
                break;
            }
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                levels.pop_back();
                value_done(levels);
                break;
            case json::parse_event_t::value:
                value_done(levels);
                break;
        }
        return true;
    };
    try {
        return json::parse(text.begin(), text.end(), track);
    } catch (const json::parse_error& e) {
        // nlohmann's own "line 3, column 0" can point past a newline it read ahead; its byte offset is the
        // offending character itself, so the position is counted from that.
        const std::size_t at = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
        const std::size_t line = 1 + static_cast<std::size_t>(std::count(
                                         text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
        const std::size_t line_start = text.rfind('\n', at == 0 ? 0 : at - 1);
        const std::size_t column = line_start == std::string_view::npos || at == 0 ? at + 1 : at - line_start;
        const std::string what = e.what();
        const std::size_t colon = what.find(": ", what.find("parse error"));
        throw InputError("", "invalid JSON at line " + std::to_string(line) + ", column " + std::to_string(column) +
                                 ": " + (colon == std::string::npos ? what : what.substr(colon + 2)));
    } catch (const json::out_of_range& e) {
        // A number too large for a double (1e999): nlohmann reports it as out_of_range, not as a parse error,
        // while the value's key or index is the one the parser is at.
        const std::string what = e.what();
        const std::size_t bracket = what.find("] ");
        throw InputError(path_of(levels, true),
                         "invalid JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
}

namespace {

bool is_scalar(const json& v) {
    return !v.is_object() && !v.is_array();
}

// Short arrays of scalars (vectors, quaternions) and arrays of them (matrices) print on one line.
bool is_flat_array(const json& v) {
    if (!v.is_array() || v.size() > 4) return false;
    return std::all_of(v.begin(), v.end(), [](const json& e) {
        return is_scalar(e) || (e.is_array() && e.size() <= 4 && std::all_of(e.begin(), e.end(), is_scalar));
    });
}

// Text read from CSV or Markdown is checked for UTF-8 when it is loaded; should any other bytes reach a string,
// they are written as U+FFFD rather than failing the whole file.
std::string scalar_text(const json& v) {
    return v.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string inline_array(const json& v) {
    std::string s = "[";
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (i > 0) s += ", ";
        s += v[i].is_array() ? inline_array(v[i]) : scalar_text(v[i]);
    }
    return s + "]";
}

void write(const json& v, int indent, std::string& out) {
    if (is_scalar(v)) {
        out += scalar_text(v);
        return;
    }
    if (v.empty()) {
        out += v.is_object() ? "{}" : "[]";
        return;
    }
    if (is_flat_array(v)) {
        out += inline_array(v);
        return;
    }
    const std::string inner(static_cast<std::size_t>(indent + 1) * 2, ' ');
    const bool object = v.is_object();
    out += object ? "{\n" : "[\n";
    std::size_t i = 0;
    for (auto it = v.begin(); it != v.end(); ++it, ++i) {
        out += inner;
        if (object) out += scalar_text(json(it.key())) + ": ";
        write(*it, indent + 1, out);
        out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(static_cast<std::size_t>(indent) * 2, ' ') + (object ? "}" : "]");
}

}  // namespace

std::string format_json(const json& value) {
    std::string out;
    write(value, 0, out);
    out += '\n';
    return out;
}

std::optional<std::size_t> first_non_utf8_byte(std::string_view text) {
    std::size_t at = 0;
    while (at < text.size()) {
        const auto lead = static_cast<unsigned char>(text[at]);
        // Sequence length from the lead byte, and the range its first continuation byte may take (which rules out
        // overlong forms, surrogates and code points past U+10FFFF).
        std::size_t length = 1;
        unsigned char low = 0x80, high = 0xBF;
        if (lead < 0x80)
            length = 1;
        else if (lead >= 0xC2 && lead <= 0xDF)
            length = 2;
        else if (lead == 0xE0)
            length = 3, low = 0xA0;
        else if (lead >= 0xE1 && lead <= 0xEC)
            length = 3;
        else if (lead == 0xED)
            length = 3, high = 0x9F;
        else if (lead >= 0xEE && lead <= 0xEF)
            length = 3;
        else if (lead == 0xF0)
            length = 4, low = 0x90;
        else if (lead >= 0xF1 && lead <= 0xF3)
            length = 4;
        else if (lead == 0xF4)
            length = 4, high = 0x8F;
        else
            return at;
        for (std::size_t k = 1; k < length; ++k) {
            if (at + k >= text.size()) return at;
            const auto next = static_cast<unsigned char>(text[at + k]);
            if (next < (k == 1 ? low : 0x80) || next > (k == 1 ? high : 0xBF)) return at;
        }
        at += length;
    }
    return std::nullopt;
}

void require_utf8(std::string_view text) {
    const std::optional<std::size_t> bad = first_non_utf8_byte(text);
    if (!bad) return;
    const std::string_view before = text.substr(0, *bad);
    const std::size_t line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t line_start = before.rfind('\n');
    const std::size_t column = line_start == std::string_view::npos ? *bad + 1 : *bad - line_start;
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[*bad])));
    throw InputError("line " + std::to_string(line),
                     "not UTF-8 text: byte " + std::string(byte) + " at column " + std::to_string(column));
}

}  // namespace impulse::formats
