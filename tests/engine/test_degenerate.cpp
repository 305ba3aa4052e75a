// Degenerate contacts under every preset: both bodies immovable, no velocity per unit impulse at all, a contact
// point at a body's centre, and normals along the axes the basis seeds its tangent from. None may divide by
// zero: each is either resolved with finite numbers or recorded as inert and skipped.

#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/bodies.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::test;

namespace {

bool finite(const RigidBody& b) {
    return b.position.allFinite() && b.orientation.coeffs().allFinite() && b.velocity.allFinite() &&
           b.angular_velocity.allFinite();
}

bool finite(const ContactPreparation& d) {
    return d.basis.contact_to_world.allFinite() && d.velocity_terms.contact_velocity.allFinite() &&
           std::isfinite(d.unit_impulse_chain.delta_velocity_per_unit_impulse) &&
           std::isfinite(d.desired_terms.desired_delta_velocity);
}

// Resolves the contacts once under `preset_name` with a recorder on, with friction (the full 3x3 solve) and
// penetration (the position phase) so every path is taken.
Trace resolved(std::string_view preset_name, std::vector<RigidBody>& bodies, const std::vector<Contact>& contacts) {
    Trace trace;
    trace.scene.settings = *preset(preset_name);
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, contacts, trace.scene.settings, recorder);
    return trace;
}

// A body that cannot translate (inverse mass 0) but can turn: pushed at its centre, nothing moves.
RigidBody pinned_spinner(const Vec3& position) {
    RigidBody b = immovable(position);
    b.inverse_inertia_body = Mat3::Identity();
    return b;
}

}  // namespace

TEST_CASE("a contact between two immovable bodies is recorded as inert and leaves both untouched, every preset") {
    for (std::string_view name : preset_names()) {
        CAPTURE(name);
        std::vector<RigidBody> bodies{immovable({0, 0.5, 0}), immovable({0, -0.5, 0})};
        bodies[0].velocity = {0, -1, 0};  // even moving, an immovable body takes no impulse
        const std::vector<RigidBody> before = bodies;
        const Trace trace = resolved(name, bodies, {contact(0, 1, {0, 0, 0}, {0, 1, 0}, 0.1, 0.5, 0.5)});
        REQUIRE(trace.frames.size() == 1);
        REQUIRE(trace.frames[0].contacts.size() == 1);
        const ContactPreparation& d = trace.frames[0].contacts[0];
        CHECK(d.inert);
        CHECK(d.unit_impulse_chain.delta_velocity_per_unit_impulse == 0.0);  // d = 0
        CHECK(finite(d));
        CHECK(trace.frames[0].velocity.iterations.empty());
        CHECK(trace.frames[0].position.iterations.empty());
        CHECK(bodies[0].velocity == before[0].velocity);
        CHECK(bodies[1] == before[1]);
    }
}

TEST_CASE("a push through the centre of a body that cannot translate has d = 0 and is recorded as inert") {
    // q_rel = 0 so u = q_rel x n = 0 and the angular part is 0; m^-1 = 0: d = 0 + 0 against the world.
    for (std::string_view name : preset_names()) {
        CAPTURE(name);
        std::vector<RigidBody> bodies{pinned_spinner({0, 0, 0})};
        bodies[0].velocity = {0, -1, 0};
        const Trace trace = resolved(name, bodies, {contact(0, world_body, {0, 0, 0}, {0, 1, 0}, 0.1, 0.5, 0.5)});
        REQUIRE(trace.frames.size() == 1);
        const ContactPreparation& d = trace.frames[0].contacts.at(0);
        CHECK(d.inert);
        CHECK(finite(d));
        CHECK(finite(bodies[0]));
        CHECK(bodies[0].angular_velocity == Vec3::Zero());
    }
}

TEST_CASE("a contact at a movable body's centre is resolved with no turn and finite numbers, every preset") {
    // q_rel = 0: the angular component and every angular move are 0, d = m^-1 = 1, so g = v / d stays finite
    // and the position phase moves the body linearly only.
    for (std::string_view name : preset_names()) {
        CAPTURE(name);
        std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0, 0, 0}, {0, -1, 0})};
        const Trace trace = resolved(name, bodies, {contact(0, world_body, {0, 0, 0}, {0, 1, 0}, 0.1, 0.0, 0.5)});
        REQUIRE(trace.frames.size() == 1);
        const ContactPreparation& d = trace.frames[0].contacts.at(0);
        CHECK_FALSE(d.inert);
        CHECK(d.unit_impulse_chain.delta_velocity_per_unit_impulse == 1.0);
        CHECK(finite(d));
        CHECK(finite(bodies[0]));
        CHECK(bodies[0].angular_velocity.norm() < 1e-12);
        CHECK(bodies[0].velocity.y() > -1.0);  // the closing speed was taken away, at least in part
    }
}

TEST_CASE("a body that can translate but not turn, hit off its centre, gets finite linear answers only") {
    for (std::string_view name : preset_names()) {
        CAPTURE(name);
        RigidBody b = sphere(1.0, 0.5, {0, 0.5, 0}, {0, -1, 0});
        b.inverse_inertia_body = Mat3::Zero();
        std::vector<RigidBody> bodies{b};
        const Trace trace = resolved(name, bodies, {contact(0, world_body, {0.3, 0, 0.2}, {0, 1, 0}, 0.1, 0.0, 0.5)});
        const ContactPreparation& d = trace.frames.at(0).contacts.at(0);
        CHECK_FALSE(d.inert);
        CHECK(finite(d));
        CHECK(finite(bodies[0]));
        CHECK(bodies[0].angular_velocity == Vec3::Zero());
    }
}

TEST_CASE("normals along and between the axes the tangent is seeded from give an orthonormal basis, every preset") {
    // basis() crosses a world axis with n; n parallel to that axis would give a zero tangent, so it picks the
    // axis n is least aligned with. Every axis, both signs, and the tie |n.x| = |n.y|.
    const std::vector<Vec3> normals{Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(),     -Vec3::UnitY(),
                                    Vec3::UnitZ(), -Vec3::UnitZ(), Vec3(1, 1, 0),     Vec3(-1, 1, 0),
                                    Vec3(1, 1, 1), Vec3(0, 1, 1),  Vec3(1e-300, 1, 0)};
    for (std::string_view name : preset_names())
        for (const Vec3& n : normals) {
            CAPTURE(name);
            CAPTURE(n.transpose());
            std::vector<RigidBody> bodies{box(1.0, {0.5, 0.5, 0.5}, Vec3(n.normalized() * 0.5))};
            bodies[0].velocity = -n.normalized();
            const Trace trace =
                resolved(name, bodies, {contact(0, world_body, Vec3(0.1, 0.05, -0.1), n, 0.05, 0.3, 0.5)});
            const ContactPreparation& d = trace.frames.at(0).contacts.at(0);
            const Mat3& c = d.basis.contact_to_world;
            CHECK(finite(d));
            CHECK((c.transpose() * c - Mat3::Identity()).norm() < 1e-12);
            CHECK(finite(bodies[0]));
        }
}
