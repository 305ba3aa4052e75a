#pragma once
// What a method reports of one visit of a contact, as plain numbers: which contact, where in its loop, and what
// it computed and applied. A method reports only when the recorder keeps the frame (one `if` in its loop); the
// recorder builds the trace's iteration from it (record/visit_records.hpp), with the bookkeeping updates of the
// other contacts, so no method builds a record or keeps a bookkeeping for the recorder's sake.

#include "derivation/desired_delta_velocity.hpp"
#include "derivation/position_change.hpp"
#include "record/iteration_records.hpp"
#include "record/position_resolution.hpp"

#include <optional>

namespace impulse {

// How the other contacts' desired delta v follows a change of their velocity, in the visiting method's terms.
enum class DesiredFollows {
    step_5,      // step 5 again on the new velocity (the book's bookkeeping)
    row_target,  // the normal velocity the contact's rigid row asks for, minus the new one (projected Gauss-Seidel)
    nothing,     // no updates are recorded (soft step keeps no bookkeeping: its bodies move within the frame)
};

struct VelocityVisit {
    int contact = 0;
    std::optional<SweepPlace> sweep;  // where in the sweeps (worst-first: none)
    double epsilon = 0.0;             // what the visit's desired delta v is judged against (0: nothing)
    DesiredFollows updates = DesiredFollows::step_5;
    // The book's one-shot impulse: steps 5 to 7 as the method computed them on its bookkeeping.
    const VelocityResolution* resolution = nullptr;
    // An accumulating method's visit (resolution null): the contact velocity it read from the bodies, step 5 as
    // it judged the visit (desired delta v = its target minus the normal velocity), and its running total. The
    // impulse applied is accumulated.after - before, through step 7.
    Vec3 contact_velocity = Vec3::Zero();
    DesiredDeltaVelocity desired_terms{};
    AccumulatedImpulse accumulated{};
    bool friction_rows = false;  // the friction rows were solved (else the impulse is frictionless)
};

struct PositionVisit {
    int contact = 0;
    std::optional<int> pass;  // relaxation's pass, the split impulse's sweep
    // A projection's move: step 8 as the method computed it, and what the penetration was judged against.
    const PositionResolution* resolution = nullptr;
    double epsilon = 0.0;
    // The split impulse's push (resolution null): the push impulse applied, the moves it made, and the penetration
    // its pushes leave (m), which its target subtracts: beta max(penetration - slop, 0) / h.
    double push_impulse = 0.0;
    PositionChange change{};
    double slop = 0.0;
};

}  // namespace impulse
