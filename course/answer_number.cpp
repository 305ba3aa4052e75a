#include "course/answer_number.hpp"

#include "formats/input_error.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>

namespace impulse::course {

namespace {

constexpr std::string_view minus_sign = "\u2212";  // −, as the tables print it and a student may paste it
constexpr std::string_view examples = "e.g. 3.2, -1.5e-2, 3,2 or 1/60";

bool digit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

void skip_spaces(std::string_view& s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
}

void refuse_marks(const std::string& shown) {
    throw formats::InputError("answer", "\"" + shown +
                                            "\" has more than one decimal mark: write the number with one point or "
                                            "one comma, without thousands separators");
}

// A decimal number at the start of `s` (consumed), written with a point or a comma; none when `s` does not start
// with one. A number with two decimal marks ("1,000.5") is refused rather than guessed at.
std::optional<double> take_decimal(std::string_view& s, const std::string& shown) {
    int marks = 0;
    std::string ascii;
    std::string_view rest = s;
    if (rest.starts_with(minus_sign)) {
        ascii += '-';
        rest.remove_prefix(minus_sign.size());
    } else if (!rest.empty() && (rest.front() == '-' || rest.front() == '+')) {
        if (rest.front() == '-') ascii += '-';
        rest.remove_prefix(1);
    }
    bool any_digit = false;
    while (!rest.empty() && (digit(rest.front()) || rest.front() == '.' || rest.front() == ',')) {
        if (rest.front() == '.' || rest.front() == ',') {
            ++marks;
            ascii += '.';
        } else {
            ascii += rest.front();
            any_digit = true;
        }
        rest.remove_prefix(1);
    }
    if (!any_digit) return std::nullopt;
    if (marks > 1) refuse_marks(shown);
    // An exponent only when digits follow it: "2 e" is a unit, not half an exponent.
    if (rest.size() >= 2 && (rest.front() == 'e' || rest.front() == 'E')) {
        std::size_t k = 1;
        if (rest[k] == '-' || rest[k] == '+') ++k;
        if (k < rest.size() && digit(rest[k])) {
            ascii += 'e';
            ascii.append(rest.substr(1, k - 1));
            rest.remove_prefix(k);
            while (!rest.empty() && digit(rest.front())) ascii += rest.front(), rest.remove_prefix(1);
        }
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(ascii.data(), ascii.data() + ascii.size(), value);
    if (error != std::errc() || end != ascii.data() + ascii.size()) return std::nullopt;
    s = rest;
    return value;
}

std::string replace_all(std::string text, std::string_view from, std::string_view to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

}  // namespace

std::string comparable_unit(std::string_view unit) {
    std::string u(unit);
    u = replace_all(u, "\u00b7", "");  // ·
    u = replace_all(u, "\u22c5", "");  // ⋅
    u = replace_all(u, "**", "^");
    u = replace_all(u, "^-1", "\u207b\u00b9");  // ⁻¹
    u = replace_all(u, "^2", "\u00b2");
    u = replace_all(u, "^3", "\u00b3");
    std::string out;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const char c = u[i];
        if (c == '*' || c == '.' || std::isspace(static_cast<unsigned char>(c))) continue;
        // "m/s2": a digit right after a letter is a power.
        if ((c == '2' || c == '3') && i > 0 && std::isalpha(static_cast<unsigned char>(u[i - 1]))) {
            out += c == '2' ? "\u00b2" : "\u00b3";
            continue;
        }
        out += c;
    }
    return out;
}

double read_answer_number(std::string_view typed, std::string_view unit) {
    std::string_view s = typed;
    skip_spaces(s);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    const std::string shown(s);
    if (s.empty()) throw formats::InputError("answer", std::string("type a number, ") + std::string(examples));
    std::optional<double> value = take_decimal(s, shown);
    if (!value)
        throw formats::InputError("answer",
                                  "\"" + shown + "\" is not a number: type a number, " + std::string(examples));
    // A fraction: "1/60", "-3 / 4".
    {
        std::string_view rest = s;
        skip_spaces(rest);
        if (rest.starts_with('/')) {
            rest.remove_prefix(1);
            skip_spaces(rest);
            if (const std::optional<double> denominator = take_decimal(rest, shown)) {
                if (*denominator == 0.0) throw formats::InputError("answer", "\"" + shown + "\" divides by 0");
                value = *value / *denominator;
                s = rest;
            }
        }
    }
    skip_spaces(s);
    if (!s.empty()) {
        const std::string typed_unit(s);
        if (unit.empty())
            throw formats::InputError("answer",
                                      "this value has no unit: type the number alone, without \"" + typed_unit + "\"");
        if (comparable_unit(typed_unit) != comparable_unit(unit))
            throw formats::InputError("answer", "the answer is in " + std::string(unit) + ", not \"" + typed_unit +
                                                    "\": type it in " + std::string(unit) +
                                                    " (the unit may follow the number, or be left out)");
    }
    if (!std::isfinite(*value)) throw formats::InputError("answer", "\"" + shown + "\" is too large a number");
    return *value;
}

}  // namespace impulse::course
