#pragma once
// How the navigator names a trace's stages and items, through a lesson's mask: the window's tree and the
// terminal's list of the phase's order (key i) say the same words and hide the same values.

#include "course/mask.hpp"

#include <string>

namespace impulse::course {

// "Preparation: 4 contacts", "Velocity phase: 12 of 16 iterations".
std::string stage_label(const FrameRecord& frame, model::Stage stage);

// An item's line: its contact and the value that made it the choice ("iteration 3 → contact 1 (Δv 7.5 m/s)"),
// unless the mask hides that value (or which bodies the contact joins).
std::string item_label(const Trace& trace, const Mask& mask, int frame, model::Stage stage, int item);

}  // namespace impulse::course
