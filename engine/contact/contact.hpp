#pragma once
// A contact as collision detection (or a case file) hands it to the resolver.

#include "math/types.hpp"

#include <array>
#include <optional>

namespace impulse {

// Index of the static world in Contact::bodies.
inline constexpr int world_body = -1;

// Which test made a contact (explicit = written into a case or scene by hand).
enum class CollisionTest { explicit_contact, sphere_sphere, sphere_half_space, box_half_space, box_sphere, box_box };

// The part of a body's shape that touches: a box's face, edge or vertex (numbered as in shapes/shape.hpp), a
// sphere's surface, the ground plane, or nothing known (an explicit contact).
enum class FeatureKind { none, face, edge, vertex, sphere, plane };

struct Feature {
    FeatureKind kind = FeatureKind::none;
    int index = -1;  // face, edge or vertex number; -1 for a sphere, a plane or nothing

    bool operator==(const Feature&) const = default;
};

// Why a contact exists, so a student can see it: the test that made it and the feature of each body.
struct ContactOrigin {
    CollisionTest test = CollisionTest::explicit_contact;
    std::array<Feature, 2> features{};  // [body 0, body 1]

    bool operator==(const ContactOrigin&) const = default;
};

struct Contact {
    // Body 0 and body 1 as indices into the body list; body 1 may be `world_body`. A contact given with
    // the world as body 0 is swapped (normal negated) when it is prepared, and the trace says so.
    std::array<int, 2> bodies{0, world_body};
    Vec3 point = Vec3::Zero();    // q: the contact point, world (m)
    Vec3 normal = Vec3::UnitY();  // unit; points from body 1 towards body 0 (the way body 0 must move)
    double penetration = 0.0;     // overlap along the normal (m); > 0 means interpenetrating
    double restitution = 0.0;     // c in v_s' = -c v_s
    double friction = 0.0;        // mu; exactly 0 selects the frictionless impulse (14.3)
    ContactOrigin origin{};       // which test and which features made it
    // A recycled contact (memory/contact_recycling.hpp) keeps each body's own anchor, which the bodies' moves since
    // detection have carried apart: `point` is body 0's, this body 1's. Empty (every detected contact): both bodies
    // are touched at `point`.
    std::optional<Vec3> body1_point{};

    bool operator==(const Contact&) const = default;
};

// Where body `slot` (0 or 1, as the contact gives them) is touched: q, or body 1's own anchor on a recycled contact.
inline const Vec3& touch_point(const Contact& contact, int slot) {
    return slot == 1 && contact.body1_point ? *contact.body1_point : contact.point;
}

}  // namespace impulse
