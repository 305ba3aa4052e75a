// Friction right in every direction. The box (0.8 x 0.5 x 0.6 m, 2 kg, mu = 0.5, turned 30 degrees about
// the vertical, sent at 4 m/s along world x): the same scene turned as a whole moves the same way, turned; sliding
// on level ground it stops where Coulomb friction says, without turning or veering; on a slope steeper than
// atan mu it slides with g (sin - mu cos), below it holds.
//
// The methods checked: the accumulating ones (pgs, pgs_split, soft_step: methods/contact_rows.hpp) and the
// worst-first family with sliding_friction = against_slip (derivation/impulse.hpp). The book's own sliding model
// (reference) is the reference engine's and fails these on purpose (docs/methods.md measures it).

#if IMPULSE_HAVE_RAPIDCHECK  // property tests need rapidcheck (not in the engine-only build)
#include "support/gravity_and_frame.hpp"
#include "support/property.hpp"
#endif
#include "support/sliding_box.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace impulse;

namespace {

using impulse::test::g;
constexpr double mu = test::sliding_box_friction;
constexpr double degree = std::numbers::pi / 180.0;

struct Method {
    std::string preset;
    std::vector<std::string> settings;
    bool accumulates;  // pgs, pgs_split, soft_step, avbd; otherwise one-shot impulses (worst_first, sequential_sweep)
};

const std::vector<Method> methods{{"pgs", {}, true},
                                  {"pgs_split", {}, true},
                                  {"soft_step", {}, true},
                                  {"avbd", {}, true},
                                  {"book", {"sliding_friction=against_slip"}, false},
                                  {"sweep", {"sliding_friction=against_slip"}, false}};

Scene with(Scene scene, const Method& m) {
    for (const std::string& s : m.settings) formats::apply_setting(scene, s, "--set");
    return scene;
}

std::string name_of(const Method& m) {
    return m.preset + (m.settings.empty() ? "" : " " + m.settings.front());
}

// Where the box is when it no longer moves forward: its velocity along its start direction first falls to
// 0.02 m/s or below (the worst-first family leaves up to its velocity epsilon, 0.01 m/s, unresolved per contact,
// and the sweep creeps at rest afterwards, so neither reaches exactly 0), within 4 s.
struct Stop {
    bool stopped = false;
    double along = 0.0;     // distance along the start direction (m)
    double sideways = 0.0;  // distance across it (m)
    double turned = 0.0;    // yaw change (radians)
};

Stop slide(const Scene& scene) {
    World world(scene);
    const std::vector<RigidBody>& bodies = world.bodies();
    const Vec3 forward = scene.bodies[0].velocity.normalized();
    const Vec3 left = Vec3::UnitY().cross(forward);
    Stop stop;
    for (int frame = 0; frame < 240 && !stop.stopped; ++frame) {
        world.step();
        stop.stopped = frame > 5 && bodies[0].velocity.dot(forward) <= 0.02;
    }
    const Vec3 moved = bodies[0].position - scene.bodies[0].position;
    stop.along = moved.dot(forward);
    stop.sideways = moved.dot(left);
    stop.turned = test::yaw_of(bodies[0]) - test::yaw_of(scene.bodies[0]);
    return stop;
}

// The two ways the turned box is sent: along its own long axis (the issue's), and along world x, 30 degrees
// across its axes (so every corner's K couples the slip with the sideways direction differently).
const std::vector<Vec3> start_velocities{{4 * std::cos(30 * degree), 0, -4 * std::sin(30 * degree)}, {4, 0, 0}};

// Every corner of the box, world: its position and its orientation at once, in metres.
[[maybe_unused]] std::vector<Vec3> corners(const RigidBody& box) {
    std::vector<Vec3> out;
    for (int v = 0; v < 8; ++v)
        out.push_back(box.position + box.orientation * box_vertex(test::sliding_box_half_size, v));
    return out;
}

}  // namespace

#if IMPULSE_HAVE_RAPIDCHECK
TEST_CASE(
    "a scene turned as a whole by any rotation moves the same way turned, within 1e-9 m after 2 s (floats 2e-5)") {
    // Physics has no preferred direction; the engine's tangent basis does (it is seeded from world axes), so
    // nothing may depend on it: the friction rows are solved together against the slip and projected onto the
    // cone in K's metric, early stops compare norms. Measured (20 rotations, 2 s): every preset within 1.8e-14 m.
    // Before the rows were written once: soft step (one friction axis at a time) 0.28 m, pgs 7.6e-5 m and
    // pgs_split 5.1e-5 m (an early stop on the largest component). Eight rotations per preset keep the test to
    // seconds under the sanitizers. soft_step_wide solves in floats (2^-24 of each velocity change), and the box slides
    // 1.6 m: 5.0e-6 m at most over 100 rotations, so within 2e-5 m there.
    for (const std::string_view preset : preset_names()) {
        CAPTURE(preset);
        const Scene scene = test::sliding_box(std::string(preset));
        const double within = scene.settings.soft_step.order == SolveOrder::wide ? 2e-5 : 1e-9;
        const std::vector<Vec3> plain = corners(test::simulate_frames(scene, 120)[0]);
        test::check_property(
            "turned " + std::string(preset),
            [&] {
                // A uniformly random rotation from three uniform numbers (Shoemake's method).
                const double u1 = *rc::gen::inRange(0, 1 << 20) / double(1 << 20);
                const double u2 = *rc::gen::inRange(0, 1 << 20) / double(1 << 20);
                const double u3 = *rc::gen::inRange(0, 1 << 20) / double(1 << 20);
                const double two_pi = 2.0 * std::numbers::pi;
                const Quat turn(std::sqrt(u1) * std::cos(two_pi * u3), std::sqrt(1 - u1) * std::sin(two_pi * u2),
                                std::sqrt(1 - u1) * std::cos(two_pi * u2), std::sqrt(u1) * std::sin(two_pi * u3));
                const std::vector<Vec3> moved = corners(test::simulate_frames(test::turned(scene, turn), 120)[0]);
                for (std::size_t k = 0; k < plain.size(); ++k) RC_ASSERT((turn * plain[k] - moved[k]).norm() < within);
            },
            8);
    }
}
#endif

TEST_CASE("a box sliding at 4 m/s on level ground stops within 5 % of v0^2 / (2 mu g), without turning or veering") {
    // v0^2 / (2 mu g) = 16 / 9.81 = 1.631 m. The frame's integration moves the box by its speed before friction
    // acts, which adds about v0 h / 2 = 3 cm (2 %). Measured (along its axis / along world x): pgs 1.6065 m both,
    // pgs_split 1.6644, soft_step 1.6223, avbd 1.5977, worst-first against_slip 1.6665 / 1.6655, the sweep against_slip
    // 1.6670 / 1.6663. (Before: pgs 1.7015 / 1.6558 m, pgs_split 1.7599 / 1.7140, soft_step 1.6916 / 1.6223.)
    // Veering is the distance across the start direction when the box stops, turning its change of heading.
    // The accumulating methods share the weight between the corners evenly, so nothing turns the box: within
    // 1 mm and 0.1 degree (measured under 0.2 mm and 0.03 degree; before, pgs veered 180 mm and turned 9 degrees
    // when sent along world x). The worst-first family gives each corner its whole impulse at once, so the
    // corners carry the weight unevenly, and friction at unevenly loaded corners lying unevenly about the path
    // turns a box whose sides are not square to it: within 2 cm and 3 degrees (measured: worst-first 0.1 mm and
    // 0.0 degree / 0.5 mm and 2.4 degrees; the sweep 14.7 mm and 1.6 degrees / 6.6 mm and 0.3 degree). The
    // reference sliding model veers up to 24 cm and turns up to 9 degrees.
    const double expected = 4.0 * 4.0 / (2.0 * mu * g);
    for (const Vec3& velocity : start_velocities)
        for (const Method& m : methods) {
            CAPTURE(name_of(m));
            CAPTURE(velocity.transpose());
            const Stop stop = slide(with(test::sliding_box(m.preset, 30.0, velocity), m));
            REQUIRE(stop.stopped);
            CHECK(std::abs(stop.along / expected - 1.0) < 0.05);
            CHECK(std::abs(stop.sideways) < (m.accumulates ? 1e-3 : 2e-2));
            CHECK(std::abs(stop.turned) < (m.accumulates ? 0.1 : 3.0) * degree);
        }
}

TEST_CASE("the reference sliding model carries the box too far, as the reference engine does") {
    // Along the in-plane part of the static 3x3 impulse, applied one corner at a time and never taken back: at a
    // corner that direction is not against the slip. Measured (along its axis / along world x): worst-first
    // +13.6 % / +9.2 %, 96 / 238 mm sideways, 3.3 / 8.0 degrees; the sweep +13.7 % / +8.6 %, 16 / 225 mm,
    // 0.5 / 9.2 degrees. Changing this is not the book's to do: the book preset reproduces the reference engine.
    const double expected = 4.0 * 4.0 / (2.0 * mu * g);
    for (const Vec3& velocity : start_velocities)
        for (const std::string preset : {"book", "sweep"}) {
            CAPTURE(preset);
            const Stop stop = slide(test::sliding_box(preset, 30.0, velocity));
            CHECK(stop.along / expected - 1.0 > 0.08);
        }
    CHECK(std::abs(slide(test::sliding_box("book", 30.0, start_velocities[0])).sideways) > 0.05);
}

TEST_CASE("on a slope steeper than atan mu the box slides with g (sin - mu cos) within 3 %") {
    // 30 degrees > atan 0.5 = 26.6 degrees: a = 9.81 (0.5 - 0.5 x 0.866) = 0.657 m/s^2, measured between 1 s and
    // 5 s (the first second lets the start settle). Measured: the accumulating methods 0.6571 (to 1e-4), the
    // worst-first family against_slip 0.6582 (+0.2 %).
    const double a = g * (std::sin(30 * degree) - mu * std::cos(30 * degree));
    for (const Method& m : methods) {
        CAPTURE(name_of(m));
        const Scene scene = with(test::on_slope(test::sliding_box(m.preset, 30.0, Vec3::Zero()), 30.0), m);
        World world(scene);
        const std::vector<RigidBody>& bodies = world.bodies();
        double at_one_second = 0.0;
        for (int frame = 0; frame < 300; ++frame) {
            world.step();
            if (frame == 59) at_one_second = bodies[0].velocity.x();
        }
        CHECK(std::abs((bodies[0].velocity.x() - at_one_second) / 4.0 / a - 1.0) < 0.03);
    }
}

TEST_CASE("on a slope below atan mu the box holds within 5 mm over 5 s with the accumulating methods") {
    // 20 degrees < 26.6: friction can hold the box, and it must, in the ground's plane (the normal settling of
    // Baumgarte's bias is not sliding). Measured: pgs 1.6 mm, pgs_split 1.7 mm, soft_step 0.06 mm, avbd < 1e-4 mm.
    // The worst-first family is not held to this, with either sliding model: it creeps even when no contact can
    // slide at all (mu = 10: worst-first 14 mm, the sweep 41 mm), because static impulses given one corner at a
    // time and never taken back over-push some corners, which separate just under the velocity epsilon, and the
    // box rocks and walks; the 0.01 m/s epsilon alone allows 50 mm in 5 s (docs/methods.md).
    for (const Method& m : methods) {
        if (!m.accumulates) continue;
        CAPTURE(name_of(m));
        const Scene scene = with(test::on_slope(test::sliding_box(m.preset, 30.0, Vec3::Zero()), 20.0), m);
        const RigidBody box = test::simulate_frames(scene, 300)[0];
        const Vec3 moved = box.position - scene.bodies[0].position;
        CHECK(std::hypot(moved.x(), moved.z()) < 5e-3);
    }
}
