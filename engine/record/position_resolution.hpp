#pragma once
// What one interpenetration move of any method computes: the values of derivation step 8, plus the
// method's own intermediates. Each method (engine/methods/) returns this record; the position phase applies
// it and updates the other contacts, and the recorder keeps it.

#include "derivation/position_change.hpp"
#include "settings/settings.hpp"

#include <optional>

namespace impulse {

// Velocity-based resolution: the bodies are moved back along the paths they followed this frame.
struct Rewind {
    double closing_velocity;       // speed at which the contact points approach along n (m/s); > 0 = closing
    double time;                   // how far back along their paths the bodies go (s)
    double time_limit;             // the frame duration: they cannot go back before the frame began
    double removed_penetration;    // closing_velocity x time
    PerBody<Vec3> linear_change;   // -p-dot t
    PerBody<Vec3> angular_change;  // -theta-dot t

    bool operator==(const Rewind&) const = default;
};

struct PositionResolution {
    PositionMethod method;
    double penetration;            // the contact's penetration when it was chosen
    double amount = 0.0;           // m: the penetration a projection removes (relaxation: a fraction of it;
                                   // velocity-based: what the rewind left); 0 for the split impulse
    double push_impulse = 0.0;     // N·s: the split impulse's push this visit (it moves by an impulse, not a
                                   // distance: its own word); 0 for the projections
    std::optional<Rewind> rewind;  // velocity-based only
    PenetrationInertia inertia;    // linear projection counts angular inertia as 0: it never turns a body
    MoveSplit moves;
    std::optional<AngularLimit> angular_limit;  // nonlinear projection (and the methods built on it)
    PositionChange change;                      // the total translation and rotation applied to each body

    bool operator==(const PositionResolution&) const = default;
};

}  // namespace impulse
