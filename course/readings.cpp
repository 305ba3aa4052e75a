#include "course/readings.hpp"

#include "formats/input_error.hpp"

namespace impulse::course {

namespace {

constexpr std::string_view open_mark = "{{", close_mark = "}}";

}  // namespace

std::string reading(std::string_view text, Reading which) {
    std::string out;
    std::size_t start = 0;
    for (std::size_t open = text.find(open_mark); open != std::string_view::npos; open = text.find(open_mark, start)) {
        const std::size_t close = text.find(close_mark, open);
        const std::size_t bar = text.find('|', open);
        if (close == std::string_view::npos || bar == std::string_view::npos || bar > close) break;
        out.append(text.substr(start, open - start));
        out.append(which == Reading::window ? text.substr(open + 2, bar - open - 2)
                                            : text.substr(bar + 1, close - bar - 1));
        start = close + close_mark.size();
    }
    out.append(text.substr(start));
    return out;
}

void check_readings(std::string_view text, const std::string& where) {
    std::size_t start = 0;
    while (true) {
        const std::size_t open = text.find(open_mark, start);
        const std::size_t stray = text.find(close_mark, start);
        if (stray != std::string_view::npos && (open == std::string_view::npos || stray < open))
            throw formats::InputError(where, "a }} without its {{ (two readings are written {{window|terminal}})");
        if (open == std::string_view::npos) return;
        const std::size_t close = text.find(close_mark, open);
        const std::string shown(text.substr(open, std::min<std::size_t>(40, text.size() - open)));
        if (close == std::string_view::npos)
            throw formats::InputError(where, "\"" + shown +
                                                 "\" has no closing }} (two readings are written "
                                                 "{{window|terminal}})");
        const std::size_t bar = text.find('|', open);
        if (bar == std::string_view::npos || bar > close)
            throw formats::InputError(where, "\"" + shown + "\" has no | between its window and terminal readings");
        if (text.find(open_mark, open + 2) < close)
            throw formats::InputError(where, "\"" + shown + "\": two readings cannot nest");
        start = close + close_mark.size();
    }
}

}  // namespace impulse::course
