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

std::vector<std::string> wrap_words(std::string_view text, std::size_t width) {
    std::vector<std::string> lines;
    for (std::string_view paragraph : lines_of(text)) {
        std::string line;
        std::size_t start = 0;
        while (start <= paragraph.size()) {
            const std::size_t end = std::min(paragraph.find(' ', start), paragraph.size());
            const std::string_view word = paragraph.substr(start, end - start);
            start = end + 1;
            if (word.empty()) {
                if (end == paragraph.size()) break;
                continue;
            }
            if (!line.empty() && display_width(line) + 1 + display_width(word) > width) {
                lines.push_back(line);
                line.clear();
            }
            line += (line.empty() ? "" : " ") + std::string(word);
            if (end == paragraph.size()) break;
        }
        lines.push_back(line);
    }
    return lines;
}

namespace {

std::size_t widest_word(std::string_view text) {
    std::size_t widest = 0;
    for (std::string_view line : lines_of(text)) {
        std::size_t start = 0;
        while (start <= line.size()) {
            const std::size_t end = std::min(line.find(' ', start), line.size());
            widest = std::max(widest, display_width(line.substr(start, end - start)));
            start = end + 1;
        }
    }
    return widest;
}

// Each row as "quantity  value" and, indented below, "formula  eq. — meaning": for a terminal too narrow for the
// columns side by side.
void write_stacked(std::ostream& out, const StepTable& table, std::string_view indent, std::size_t width) {
    const std::string pad(indent);
    std::size_t name_width = 0;
    for (const Row& row : table.rows) name_width = std::max(name_width, display_width(row.quantity));
    name_width = std::min(name_width, width / 2);
    const std::size_t value_column = pad.size() + name_width + 2;
    const std::size_t value_width = width > value_column + 8 ? width - value_column : 8;
    out << table.title << '\n' << pad << "quantity  value\n" << pad << "    formula  eq. — meaning\n";
    for (const Row& row : table.rows) {
        std::string line = pad + row.quantity;
        const std::vector<std::string> value = wrap_words(row.value, value_width);
        std::size_t first = 0;
        if (display_width(row.quantity) <= name_width) {
            for (std::size_t w = display_width(row.quantity); w < name_width + 2; ++w) line += ' ';
            line += value.front();
            first = 1;
        }
        out << line << '\n';
        for (std::size_t i = first; i < value.size(); ++i) out << std::string(value_column, ' ') << value[i] << '\n';
        std::string detail = row.formula;
        // The equation in parentheses after the formula ("(14.3)", "(ch. 15)"), so it reads apart from it.
        const std::string equation =
            row.equation.empty() || row.equation.front() == '(' ? row.equation : "(" + row.equation + ")";
        if (!equation.empty()) detail += (detail.empty() ? "" : " ") + equation;
        if (!row.meaning.empty()) detail += (detail.empty() ? "" : " — ") + row.meaning;
        if (detail.empty()) continue;
        const std::string detail_pad = pad + "    ";
        for (const std::string& l : wrap_words(detail, width > detail_pad.size() + 8 ? width - detail_pad.size() : 8))
            out << detail_pad << l << '\n';
    }
}

}  // namespace

void write_table(std::ostream& out, const StepTable& table, std::string_view indent, std::size_t width) {
    constexpr std::array<std::string_view, 5> headers{"quantity", "value", "formula", "eq.", "meaning"};
    std::array<std::size_t, 5> natural{}, least{};
    for (std::size_t c = 0; c < headers.size(); ++c) natural[c] = least[c] = display_width(headers[c]);
    for (const Row& row : table.rows) {
        const std::array<const std::string*, 5> cells{&row.quantity, &row.value, &row.formula, &row.equation,
                                                      &row.meaning};
        for (std::size_t c = 0; c < cells.size(); ++c) {
            for (std::string_view line : lines_of(*cells[c])) natural[c] = std::max(natural[c], display_width(line));
            // The quantity and the equation are never wrapped, nor a single value and its unit ("7.5 m/s"); the
            // rest at their words.
            const bool whole =
                c == 0 || c == 3 ||
                (c == 1 && cells[c]->find_first_of("([\n") == std::string::npos && !cells[c]->starts_with("?"));
            std::size_t cell = 0;
            for (std::string_view line : lines_of(*cells[c])) cell = std::max(cell, display_width(line));
            least[c] = std::max(least[c], whole ? cell : widest_word(*cells[c]));
        }
    }
    const std::size_t gaps = indent.size() + 2 * (headers.size() - 1);
    std::size_t total = gaps;
    for (std::size_t n : natural) total += n;
    if (width == 0 || total <= width) {
        write_table(out, table, indent);
        return;
    }
    std::size_t least_total = gaps;
    for (std::size_t n : least) least_total += n;
    // Formula and meaning need a few words a line to read as columns.
    if (least_total + 24 > width) {
        write_stacked(out, table, indent, width);
        return;
    }
    // From the least widths, the room left goes to the value, the formula and the meaning by what each lacks.
    std::array<std::size_t, 5> w = least;
    std::size_t spare = width - least_total, lacking = 0;
    for (std::size_t c : {1u, 2u, 4u}) lacking += natural[c] - least[c];
    for (std::size_t c : {1u, 2u, 4u}) {
        const std::size_t grow =
            lacking ? std::min(natural[c] - least[c], spare * (natural[c] - least[c]) / lacking) : 0;
        w[c] += grow;
    }
    out << table.title << '\n';
    const auto write_lines = [&](const std::array<std::vector<std::string>, 5>& cells) {
        std::size_t lines = 0;
        for (const auto& c : cells) lines = std::max(lines, c.size());
        for (std::size_t l = 0; l < lines; ++l) {
            std::string line(indent);
            for (std::size_t c = 0; c < cells.size(); ++c) {
                const std::string cell = l < cells[c].size() ? cells[c][l] : std::string();
                pad(line, cell, c + 1 == cells.size() ? 0 : w[c]);
                line += "  ";
            }
            line.erase(line.find_last_not_of(' ') + 1);
            out << line << '\n';
        }
    };
    std::array<std::vector<std::string>, 5> header_cells;
    for (std::size_t c = 0; c < headers.size(); ++c) header_cells[c] = {std::string(headers[c])};
    write_lines(header_cells);
    for (const Row& row : table.rows)
        write_lines({std::vector<std::string>{row.quantity}, wrap_words(row.value, w[1]), wrap_words(row.formula, w[2]),
                     std::vector<std::string>{row.equation}, wrap_words(row.meaning, w[4])});
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
