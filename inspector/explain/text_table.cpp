#include "explain/text_table.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace impulse::explain {

std::size_t display_width(std::string_view text) {
    std::size_t width = 0;
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        char32_t code = 0;
        if (length == 2 && i + 1 < text.size())
            code = (char32_t(lead & 0x1F) << 6) | char32_t(static_cast<unsigned char>(text[i + 1]) & 0x3F);
        const bool combining = code >= 0x300 && code <= 0x36F;  // combining diacritical marks
        if (!combining) ++width;
        i += length;
    }
    return width;
}

namespace {

std::vector<std::string_view> lines_of(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    for (std::size_t nl = text.find('\n'); nl != std::string_view::npos; nl = text.find('\n', start)) {
        lines.push_back(text.substr(start, nl - start));
        start = nl + 1;
    }
    lines.push_back(text.substr(start));
    return lines;
}

void pad(std::string& line, std::string_view text, std::size_t width) {
    line += text;
    for (std::size_t w = display_width(text); w < width; ++w) line += ' ';
}

}  // namespace

void write_table(std::ostream& out, const StepTable& table, std::string_view indent) {
    constexpr std::array<std::string_view, 5> headers{"quantity", "value", "formula", "eq.", "meaning"};
    std::array<std::size_t, 5> width{};
    for (std::size_t c = 0; c < headers.size(); ++c) width[c] = display_width(headers[c]);
    for (const Row& row : table.rows) {
        const std::array<const std::string*, 5> cells{&row.quantity, &row.value, &row.formula, &row.equation,
                                                      &row.meaning};
        for (std::size_t c = 0; c < cells.size(); ++c)
            for (std::string_view line : lines_of(*cells[c])) width[c] = std::max(width[c], display_width(line));
    }
    out << table.title << '\n';
    const auto write_line = [&](const std::array<std::string_view, 5>& cells) {
        std::string line(indent);
        for (std::size_t c = 0; c < cells.size(); ++c) {
            pad(line, cells[c], c + 1 == cells.size() ? 0 : width[c]);
            line += "  ";
        }
        line.erase(line.find_last_not_of(' ') + 1);
        out << line << '\n';
    };
    write_line(headers);
    for (const Row& row : table.rows) {
        const std::vector<std::string_view> value_lines = lines_of(row.value);
        for (std::size_t l = 0; l < value_lines.size(); ++l) {
            if (l == 0)
                write_line({row.quantity, value_lines[l], row.formula, row.equation, row.meaning});
            else
                write_line({"", value_lines[l], "", "", ""});
        }
    }
}

std::string aligned_columns(const std::vector<std::vector<std::string>>& rows) {
    std::vector<std::size_t> widths;
    for (const auto& row : rows)
        for (std::size_t i = 0; i < row.size(); ++i) {
            if (widths.size() <= i) widths.push_back(0);
            widths[i] = std::max(widths[i], display_width(row[i]));
        }
    std::string text;
    for (const auto& row : rows) {
        std::string line;
        for (std::size_t i = 0; i < row.size(); ++i) {
            line += row[i];
            if (i + 1 < row.size()) line += std::string(widths[i] - display_width(row[i]) + 2, ' ');
        }
        while (!line.empty() && line.back() == ' ') line.pop_back();
        text += line + '\n';
    }
    return text;
}

}  // namespace impulse::explain
