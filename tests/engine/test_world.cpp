// The world step against analytic answers: free fall, bounces, resting contact, momentum, robustness and
// determinism.

#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "support/approx.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace impulse;

namespace {

Scene shipped_scene(const std::string& name, const std::vector<std::string>& settings = {}) {
    Scene scene = test::shipped(name);
    for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
    return scene;
}

Scene one_body(const Shape& shape, const Vec3& position, bool ground) {
    Scene s;
    s.body_names = {"body"};
    RigidBody b;
    b.position = position;
    b.inverse_mass = 1.0;
    b.inverse_inertia_body = solid_inverse_inertia(shape, 1.0);
    s.bodies = {b};
    s.shapes = {shape};
    s.body_materials = {default_material};
    s.materials = {{default_material, Material{}}};
    if (ground) s.ground = Ground{};
    return s;
}

}  // namespace

TEST_CASE("free fall follows x0 + v0 t + 1/2 g t^2 within the semi-implicit Euler error") {
    // Semi-implicit Euler: v_n = v0 + n g dt, x_n = x0 + v0 n dt + g dt^2 n (n + 1) / 2, which is the exact
    // parabola plus 1/2 g dt t: at t = 1 s and dt = 1/60, 1/2 9.81 / 60 = 0.0818 m lower.
    Scene s = one_body(Sphere{0.5}, {0, 10, 0}, false);
    s.bodies[0].velocity = {1, 2, 0};
    World world(s);
    const int n = 60;
    const double dt = s.settings.duration, t = n * dt, g = -9.81;
    for (int frame = 0; frame < n; ++frame) world.step();
    const std::vector<RigidBody>& bodies = world.bodies();
    const Vec3 exact(t, 10 + 2 * t + 0.5 * g * t * t, 0);
    const Vec3 semi_implicit(t, 10 + 2 * t + g * dt * dt * n * (n + 1) / 2.0, 0);
    CHECK_CLOSE(bodies[0].position, semi_implicit, 1e-12);
    CHECK_CLOSE(bodies[0].velocity, Vec3(1, 2 + g * t, 0), 1e-12);
    CHECK(bodies[0].last_frame_acceleration == Vec3(0, g, 0));
    // First order: with half the step over the same second the error against the parabola halves.
    Scene fine = s;
    fine.settings.duration = dt / 2;
    World finer(fine);
    for (int frame = 0; frame < 2 * n; ++frame) finer.step();
    const double coarse_error = bodies[0].position.y() - exact.y(),
                 fine_error = finer.bodies()[0].position.y() - exact.y();
    CHECK(coarse_error == doctest::Approx(0.5 * g * dt * t));
    CHECK(fine_error / coarse_error == doctest::Approx(0.5));
}

TEST_CASE("a ball dropped from 1 m with restitution 0.6 rises to about c^2 h = 0.36 m") {
    // It lands at about sqrt(2 g h) = 4.43 m/s. Two effects of a discrete step lower the first apex, and both
    // are expected: the book preset does not bounce back the g dt = 0.16 m/s that gravity added during the
    // last frame (velocity_from_acceleration), taking the rebound from 2.66 to 2.55 m/s (-7 %); and semi-implicit
    // Euler, sampled at frames, peaks about v' dt / 2 = 2 cm below v'^2 / 2g (-6 %). So the apex is within
    // 20 % below 0.36 m, and closer with the refinement off.
    const auto first_apex = [](const std::vector<std::string>& settings) {
        World world(shipped_scene("sphere_drop", settings));
        const std::vector<RigidBody>& bodies = world.bodies();
        double apex = 0.0;
        bool bounced = false;
        for (int frame = 0; frame < 240; ++frame) {
            world.step();
            const double height = bodies[0].position.y() - 0.5;
            if (!bounced && bodies[0].velocity.y() > 0) bounced = true;
            if (bounced && bodies[0].velocity.y() < 0) break;  // past the first apex
            if (bounced) apex = std::max(apex, height);
        }
        return apex;
    };
    const double book = first_apex({});
    CHECK(book > 0.8 * 0.36);
    CHECK(book < 0.36);
    const double plain = first_apex({"velocity_from_acceleration=false"});
    CHECK(plain > book);
    CHECK(plain > 0.9 * 0.36);
    CHECK(plain < 0.36 * 1.02);
}

TEST_CASE("a resting box sinks no deeper than the book's position epsilon and one frame's fall") {
    // The book leaves penetrations up to 0.01 m alone; each frame gravity adds g dt^2 = 2.7 mm before the
    // contact is detected. So the box never sinks more than 0.01 + 0.0027 m.
    World world(shipped_scene("box_resting"));
    double deepest = 0.0;
    for (int frame = 0; frame < 600; ++frame) {
        const StepReport r = world.step();
        deepest = std::max(deepest, r.deepest_penetration);
        CHECK(r.contacts == 4);
    }
    CHECK(deepest <= 0.01 + 9.81 / 3600.0 + 1e-9);
}

TEST_CASE("with epsilons of 0.5 mm and 0.1 mm/s a resting box stays within 1 mm over 10 s") {
    // The target. With the book's own epsilons (1 cm, 0.01 m/s) the box instead settles up to 1 cm
    // in and creeps sideways by the friction residue the velocity epsilon leaves each frame (27.7 mm in
    // 10 s, see the closing note); the method, not the contacts, sets that floor.
    World world(shipped_scene("box_resting", {"position_epsilon=0.0005", "velocity_epsilon=0.0001"}));
    double drift = 0.0;
    for (int frame = 0; frame < 600; ++frame) {
        world.step();
        drift = std::max(drift, (world.bodies()[0].position - world.scene().bodies[0].position).norm());
    }
    CHECK(drift < 0.001);
}

TEST_CASE("momentum is conserved when two spheres collide") {
    World world(shipped_scene("two_spheres"));
    const std::vector<RigidBody>& bodies = world.bodies();
    const auto momentum = [](const std::vector<RigidBody>& b) {
        Vec3 p = Vec3::Zero();
        for (const RigidBody& body : b) p += body.velocity / body.inverse_mass;
        return p;
    };
    const Vec3 before = momentum(bodies);
    int contacts = 0;
    for (int frame = 0; frame < 120; ++frame) {
        contacts += world.step().contacts;
        CHECK_CLOSE(momentum(bodies), before, 1e-12);
    }
    CHECK(contacts > 0);                   // they did collide
    CHECK(bodies[0].velocity.y() != 0.0);  // obliquely: the small ball was deflected
    CHECK_CLOSE(momentum(bodies), before, 1e-12);
}

TEST_CASE("200 boxes dropped in a pile run 10 s with no NaN and bounded energy") {
    // Bounded: the kinetic energy never exceeds what falling from the start could give (the potential energy
    // above the ground at the start), with 20 % to spare for the position moves' lift.
    World world(shipped_scene("pile_200"));
    double available = 0.0;
    for (const RigidBody& b : world.bodies()) available += 9.81 * b.position.y() / b.inverse_mass;
    double most = 0.0;
    bool finite = true;
    for (int frame = 0; frame < 600; ++frame) {
        const StepReport r = world.step();
        most = std::max(most, r.kinetic_energy);
        for (const RigidBody& b : world.bodies())
            finite = finite && b.position.allFinite() && b.velocity.allFinite() && b.angular_velocity.allFinite() &&
                     b.orientation.coeffs().allFinite();
    }
    CHECK(finite);
    CHECK(most < 1.2 * available);
}

TEST_CASE("running a scene twice gives byte-identical traces") {
    const auto trace_text = [] {
        Trace trace;
        trace.scene = shipped_scene("stack_3");
        trace.recording.last_frame = 29;
        World world(trace.scene);
        TraceRecorder recorder(trace);
        for (int frame = 0; frame < 60; ++frame) world.step(recorder);
        return formats::format_json(formats::trace_json(trace));
    };
    const std::string first = trace_text();
    CHECK(first == trace_text());
    CHECK(first.size() > 10000);
}

TEST_CASE("a trace of a run records why each contact exists and reads back equal") {
    Trace trace;
    trace.scene = shipped_scene("box_tipping");
    World world(trace.scene);
    TraceRecorder recorder(trace);
    for (int frame = 0; frame < 40; ++frame) world.step(recorder);
    REQUIRE(trace.frames.size() == 40);
    // It starts on an edge: two vertex contacts with the ground plane.
    const auto& first = trace.frames[0].contacts;
    REQUIRE(first.size() == 2);
    for (const ContactPreparation& c : first) {
        CHECK(c.origin.test == CollisionTest::box_half_space);
        CHECK(c.origin.features[0].kind == FeatureKind::vertex);
        CHECK(c.origin.features[1].kind == FeatureKind::plane);
    }
    CHECK(formats::read_trace_text(formats::format_json(formats::trace_json(trace))) == trace);
}

TEST_CASE("the contact blamed for a body is the last one resolved on it, whichever phase") {
    // Contacts: 0 between bodies 0 and 1, 1 between body 1 and the world, 2 between body 2 and the world.
    // Resolved in the order 1 (position), 0 (position), 2 (velocity), 1 (velocity): body 0 was last touched
    // by contact 0, body 1 by contact 1 (its second visit), body 2 by contact 2; body 3 by none.
    std::vector<Contact> contacts(3);
    contacts[0].bodies = {0, 1};
    contacts[1].bodies = {1, world_body};
    contacts[2].bodies = {2, world_body};
    LastTouch touch(contacts);
    for (const int contact : {1, 0, 2, 1}) touch.touched(contact);
    CHECK(touch.last_contact(0) == 0);
    CHECK(touch.last_contact(1) == 1);
    CHECK(touch.last_contact(2) == 2);
    CHECK_FALSE(touch.last_contact(3).has_value());
    CHECK(touch.bodies_of(0) == std::array<int, 2>{0, 1});
}

TEST_CASE("a run of visits stamped out of order blames as the visits in order would") {
    // Contacts 0 to 3 on body 0, visited in the order 2, 0, 3, 1 (contact k is visit place[k]) after a visit of
    // contact 1, and before one of contact 3. Stamped in the contacts' order, the run must blame as the visits' order.
    std::vector<Contact> contacts(4);
    for (Contact& c : contacts) c.bodies = {0, world_body};
    const std::array<std::size_t, 4> place{1, 3, 0, 2};
    LastTouch in_order(contacts), by_run(contacts);
    for (LastTouch* touch : {&in_order, &by_run}) touch->touched(1);
    for (const int contact : {2, 0, 3, 1}) in_order.touched(contact);
    const LastTouch::Run run = by_run.run(4);
    for (int k = 0; k < 4; ++k) run.visit(k, place[static_cast<std::size_t>(k)]);
    CHECK(by_run.last_contact(0) == 1);  // the run's last visit
    for (LastTouch* touch : {&in_order, &by_run}) touch->touched(3);
    CHECK(in_order.last_contact(0) == 3);
    CHECK(by_run.last_contact(0) == 3);  // the run counted its four visits: the visit after comes later
}
