// JSON text: strict parsing (duplicate keys, depth, positions of syntax errors) and readable writing that
// keeps every double to the last bit.

#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "io/json_values.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace impulse;

TEST_CASE("a key given twice is an error at its path, not a silent overwrite") {
    CHECK_THROWS_WITH_AS(io::parse_json_text(R"({"a": [{"b": 1}, {"c": 1, "c": 2}]})"),
                         "a[1].c: key given twice in the same object", io::InputError);
}

TEST_CASE("nesting deeper than the limit is refused instead of exhausting the stack") {
    const std::string deep = std::string(200, '[') + std::string(200, ']');
    CHECK_THROWS_AS(io::parse_json_text(deep), io::InputError);
    const std::string ok = std::string(60, '[') + std::string(60, ']');
    CHECK_NOTHROW(io::parse_json_text(ok));
}

TEST_CASE("a syntax error gives its line and column") {
    CHECK_THROWS_WITH_AS(io::parse_json_text("{\n  \"a\": 1,\n  \"b\" 2\n}"),
                         doctest::Contains("invalid JSON at line 3, column 7:"), io::InputError);
}

TEST_CASE("written doubles read back to the same bits, and vectors stay on one line") {
    const io::json value = {{"v", {0.1, 1.0 / 3.0, -2.5e-310}}, {"m", {{1.0, 2.0}, {3.0, 4.0}}}, {"x", M_PI}};
    const std::string text = io::format_json(value);
    CHECK(text.find("\"v\": [0.1, 0.3333333333333333, -2.5e-310]") != std::string::npos);
    CHECK(text.find("\"m\": [[1.0, 2.0], [3.0, 4.0]]") != std::string::npos);
    const io::json again = io::parse_json_text(text);
    CHECK(again == value);
    CHECK(again["x"].get<double>() == M_PI);
}
