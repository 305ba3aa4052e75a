// CSV cells as the exports and the bench programs write them (formats/csv.hpp).

#include "formats/csv.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace impulse::test {

TEST_CASE("a number cell keeps nine significant digits and says NaN for a missing value") {
    CHECK(formats::csv_number(0.0) == "0");
    CHECK(formats::csv_number(2.5) == "2.5");
    CHECK(formats::csv_number(1.0 / 3.0) == "0.333333333");
    CHECK(formats::csv_number(-1.2345678912e-7) == "-1.23456789e-07");
    CHECK(formats::csv_number(12345678912.0) == "1.23456789e+10");
    CHECK(formats::csv_number(std::numeric_limits<double>::quiet_NaN()) == "NaN");
    CHECK(formats::csv_number(std::numeric_limits<double>::infinity()) == "inf");
}

TEST_CASE("a field is quoted only when it holds a comma, a quote or a line break") {
    CHECK(formats::csv_field("plain") == "plain");
    CHECK(formats::csv_field("a,b") == "\"a,b\"");
    CHECK(formats::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    CHECK(formats::csv_row({"x", formats::csv_number(0.5)}) == "x,0.5\n");
}

}  // namespace impulse::test
