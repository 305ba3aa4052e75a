// CSV cells as the exports and the bench programs write them (explain/csv.hpp).

#include "explain/csv.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace impulse::test {

TEST_CASE("a number cell keeps nine significant digits and says NaN for a missing value") {
    CHECK(explain::csv_number(0.0) == "0");
    CHECK(explain::csv_number(2.5) == "2.5");
    CHECK(explain::csv_number(1.0 / 3.0) == "0.333333333");
    CHECK(explain::csv_number(-1.2345678912e-7) == "-1.23456789e-07");
    CHECK(explain::csv_number(12345678912.0) == "1.23456789e+10");
    CHECK(explain::csv_number(std::numeric_limits<double>::quiet_NaN()) == "NaN");
    CHECK(explain::csv_number(std::numeric_limits<double>::infinity()) == "inf");
}

TEST_CASE("a field is quoted only when it holds a comma, a quote or a line break") {
    CHECK(explain::csv_field("plain") == "plain");
    CHECK(explain::csv_field("a,b") == "\"a,b\"");
    CHECK(explain::csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
    CHECK(explain::csv_row({"x", explain::csv_number(0.5)}) == "x,0.5\n");
}

}  // namespace impulse::test
