#pragma once
// A contact as collision detection (or a case file) hands it to the resolver.

#include "math/types.hpp"

#include <array>

namespace impulse {

// Index of the static world in Contact::bodies.
inline constexpr int world_body = -1;

struct Contact {
    // Body 0 and body 1 as indices into the body list; body 1 may be `world_body`. A contact given with
    // the world as body 0 is swapped (normal negated) when it is prepared, and the trace says so.
    std::array<int, 2> bodies{0, world_body};
    Vec3 point = Vec3::Zero();    // q: the contact point, world (m)
    Vec3 normal = Vec3::UnitY();  // unit; points from body 1 towards body 0 (the way body 0 must move)
    double penetration = 0.0;     // overlap along the normal (m); > 0 means interpenetrating
    double restitution = 0.0;     // c in v_s' = -c v_s
    double friction = 0.0;        // mu; exactly 0 selects the frictionless impulse (14.3)

    bool operator==(const Contact&) const = default;
};

}  // namespace impulse
