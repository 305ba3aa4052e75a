#pragma once
// What a terminal lesson shows besides the step's table, on a key, through the lesson's mask as the window's
// panels show it: the bodies before and after the step's item (key o), the frame's contacts (key c) and the
// order the phase took them in (key i, the navigator's list). Lines fit `width` columns where they can wrap.

#include "course/mask.hpp"

#include <ostream>

namespace impulse::course {

void write_bodies(std::ostream& out, const Trace& trace, const model::Cursor& at, const Mask& mask, int width);
// Its columns are short (a contact, its bodies, three numbers and a status): they fit 80 columns.
void write_contacts(std::ostream& out, const Trace& trace, const model::Cursor& at, const Mask& mask);
// The frame's stages and, around the cursor, their items: at most `around` before and after it in its stage.
void write_order(std::ostream& out, const Trace& trace, const model::Cursor& at, const Mask& mask, int width,
                 int around = 12);

// "? (hidden until you answer step 5 · slip)": which step's question to answer; "this step's" for `current`.
std::string hidden_until(const Lesson& lesson, int step, int current);

}  // namespace impulse::course
