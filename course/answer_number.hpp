#pragma once
// The one reader of a typed answer, for the window, the terminal and the page alike: a number as people write
// it — "3.2", "-1.5e-2", "−3" (a typographic minus), "15,0" (a decimal comma), "1/60" (a fraction) — perhaps
// followed by a unit, which must be the question's ("7.5 m/s", "15 N*s", "9.81 m/s^2"). Anything else is
// refused with one line that says what to type, never read as another number.

#include <string>
#include <string_view>

namespace impulse::course {

// The number in `typed`, in `unit` (the question's unit; empty for a value without one). Throws
// formats::InputError("answer", ...) when it is not a number, holds two decimal marks, divides by 0, or names
// another unit.
double read_answer_number(std::string_view typed, std::string_view unit);

// `unit` as it is compared: separators (·, *, ., spaces) dropped, ^2 and a trailing 2 read as ², ^-1 as ⁻¹.
std::string comparable_unit(std::string_view unit);

}  // namespace impulse::course
