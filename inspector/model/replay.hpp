#pragma once
// The state of a frame at the cursor, rebuilt from the recording alone: each contact's bookkeeping
// (penetration, desired delta v) and status, each body's state before and after the cursor's item, and the
// impulse each contact has received so far. Replaying means applying the recorded updates and changes in
// order; nothing is derived again, so stepping back is exact.

#include "model/navigator.hpp"

#include <vector>

namespace impulse::model {

enum class ContactStatus {
    chosen,         // resolved by the cursor's iteration
    waiting,        // above the phase's epsilon: a later iteration may pick it
    below_epsilon,  // at or below the epsilon: left alone unless an update pushes it back up
};

std::string_view status_name(ContactStatus status);  // "chosen", "waiting", "below ε"

struct ContactRow {
    int contact;  // index in the frame's contact list
    const ContactPreparation* prepared;
    double penetration;             // the bookkeeping value before the cursor's item (m)
    double desired_delta_velocity;  // likewise (m/s)
    ContactStatus status;           // in the cursor's phase; in preparation, against the first phase's epsilon
    Vec3 impulse_so_far;            // world, summed over the velocity iterations before the cursor's item (N s)
};

// One row per recorded contact, in contact order.
std::vector<ContactRow> contact_rows(const Trace& trace, const Cursor& cursor);

struct BodiesAtCursor {
    std::vector<BodyState> before;  // before the cursor's item (its move or impulse)
    std::vector<BodyState> after;   // after it; equal to `before` in preparation
    std::vector<int> moved;         // bodies the item moved or changed the speed of
    // False when an earlier iteration's derivation was left out by the recording's contact filter: the
    // states are then the frame's start (before) and end (after) and say nothing about the cursor.
    bool exact = true;
};

BodiesAtCursor bodies_at(const Trace& trace, const Cursor& cursor);

// The worst value each iteration of a phase picked (penetration or desired delta v), for the phase plots.
struct PhaseCurve {
    Stage stage;
    std::vector<double> worst;  // one per iteration
    double epsilon;
};
std::vector<PhaseCurve> phase_curves(const FrameRecord& frame);

}  // namespace impulse::model
