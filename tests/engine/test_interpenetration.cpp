// Resolving interpenetration four ways, and the angular-limit policies.

#include "methods/projections.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"

#include <cmath>
#include <numbers>

using namespace impulse;
using namespace impulse::test;

namespace {

// The turn (radians) between two orientations.
double angle_between(const Quat& a, const Quat& b) {
    return a.angularDistance(b);
}

// A 20 kg bar with a small moment of inertia, 0.8 m deep at one end (scenes/cases/deep_corner.json).
std::vector<RigidBody> deep_bar() {
    RigidBody bar;
    bar.position = {0, -0.3, 0};
    bar.orientation = Quat(Eigen::AngleAxisd(std::numbers::pi / 6, Vec3::UnitZ()));
    bar.inverse_mass = 1.0 / 20.0;
    bar.inverse_inertia_body = Vec3(50, 10, 10).asDiagonal();
    return {bar};
}

Contact deep_bar_contact() {
    return contact(0, world_body, {-std::sqrt(3.0) / 2, -0.8, 0}, {0, 1, 0}, 0.8);
}

}  // namespace

TEST_CASE("linear projection never turns a body and splits the move by inverse mass") {
    // Bodies of 1 kg and 3 kg, penetration 0.2: inverse masses 1 and 1/3 share 0.2 as 0.15 and 0.05, body 1
    // moving against the normal.
    const std::vector<RigidBody> bodies{box(1.0, {0.5, 0.5, 0.5}, {0.3, 0.5, 0}),
                                        box(3.0, {0.5, 0.5, 0.5}, {0, -0.5, 0})};
    const PreparedContact p = prepared(contact(0, 1, {0.7, 0, 0.2}, {0, 1, 0}, 0.2), bodies);
    const PositionResolution r = linear_projection(p, mass_of(p.bodies, bodies), 0.2);
    CHECK_CLOSE(*r.moves.linear_move[0], 0.15);
    CHECK_CLOSE(*r.moves.linear_move[1], -0.05);
    CHECK_CLOSE(*r.change.angular_change[0], Vec3::Zero(), 0.0);
    CHECK_CLOSE(*r.change.angular_change[1], Vec3::Zero(), 0.0);
    CHECK_FALSE(r.angular_limit.has_value());
}

TEST_CASE("without a limit a severely interpenetrated light-inertia bar turns about 49 degrees in one move") {
    // Angular inertia ((I^-1 (r x n)) x r).n = 0.866^2 * 10 = 7.5 against linear 0.05: 99% of the 0.8 m is
    // angular. The rotation vector is 10 * 0.866 * 0.7947 / 7.5 = 0.918 rad long, and the first-order update
    // turns through 2 atan(0.918 / 2) = 0.8608 rad = 49.3 degrees.
    std::vector<RigidBody> bodies = deep_bar();
    const Quat before = bodies[0].orientation;
    ResolverSettings s = plain_settings();
    s.angular_limit = {AngularLimitPolicy::none, 0.0};
    resolve_contacts(bodies, std::vector{deep_bar_contact()}, s);
    CHECK(angle_between(before, bodies[0].orientation) * 180 / std::numbers::pi == doctest::Approx(49.3).epsilon(0.01));
}

TEST_CASE("the angle policy turns the body through exactly 45 degrees under either orientation update") {
    for (OrientationUpdate update : {OrientationUpdate::first_order, OrientationUpdate::exact}) {
        std::vector<RigidBody> bodies = deep_bar();
        const Quat before = bodies[0].orientation;
        ResolverSettings s = plain_settings();
        s.angular_limit = {AngularLimitPolicy::angle, 45.0};
        s.orientation_update = update;
        Trace trace;
        TraceRecorder recorder(trace);
        resolve_contacts(bodies, std::vector{deep_bar_contact()}, s, recorder);
        const PositionResolution& r = *trace.frames[0].position.iterations[0].resolution;
        CHECK(*r.angular_limit->applied[0]);
        CHECK(angle_between(before, bodies[0].orientation) == doctest::Approx(std::numbers::pi / 4).epsilon(1e-12));
        // The whole 0.8 m is still removed (linearised): the limit only moves share from turning to moving.
        CHECK_CLOSE(*r.moves.linear_move[0] + *r.moves.angular_move[0], 0.8);
    }
}

TEST_CASE("the book's lever-arm limit caps the angular move at 0.2 times the lever arm") {
    // Lever arm: q_rel = (-0.866, -0.5, 0) without its normal part, length 0.866; maximum 0.1732 m.
    std::vector<RigidBody> bodies = deep_bar();
    Trace trace;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, std::vector{deep_bar_contact()}, plain_settings(), recorder);
    const PositionResolution& r = *trace.frames[0].position.iterations[0].resolution;
    CHECK_CLOSE(*r.angular_limit->maximum[0], 0.2 * std::sqrt(3.0) / 2);
    CHECK(*r.angular_limit->applied[0]);
    CHECK_CLOSE(*r.moves.angular_move[0], 0.2 * std::sqrt(3.0) / 2);
    CHECK_CLOSE(*r.moves.linear_move[0], 0.8 - 0.2 * std::sqrt(3.0) / 2);
}

TEST_CASE("velocity-based resolution moves a falling sphere back along its path to first contact") {
    // Falling at 2 m/s, 0.01 m deep: the contact closes at 2 m/s, so t = 0.01 / 2 = 0.005 s back, which is
    // within the 1/60 s frame: the sphere goes back up 0.01 m and nothing is left to project.
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0, 0.49, 0}, {0, -2, 0})};
    const PreparedContact p = prepared(contact(0, world_body, {0, -0.01, 0}, {0, 1, 0}, 0.01), bodies);
    PerBody<BodyMotion> motion;
    motion[0] = BodyMotion{{0, -2, 0}, Vec3::Zero(), Vec3::Zero()};
    const PositionResolution r = velocity_based(p, mass_of(p.bodies, bodies), motion, 1.0 / 60.0,
                                                {AngularLimitPolicy::lever_arm, 0.2}, OrientationUpdate::first_order);
    REQUIRE(r.rewind.has_value());
    CHECK_CLOSE(r.rewind->closing_velocity, 2.0);
    CHECK_CLOSE(r.rewind->time, 0.005);
    CHECK_CLOSE(r.amount, 0.0, 1e-15);
    CHECK_CLOSE(*r.change.linear_change[0], Vec3(0, 0.01, 0));
}

TEST_CASE("velocity-based resolution cannot go back before the frame began and projects the rest") {
    // 0.05 m deep at 2 m/s with a 1/60 s frame: the path explains 2/60 = 0.0333 m; the remaining 0.01667 m
    // is projected (linearly, for a head-on sphere). Total: 0.05 m up.
    const std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0, 0.45, 0}, {0, -2, 0})};
    const PreparedContact p = prepared(contact(0, world_body, {0, -0.05, 0}, {0, 1, 0}, 0.05), bodies);
    PerBody<BodyMotion> motion;
    motion[0] = BodyMotion{{0, -2, 0}, Vec3::Zero(), Vec3::Zero()};
    const PositionResolution r = velocity_based(p, mass_of(p.bodies, bodies), motion, 1.0 / 60.0,
                                                {AngularLimitPolicy::lever_arm, 0.2}, OrientationUpdate::first_order);
    CHECK_CLOSE(r.rewind->time, 1.0 / 60.0);
    CHECK_CLOSE(r.rewind->removed_penetration, 2.0 / 60.0);
    CHECK_CLOSE(r.amount, 0.05 - 2.0 / 60.0);
    CHECK_CLOSE(*r.change.linear_change[0], Vec3(0, 0.05, 0));
}

TEST_CASE("relaxation removes half the penetration per pass and leaves the rest by design") {
    // 0.32 m deep, fraction 0.5, 4 passes: 0.32 -> 0.16 -> 0.08 -> 0.04 -> 0.02, still above the 0.01 epsilon.
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0, 0.18, 0})};
    ResolverSettings s = plain_settings();
    s.position_method = PositionMethod::relaxation;
    s.relaxation = {0.5, 4};
    s.iterations_per_contact = 10;
    Trace trace;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, std::vector{contact(0, world_body, {0, -0.32, 0}, {0, 1, 0}, 0.32)}, s, recorder);
    const auto& log = trace.frames[0].position;
    REQUIRE(log.iterations.size() == 4);
    for (int pass = 0; pass < 4; ++pass) {
        CHECK(log.iterations[static_cast<std::size_t>(pass)].pass == pass);
        CHECK_CLOSE(log.iterations[static_cast<std::size_t>(pass)].penetration, 0.32 / std::pow(2.0, pass));
    }
    CHECK(log.outcome.stop == StopReason::passes_complete);
    CHECK_CLOSE(bodies[0].position.y(), 0.18 + 0.30);
}

TEST_CASE("relaxation shares the penetration among contacts that fight over one body") {
    // A brick pressed from both sides (normals +x and -x, head-on, so every move is linear), 0.3 m and
    // 0.2 m deep: no position removes both, their sum stays 0.5. Full projection alternates and always
    // ends with one contact 0.5 deep. Relaxation (fraction 0.5 per visit) settles where each pass leaves
    // x = x/4 - 0.025, i.e. x = -1/30: 1/3 and 1/6 deep, shared.
    const auto deepest_left = [](PositionMethod method) {
        std::vector<RigidBody> bodies{box(1.0, {0.5, 0.5, 0.5}, Vec3::Zero())};
        ResolverSettings s = plain_settings();
        s.position_method = method;
        s.relaxation = {0.5, 8};
        s.iterations_per_contact = 8;
        const std::vector<Contact> contacts{contact(0, world_body, {-0.5, 0, 0}, {1, 0, 0}, 0.3),
                                            contact(0, world_body, {0.5, 0, 0}, {-1, 0, 0}, 0.2)};
        resolve_contacts(bodies, contacts, s);
        const double x = bodies[0].position.x();
        return std::max(0.3 - x, 0.2 + x);
    };
    CHECK(deepest_left(PositionMethod::nonlinear_projection) == doctest::Approx(0.5));
    CHECK(deepest_left(PositionMethod::relaxation) == doctest::Approx(1.0 / 3.0).epsilon(1e-3));
}

TEST_CASE("velocity-based resolution never moves a body back more than one frame, however many contacts rewind it") {
    // Regression: the frame cap was per contact. A sphere moving at (-1, -1, 0) touches the floor (n = +y) and a
    // wall (n = +x), each 2/60 m deep, frame 1/60 s. The floor contact rewinds the sphere the whole frame,
    // (1/60, 1/60, 0), and projects the other 1/60 up; that also opens the wall contact by 1/60. The wall then
    // has no frame left to rewind and projects its remaining 1/60. Total: (2/60, 2/60, 0), one frame of path.
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, Vec3::Zero(), {-1, -1, 0})};
    ResolverSettings s = plain_settings();
    s.position_method = PositionMethod::velocity_based;
    s.duration = 1.0 / 60.0;
    const double depth = 2.0 / 60.0;
    Trace trace;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies,
                     std::vector{contact(0, world_body, {0, -0.5, 0}, {0, 1, 0}, depth),
                                 contact(0, world_body, {-0.5, 0, 0}, {1, 0, 0}, depth)},
                     s, recorder);
    double rewound = 0.0;
    for (const auto& it : trace.frames[0].position.iterations) rewound += it.resolution->rewind->time;
    CHECK_CLOSE(rewound, 1.0 / 60.0);
    CHECK_CLOSE(bodies[0].position, Vec3(2.0 / 60.0, 2.0 / 60.0, 0));
}

TEST_CASE("relaxation whose last pass ends exactly at the iteration limit reports its passes complete") {
    // Regression: 4 passes over one contact with a limit of 4 iterations used to read as "iteration_limit".
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, Vec3::Zero())};
    ResolverSettings s = plain_settings();
    s.position_method = PositionMethod::relaxation;
    s.relaxation = {0.5, 4};
    const ResolutionSummary summary =
        resolve_contacts(bodies, std::vector{contact(0, world_body, {0, -0.5, 0}, {0, 1, 0}, 1.0)}, s);
    CHECK(summary.position.iterations_used == 4);
    CHECK(summary.position.stop == StopReason::passes_complete);
    // One more pass than the limit allows is cut short, and says so.
    s.relaxation.passes = 5;
    std::vector<RigidBody> again{sphere(1.0, 0.5, Vec3::Zero())};
    CHECK(resolve_contacts(again, std::vector{contact(0, world_body, {0, -0.5, 0}, {0, 1, 0}, 1.0)}, s).position.stop ==
          StopReason::iteration_limit);
}

TEST_CASE("the angular limit never translates a body that cannot translate") {
    // Regression: a pivot (inverse mass 0, free to turn) whose angular move is cut back had the excess given
    // to its linear move, moving an infinitely heavy body. Now the excess stays as penetration.
    RigidBody pivot;
    pivot.inverse_mass = 0.0;
    pivot.inverse_inertia_body = Mat3::Identity();
    const std::vector<RigidBody> bodies{pivot};
    const PreparedContact p = prepared(contact(0, world_body, {1, -0.5, 0}, {0, 1, 0}, 1.0), bodies);
    const PositionResolution r = nonlinear_projection(
        p, mass_of(p.bodies, bodies), 1.0, {AngularLimitPolicy::lever_arm, 0.2}, OrientationUpdate::first_order);
    CHECK(*r.angular_limit->applied[0]);
    CHECK_CLOSE(*r.moves.angular_move[0], 0.2);
    CHECK(*r.moves.linear_move[0] == 0.0);
    CHECK(*r.change.linear_change[0] == Vec3::Zero());
}

TEST_CASE("linear projection leaves a contact it cannot move instead of spending every iteration on it") {
    // Regression: both bodies can turn but not translate, so linear projection moves nothing; it used to
    // choose the same contact until the iteration limit.
    RigidBody a, b;
    a.inverse_mass = b.inverse_mass = 0.0;
    b.position = {0, -1, 0};
    std::vector<RigidBody> bodies{a, b};
    ResolverSettings s = plain_settings();
    s.position_method = PositionMethod::linear_projection;
    const ResolutionSummary summary =
        resolve_contacts(bodies, std::vector{contact(0, 1, {0.3, -0.5, 0}, {0, 1, 0}, 0.2)}, s);
    CHECK(summary.position.iterations_used == 0);
    CHECK(summary.position.stop == StopReason::unmovable_left);
}
