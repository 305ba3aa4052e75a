#pragma once
// Random bodies and contacts for property tests, drawn inside a rapidcheck property with `*generator`.
// Masses from 0.1 to 10 kg, inertias from random principal moments in random body axes, contact points
// within 1 m of the bodies, every direction of normal.

#include "support/bodies.hpp"

#include <rapidcheck.h>

#include <cmath>
#include <numbers>

namespace impulse::test {

// A double in [low, high], shrinking towards `low`.
inline rc::Gen<double> in_range(double low, double high) {
    return rc::gen::map(rc::gen::inRange(0, 1'000'001),
                        [low, high](int i) { return low + (high - low) * (static_cast<double>(i) / 1e6); });
}

inline Vec3 any_vector(double magnitude) {
    return {*in_range(-magnitude, magnitude), *in_range(-magnitude, magnitude), *in_range(-magnitude, magnitude)};
}

inline Vec3 any_unit_vector() {
    const double polar = *in_range(0.0, std::numbers::pi);
    const double azimuth = *in_range(0.0, 2.0 * std::numbers::pi);
    return {std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth)};
}

inline Quat any_orientation() {
    return Quat(Eigen::AngleAxisd(*in_range(0.0, std::numbers::pi), any_unit_vector()));
}

inline RigidBody any_dynamic_body() {
    RigidBody b;
    b.position = any_vector(1.0);
    b.orientation = any_orientation();
    b.velocity = any_vector(5.0);
    b.angular_velocity = any_vector(5.0);
    b.inverse_mass = 1.0 / *in_range(0.1, 10.0);
    const Vec3 moments(*in_range(0.01, 5.0), *in_range(0.01, 5.0), *in_range(0.01, 5.0));
    const Mat3 axes = any_orientation().toRotationMatrix();
    b.inverse_inertia_body = axes * moments.cwiseInverse().asDiagonal() * axes.transpose();
    return b;
}

struct RandomContact {
    std::vector<RigidBody> bodies;  // one body (contact with the world) or two
    Contact contact;
};

// A contact between a random dynamic body and either the world or a second random body; the normal is
// random, the point within 1 m of body 0.
inline RandomContact any_contact(bool allow_world = true) {
    RandomContact r;
    r.bodies.push_back(any_dynamic_body());
    const bool with_world = allow_world && *rc::gen::arbitrary<bool>();
    if (!with_world) r.bodies.push_back(any_dynamic_body());
    r.contact.bodies = {0, with_world ? world_body : 1};
    r.contact.point = r.bodies[0].position + any_vector(1.0);
    r.contact.normal = any_unit_vector();
    r.contact.penetration = *in_range(0.0, 0.5);
    r.contact.restitution = *in_range(0.0, 1.0);
    r.contact.friction = 0.0;
    return r;
}

}  // namespace impulse::test
