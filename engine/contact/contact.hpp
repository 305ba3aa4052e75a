#pragma once
// A contact as collision detection (or a case file) hands it to the resolver.

#include "math/types.hpp"

#include <array>

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

    bool operator==(const Contact&) const = default;
};

}  // namespace impulse
