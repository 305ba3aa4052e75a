#include "formats/json_text.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <cstdio>

namespace impulse::formats {

namespace {

using json = nlohmann::ordered_json;

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

void append_json(const json& value, int indent, std::string& out) {
    write(value, indent, out);
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
