#pragma once
// What the book's worst-first loops share between the methods built on them: the chooser of the worst
// contact, and the position phase's loop (pick the deepest contact above the epsilon, move its bodies by the
// method's projection, update every contact sharing a body, repeat until nothing is above the epsilon or the
// iteration limit is reached). Each position method (methods/*.cpp) supplies its projection.

#include "methods/method.hpp"
#include "methods/projections.hpp"
#include "methods/worst_first_selector.hpp"

#include <optional>
#include <vector>

namespace impulse {

// What the position phase carries from one iteration to the next besides the contacts.
struct PositionPhaseState {
    std::vector<double> rewound_time;  // per body: how far velocity-based resolution moved it back this frame (s)
};

// A position method's move for one contact: removes `amount` of its penetration (step 8).
using Projection = PositionResolution (*)(const PreparedContact& contact, double amount,
                                          const PositionPhaseState& state, const FrameContext& frame);

// Whether a method can move a contact at all (linear projection cannot move bodies that cannot translate,
// and choosing such a contact again would only spend iterations).
using Movable = bool (*)(const PreparedContact& contact, std::span<const MassProperties> mass);

// The phase's chooser (worst_first_selector.hpp): every non-inert contact the method can move, by penetration.
WorstFirstSelector penetration_selector(const FrameContext& frame, Movable movable);

// Removes `amount` of contact `chosen`'s penetration with `projection`, moves its bodies, updates the
// penetration of every contact sharing them (telling `selector`), and reports the visit.
void resolve_penetration(FrameContext& frame, Projection projection, PositionPhaseState& state,
                         WorstFirstSelector& selector, int chosen, double amount, std::optional<int> pass);

// The book's position phase with the given projection: worst first until nothing is above the epsilon.
PhaseOutcome worst_first_positions(FrameContext& frame, Projection projection, Movable movable);

}  // namespace impulse
