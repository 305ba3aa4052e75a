#pragma once
// The slips a wrong number most often comes from, told by its ratio to the right one: the opposite sign,
// degrees for radians (or back), a power of ten (a unit slip). The lesson's feedback and the class report both
// name them with these words, so a student hears the same thing from the window, the terminal and the teacher.

#include <string>

namespace impulse::course {

// What the slip probably was when `found` is `expected` times a telling factor (−1, 57.3, 1/57.3, 10^±1..3),
// within `tolerance` of `expected` relative; empty when no factor fits or `expected` is 0.
std::string likely_slip(double expected, double found, double tolerance = 2e-3);

}  // namespace impulse::course
