// The worst-first resolver: which contact it chooses, how it updates the others, when it stops.

#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"

using namespace impulse;
using namespace impulse::test;

namespace {

struct Run {
    std::vector<RigidBody> bodies;
    Trace trace;
};

Run run(std::vector<RigidBody> bodies, const std::vector<Contact>& contacts, const ResolverSettings& settings) {
    Run r{std::move(bodies), {}};
    r.trace.scene.settings = settings;
    TraceRecorder recorder(r.trace);
    resolve_contacts(r.bodies, contacts, settings, recorder);
    return r;
}

std::vector<int> chosen_positions(const Trace& t) {
    std::vector<int> order;
    for (const auto& it : t.frames[0].position.iterations) order.push_back(it.contact);
    return order;
}

std::vector<int> chosen_velocities(const Trace& t) {
    std::vector<int> order;
    for (const auto& it : t.frames[0].velocity.iterations) order.push_back(it.contact);
    return order;
}

// Three separate spheres, each resting on the ground with its own penetration and closing speed.
std::vector<RigidBody> three_spheres() {
    return {sphere(1, 0.5, {0, 0.45, 0}, {0, -1, 0}), sphere(1, 0.5, {2, 0.3, 0}, {0, -3, 0}),
            sphere(1, 0.5, {4, 0.4, 0}, {0, -2, 0})};
}

std::vector<Contact> three_ground_contacts(double p0, double p1, double p2) {
    return {contact(0, world_body, {0, -0.05, 0}, {0, 1, 0}, p0), contact(1, world_body, {2, -0.2, 0}, {0, 1, 0}, p1),
            contact(2, world_body, {4, -0.1, 0}, {0, 1, 0}, p2)};
}

}  // namespace

TEST_CASE("the book preset is the reference engine's configuration") {
    const ResolverSettings s = *preset("book");
    CHECK(s.phase_order == PhaseOrder::positions_first);
    CHECK(s.position_method == PositionMethod::nonlinear_projection);
    CHECK(s.velocity_method == VelocityMethod::worst_first);
    CHECK(s.angular_limit.policy == AngularLimitPolicy::lever_arm);
    CHECK(s.angular_limit.factor == 0.2);
    CHECK(s.position_epsilon == 0.01);
    CHECK(s.velocity_epsilon == 0.01);
    CHECK(iteration_limit(s.position_iterations, s, 7) == 28);
    CHECK(iteration_limit(s.velocity_iterations, s, 7) == 28);
    CHECK(s.restitution_cutoff == 0.25);
    CHECK(s.velocity_from_acceleration);
    CHECK(s.tangential_acceleration_velocity);
    CHECK(s.orientation_update == OrientationUpdate::first_order);
    CHECK_FALSE(preset("nonsense").has_value());
}

TEST_CASE("the deepest contact is resolved first, then the fastest-closing") {
    // Penetrations 0.05, 0.2, 0.1 -> positions in the order 1, 2, 0. Closing speeds 1, 3, 2 with c = 0 ->
    // desired delta v 1, 3, 2 -> velocities in the order 1, 2, 0.
    const Run r = run(three_spheres(), three_ground_contacts(0.05, 0.2, 0.1), plain_settings());
    CHECK(chosen_positions(r.trace) == std::vector<int>{1, 2, 0});
    CHECK(chosen_velocities(r.trace) == std::vector<int>{1, 2, 0});
    for (const RigidBody& b : r.bodies) CHECK_CLOSE(b.velocity, Vec3::Zero(), 1e-15);
}

TEST_CASE("equal penetrations are taken in index order, as in the reference engine") {
    const Run r = run(three_spheres(), three_ground_contacts(0.1, 0.1, 0.1), plain_settings());
    CHECK(chosen_positions(r.trace) == std::vector<int>{0, 1, 2});
}

TEST_CASE("a penetration equal to the epsilon is left alone: only values strictly above it are resolved") {
    const Run r = run(three_spheres(), three_ground_contacts(0.01, 0.0, 0.02), plain_settings());
    CHECK(chosen_positions(r.trace) == std::vector<int>{2});
    CHECK(r.trace.frames[0].position.outcome.stop == StopReason::resolved);
}

TEST_CASE("the iteration limit stops a phase with work left, and the trace says so") {
    ResolverSettings s = plain_settings();
    s.position_iterations = 1;
    const Run r = run(three_spheres(), three_ground_contacts(0.05, 0.2, 0.1), s);
    CHECK(r.trace.frames[0].position.outcome.iterations_used == 1);
    CHECK(r.trace.frames[0].position.outcome.iteration_limit == 1);
    CHECK(r.trace.frames[0].position.outcome.stop == StopReason::iteration_limit);
}

TEST_CASE("a contact given with the world as body 0 is swapped and resolves exactly like its mirror") {
    const std::vector<RigidBody> bodies{box(3.0, {1, 0.5, 0.5}, {0, 0.45, 0}, {0, -2, 0})};
    const Run given = run(bodies, {contact(world_body, 0, {1, -0.05, 0}, {0, -1, 0}, 0.05, 0.3)}, plain_settings());
    const Run mirror = run(bodies, {contact(0, world_body, {1, -0.05, 0}, {0, 1, 0}, 0.05, 0.3)}, plain_settings());
    const ContactPreparation& d = given.trace.frames[0].contacts[0];
    CHECK(d.swapped);
    CHECK(d.bodies == std::array<int, 2>{0, world_body});
    CHECK_CLOSE(d.normal, Vec3(0, 1, 0), 0.0);
    CHECK_FALSE(mirror.trace.frames[0].contacts[0].swapped);
    CHECK(given.bodies[0] == mirror.bodies[0]);
}

TEST_CASE("moving a body updates the penetration of every contact on it by the linearised formula") {
    // A box on two corners (contacts 0 and 1) and a separate sphere (contact 2). Resolving contact 0 moves
    // and turns the box; contact 1's penetration changes by -(linear_change + angular_change x q_rel) . n and
    // contact 2 is untouched.
    const std::vector<RigidBody> bodies{box(2.0, {1, 0.25, 0.25}, {0, 0.2, 0}), sphere(1, 0.5, {5, 0.49, 0})};
    const std::vector<Contact> contacts{contact(0, world_body, {-1, -0.05, 0}, {0, 1, 0}, 0.05),
                                        contact(0, world_body, {1, -0.03, 0}, {0, 1, 0}, 0.03),
                                        contact(1, world_body, {5, -0.01, 0}, {0, 1, 0}, 0.01)};
    ResolverSettings s = plain_settings();
    s.position_iterations = 1;
    const Run r = run(bodies, contacts, s);
    const PositionIteration& it = r.trace.frames[0].position.iterations[0];
    REQUIRE(it.contact == 0);
    REQUIRE(it.updates.size() == 2);  // contact 0 itself and contact 1; not contact 2
    CHECK(it.updates[0].contact == 0);
    CHECK_CLOSE(it.updates[0].after, 0.0, 1e-15);  // its own penetration is gone (linearised)
    const PositionChange& change = it.resolution->change;
    const Vec3 q_rel1 = contacts[1].point - bodies[0].position;
    const double expected = -(*change.linear_change[0] + change.angular_change[0]->cross(q_rel1)).dot(Vec3::UnitY());
    CHECK(it.updates[1].contact == 1);
    CHECK_CLOSE(it.updates[1].delta, expected);
    CHECK_CLOSE(it.updates[1].after, 0.03 + expected);
}

TEST_CASE("an impulse updates the contact velocity and desired delta v of contacts sharing the body") {
    // Two contacts on one box landing at 2 m/s: resolving the first changes the second's closing speed.
    const std::vector<RigidBody> bodies{box(2.0, {1, 0.25, 0.25}, {0, 0.25, 0}, {0, -2, 0})};
    const std::vector<Contact> contacts{contact(0, world_body, {-1, 0, 0}, {0, 1, 0}),
                                        contact(0, world_body, {1, 0, 0}, {0, 1, 0})};
    const Run r = run(bodies, contacts, plain_settings());
    const VelocityIteration& first = r.trace.frames[0].velocity.iterations[0];
    REQUIRE(first.updates.size() == 2);
    const VelocityUpdate& other = first.updates[1];
    CHECK(other.contact == 1);
    // Independent check: the second contact point's normal velocity on the bodies after the first impulse.
    RigidBody after = bodies[0];
    after.velocity += *first.resolution->velocity_change_terms.velocity_change[0];
    after.angular_velocity += *first.resolution->velocity_change_terms.rotation_change[0];
    CHECK_CLOSE(other.after.x(), point_velocity(after, contacts[1].point).y());
    CHECK_CLOSE(other.desired_delta_velocity_after, -other.after.x());  // c = 0
}

TEST_CASE("a contact between two immovable bodies is inert and never chosen") {
    const std::vector<RigidBody> bodies{immovable(), immovable({0, 1, 0})};
    const Run r = run(bodies, {contact(0, 1, {0, 0.5, 0}, {0, 1, 0}, 0.5)}, plain_settings());
    CHECK(r.trace.frames[0].contacts[0].inert);
    CHECK(r.trace.frames[0].position.iterations.empty());
    CHECK(r.bodies == bodies);
}

TEST_CASE("the chapter preset resolves velocities before positions") {
    const Run r = run(three_spheres(), three_ground_contacts(0.05, 0.2, 0.1), *preset("chapter"));
    CHECK(r.trace.frames[0].phase_order == PhaseOrder::velocities_first);
}

TEST_CASE("resolution never changes a body that no contact touches") {
    std::vector<RigidBody> bodies = three_spheres();
    bodies.push_back(sphere(1, 0.5, {9, 9, 9}, {1, 2, 3}));
    const Run r = run(bodies, three_ground_contacts(0.05, 0.2, 0.1), plain_settings());
    CHECK(r.bodies[3] == bodies[3]);
}

TEST_CASE("the recorder's contact filter keeps the iterations but only the chosen contacts' derivations") {
    Run r{three_spheres(), {}};
    r.trace.scene.settings = plain_settings();
    r.trace.recording.contacts = std::vector<int>{1};
    TraceRecorder recorder(r.trace);
    resolve_contacts(r.bodies, three_ground_contacts(0.05, 0.2, 0.1), r.trace.scene.settings, recorder);
    const FrameRecord& f = r.trace.frames[0];
    REQUIRE(f.contacts.size() == 1);
    CHECK(f.contacts[0].contact == 1);
    REQUIRE(f.position.iterations.size() == 3);
    CHECK(f.position.iterations[0].resolution.has_value());  // contact 1
    CHECK_FALSE(f.position.iterations[1].resolution.has_value());
    for (const auto& it : f.position.iterations)
        for (const auto& u : it.updates) CHECK(u.contact == 1);
}

TEST_CASE("the recorder's frame range records nothing outside it") {
    Run r{three_spheres(), {}};
    r.trace.recording.first_frame = r.trace.recording.last_frame = 3;
    TraceRecorder recorder(r.trace);
    resolve_contacts(r.bodies, three_ground_contacts(0.05, 0.2, 0.1), plain_settings(), recorder, {.frame = 2});
    CHECK(r.trace.frames.empty());
    resolve_contacts(r.bodies, three_ground_contacts(0.05, 0.2, 0.1), plain_settings(), recorder, {.frame = 3});
    CHECK(r.trace.frames.size() == 1);
}
