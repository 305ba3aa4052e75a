#include "course/slips.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <cmath>

namespace impulse::course {

std::string likely_slip(double expected, double found, double tolerance) {
    if (expected == 0.0 || !std::isfinite(expected) || !std::isfinite(found)) return "";
    // found = factor · expected, within the tolerance of the right value: |found / factor − expected| ≤ tol |expected|.
    const auto near = [&](double factor) {
        return std::abs(found / factor - expected) <= std::max(tolerance, 1e-12) * std::abs(expected);
    };
    constexpr double degrees = 180.0 / 3.14159265358979323846;
    if (near(-1.0)) return "the opposite sign: check the order of a cross product, or which body is body 0";
    if (near(degrees)) return "57.3 times the value: degrees where radians are expected?";
    if (near(1.0 / degrees)) return "the value divided by 57.3: radians where degrees are expected?";
    for (const double factor : {10.0, 100.0, 1000.0})
        if (near(factor) || near(1.0 / factor))
            return (near(factor) ? formats::number_text(factor) + " times the value"
                                 : "the value divided by " + formats::number_text(factor)) +
                   ": a unit slip (cm, mm or g where m or kg are expected)?";
    return "";
}

}  // namespace impulse::course
