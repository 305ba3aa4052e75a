// JSON text: strict parsing (duplicate keys, depth, positions of syntax errors) and readable writing that
// keeps every double to the last bit.

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/json_values.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace impulse;

TEST_CASE("a key given twice is an error at its path, not a silent overwrite") {
    CHECK_THROWS_WITH_AS(formats::parse_json_text(R"({"a": [{"b": 1}, {"c": 1, "c": 2}]})"),
                         "a[1].c: key given twice in the same object", formats::InputError);
}

TEST_CASE("nesting deeper than the limit is refused instead of exhausting the stack") {
    const std::string deep = std::string(200, '[') + std::string(200, ']');
    CHECK_THROWS_AS(formats::parse_json_text(deep), formats::InputError);
    const std::string ok = std::string(60, '[') + std::string(60, ']');
    CHECK_NOTHROW(formats::parse_json_text(ok));
}

TEST_CASE("a syntax error gives its line and column") {
    CHECK_THROWS_WITH_AS(formats::parse_json_text("{\n  \"a\": 1,\n  \"b\" 2\n}"),
                         doctest::Contains("invalid JSON at line 3, column 7:"), formats::InputError);
}

TEST_CASE("written doubles read back to the same bits, and vectors stay on one line") {
    const formats::json value = {{"v", {0.1, 1.0 / 3.0, -2.5e-310}}, {"m", {{1.0, 2.0}, {3.0, 4.0}}}, {"x", M_PI}};
    const std::string text = formats::format_json(value);
    CHECK(text.find("\"v\": [0.1, 0.3333333333333333, -2.5e-310]") != std::string::npos);
    CHECK(text.find("\"m\": [[1.0, 2.0], [3.0, 4.0]]") != std::string::npos);
    const formats::json again = formats::parse_json_text(text);
    CHECK(again == value);
    CHECK(again["x"].get<double>() == M_PI);
}

TEST_CASE("text that is not UTF-8 is found at its byte, and a string holding it is written as U+FFFD") {
    using impulse::formats::first_non_utf8_byte;
    CHECK_FALSE(first_non_utf8_byte("plain, Δv and ∑ and 🙂").has_value());
    CHECK(first_non_utf8_byte("ab\x98").value() == 2);            // a continuation byte with no lead
    CHECK(first_non_utf8_byte("\xC0\xAF").value() == 0);          // an overlong '/'
    CHECK(first_non_utf8_byte("x\xED\xA0\x80").value() == 1);     // a UTF-16 surrogate
    CHECK(first_non_utf8_byte("\xF4\x90\x80\x80").value() == 0);  // past U+10FFFF
    CHECK(first_non_utf8_byte("\xE2\x88").value() == 0);          // cut short
    CHECK_THROWS_WITH_AS(impulse::formats::require_utf8("a,b\nc,\x98"), "line 2: not UTF-8 text: byte 0x98 at column 3",
                         impulse::formats::InputError);
    const nlohmann::ordered_json value = {{"cell", std::string("a\x98")}};
    CHECK(impulse::formats::format_json(value) == "{\n  \"cell\": \"a\xEF\xBF\xBD\"\n}\n");
}
