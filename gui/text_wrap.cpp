#include "gui/text_wrap.hpp"

#include <imgui.h>

#include <algorithm>
#include <cctype>

namespace impulse::gui {

namespace {

float width_of(std::string_view text) {
    return ImGui::CalcTextSize(text.data(), text.data() + text.size()).x;
}

bool has_digit(std::string_view word) {
    return std::any_of(word.begin(), word.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

// Bytes of the UTF-8 character starting at `c`.
std::size_t char_length(unsigned char c) {
    return c < 0x80 ? 1 : c < 0xE0 ? 2 : c < 0xF0 ? 3 : 4;
}

void wrap_paragraph(std::string_view text, float width, std::vector<std::string>& lines) {
    std::string line;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(' ', start), text.size());
        std::string_view word = text.substr(start, end - start);
        start = end + 1;
        if (word.empty()) {
            if (end == text.size()) break;
            continue;
        }
        const std::string candidate = line.empty() ? std::string(word) : line + " " + std::string(word);
        if (width_of(candidate) <= width || line.empty()) {
            line = candidate;
        } else {
            lines.push_back(line);
            line = std::string(word);
        }
        // A word alone wider than the line: split between characters, unless it is a number.
        while (width_of(line) > width && !has_digit(line) && line.size() > 1) {
            std::size_t fit = 0;
            for (std::size_t i = 0; i < line.size();) {
                const std::size_t next = i + char_length(static_cast<unsigned char>(line[i]));
                if (i > 0 && width_of(std::string_view(line).substr(0, next)) > width) break;
                fit = next;
                i = next;
            }
            if (fit == 0 || fit >= line.size()) break;
            lines.push_back(line.substr(0, fit));
            line = line.substr(fit);
        }
        if (end == text.size()) break;
    }
    lines.push_back(line);
}

}  // namespace

std::vector<std::string> wrap_lines(std::string_view text, float width) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        wrap_paragraph(text.substr(start, end - start), std::max(width, 1.0f), lines);
        if (end == text.size()) break;
        start = end + 1;
    }
    return lines;
}

float wrapped_height(std::string_view text, float width) {
    return static_cast<float>(wrap_lines(text, width).size()) * ImGui::GetFontSize();
}

void wrapped_text(std::string_view text, float width) {
    if (width <= 0.0f) width = ImGui::GetContentRegionAvail().x;
    std::string joined;
    for (const std::string& line : wrap_lines(text, width)) joined += (joined.empty() ? "" : "\n") + line;
    ImGui::TextUnformatted(joined.c_str(), joined.c_str() + joined.size());
}

namespace {

template <typename Take>
float widest(std::string_view text, Take take) {
    float most = 0.0f;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find_first_of(" \n", start), text.size());
        const std::string_view word = text.substr(start, end - start);
        if (take(word)) most = std::max(most, width_of(word));
        start = end + 1;
    }
    return most;
}

}  // namespace

float widest_unbreakable(std::string_view text) {
    return widest(text, has_digit);
}

float widest_word(std::string_view text) {
    return widest(text, [](std::string_view) { return true; });
}

}  // namespace impulse::gui
