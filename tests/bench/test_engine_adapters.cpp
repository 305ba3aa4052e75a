// The other engines on the bench (inspector/bench/adapters): each adapter builds our scene in its engine so that
// the engine's own physics gives what it promises (a bounce to the height its restitution model predicts, a box
// at rest staying at rest), and hands the bodies back in our conventions (centre of mass, quaternion [w,x,y,z]
// body -> world, velocities in the world frame). Each engine's cases are compiled when the build has it.

#include "bench/adapters/engine_adapter.hpp"
#include "bench/bench_plan.hpp"
#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace impulse::test {

namespace {

std::unique_ptr<bench::EngineWorld> world_of(std::string_view engine, const Scene& scene, int iterations = 20) {
    const bench::EngineRow* row = bench::find_engine(engine);
    REQUIRE(row != nullptr);
    return row->make(scene, iterations);
}

// A ball of radius 0.5 m dropped from rest with its lowest point 1 m above the ground, restitution 0.5 (the
// ground's 0: combined by the larger), stepped at `dt` (1 ms keeps the step's own error, g dt against the impact
// speed sqrt(2 g h) = 4.43 m/s, at 0.2 %). Returns the highest the lowest point rises after the first bounce.
double bounce_height(std::string_view engine, double dt = 0.001) {
    const Scene scene = formats::read_scene_text(R"({
      "ground": {}, "materials": {"ball": {"restitution": 0.5, "friction": 0.5}},
      "settings": {"duration": 0.01},
      "bodies": [{"shape": {"type": "sphere", "radius": 0.5}, "position": [0, 1.5, 0], "material": "ball"}]})");
    Scene stepped = scene;
    stepped.settings.duration = dt;
    auto world = world_of(engine, stepped);
    std::vector<RigidBody> bodies = scene.bodies;
    bool bounced = false;
    double highest = 0.0;
    for (int frame = 0; frame < static_cast<int>(1.5 / dt); ++frame) {  // the fall takes 0.45 s, the rise 0.23 s
        world->step();
        world->read_bodies(bodies);
        if (!bounced && bodies[0].velocity.y() > 0.0) bounced = true;
        if (bounced) highest = std::max(highest, bodies[0].position.y() - 0.5);
        if (bounced && bodies[0].velocity.y() < 0.0 && bodies[0].position.y() - 0.5 > 0.05) break;  // the apex
    }
    return highest;
}

// A 1 m cube resting on the ground (its centre 0.5 m up), for 2 s at the bench's 1/60 s. Returns its state.
RigidBody resting_box_after_two_seconds(std::string_view engine, int* contacts = nullptr) {
    const Scene scene = formats::read_scene_text(R"({
      "ground": {},
      "bodies": [{"shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0]}]})");
    auto world = world_of(engine, scene);
    std::vector<RigidBody> bodies = scene.bodies;
    for (int frame = 0; frame < 120; ++frame) world->step();
    world->read_bodies(bodies);
    if (contacts) *contacts = world->touching_contacts();
    return bodies[0];
}

// A box of half sizes (0.5, 1, 2) and 2 kg in free flight without gravity, turned 90 degrees about world x (so its
// y axis points along world z), moving at (1, 2, 3) m/s and spinning at 2 rad/s about world z, i.e. about its own
// y axis, a principal axis: the spin stays constant. After 30 steps of 1/60 s, by hand: the centre of mass at
// p0 + v t = (1, 2, 3) + (1, 2, 3) 0.5 = (1.5, 3, 4.5); the orientation turned by 2 x 0.5 = 1 rad about world z
// on top of the first turn, q = R_z(1) R_x(pi/2); the velocity and the angular velocity unchanged, in world axes.
void check_state_hand_back(std::string_view engine) {
    const Scene scene = formats::read_scene_text(R"({
      "gravity": [0, 0, 0],
      "bodies": [{"shape": {"type": "box", "half_size": [0.5, 1, 2]}, "mass": 2, "position": [1, 2, 3],
                  "orientation": [0.7071067811865476, 0.7071067811865476, 0, 0],
                  "velocity": [1, 2, 3], "angular_velocity": [0, 0, 2]}]})");
    auto world = world_of(engine, scene);
    std::vector<RigidBody> bodies = scene.bodies;
    for (int frame = 0; frame < 30; ++frame) world->step();
    world->read_bodies(bodies);
    const RigidBody& b = bodies[0];
    const Quat expected =
        Quat(Eigen::AngleAxisd(1.0, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()));
    CHECK((b.position - Vec3(1.5, 3, 4.5)).norm() < 1e-9);
    // ODE integrates the orientation to first order (its default "infinitesimal" rotation), hence 1e-4 rad.
    CHECK(b.orientation.angularDistance(expected) < 1e-4);
    CHECK(b.orientation.w() > 0.0);  // [w,x,y,z]: w = cos(angle/2) of a turn below pi is positive
    CHECK((b.velocity - Vec3(1, 2, 3)).norm() < 1e-9);
    CHECK((b.angular_velocity - Vec3(0, 0, 2)).norm() < 1e-6);  // world axes, not the body's (0, 2, 0)
    // The masses and inertias stay ours.
    CHECK(b.inverse_mass == doctest::Approx(0.5));
}

// At rest: it slides or tilts no more than `slide` m and `slide` rad (an engine's contact points come and go a
// little), sinks into the ground at most `sink` m (the engine's contact softness, docs/bench.md), is still at
// the end and touches the ground.
void check_box_rests(std::string_view engine, double slide, double sink) {
    int contacts = 0;
    const RigidBody b = resting_box_after_two_seconds(engine, &contacts);
    CHECK(std::hypot(b.position.x(), b.position.z()) < slide);
    CHECK(b.orientation.angularDistance(Quat::Identity()) < slide);
    CHECK(std::abs(b.position.y() - 0.5) < sink);
    CHECK(b.velocity.norm() < 1e-3);
    CHECK(b.angular_velocity.norm() < 1e-2);
    CHECK(contacts >= 1);
}

}  // namespace

TEST_CASE("an engine the build does not have is not found, and the built ones are all named") {
    CHECK(bench::find_engine("havok") == nullptr);
    for (const bench::EngineRow& e : bench::built_engines()) {
        CHECK(bench::find_engine(e.name) == &e);
        CHECK(std::find(bench::engine_names().begin(), bench::engine_names().end(), e.name) !=
              bench::engine_names().end());
    }
}

TEST_CASE("engines refuse a scene with contacts written by hand, naming the engine") {
    const Scene scene = formats::read_scene_text(R"({
      "bodies": [{"shape": {"type": "sphere", "radius": 1}}],
      "contacts": [{"bodies": [0, null], "point": [0, -1, 0], "normal": [0, 1, 0]}]})");
    CHECK_THROWS_WITH_AS(bench::check_scene_for_engine(scene, "ode"),
                         "contacts: ode runs scenes with collision detection only; this scene has contacts written by "
                         "hand",
                         formats::InputError);
}

TEST_CASE("a damping share kept per second becomes the share lost per step") {
    // By hand: keeping 0.5 per second over a step of 0.25 s keeps 0.5^0.25 = 0.8409, so 0.1591 is lost.
    CHECK(bench::damping_per_step(0.5, 0.25) == doctest::Approx(1.0 - std::pow(0.5, 0.25)));
    CHECK(bench::damping_per_step(1.0, 1.0 / 60) == 0.0);
}

#ifdef IMPULSE_HAVE_BULLET
TEST_CASE("bullet: a ball with restitution 0.5 bounces to 0.25 of its drop height, at 1/60 s and at 1 ms") {
    // Bullet's restitution: the separating speed is c times the closing speed it had before the contact's frame
    // (this frame's gravity not counted), so the rise is about c^2 h = 0.25 m. The adapter solves a bouncy body's
    // contacts only once it touches, and pushes an impact's penetration out by the split impulse (ERP2 = 0.8 of the
    // depth, no velocity added), so by hand, stepping v += g dt, y += v dt as Bullet does:
    // - dt = 1/60 s: after 27 frames the ball has fallen g dt^2 (27 x 28 / 2) = 1.03005 m, 3.005 cm into the
    //   ground, at 27 g dt = 4.4145 m/s. The contact's frame sends it up at c 4.4145 = 2.20725 m/s and moves it by
    //   v dt + 0.8 x 0.03005, to 3.078 cm. Then it climbs 13 more frames (13 v dt - g dt^2 (13 x 14 / 2) =
    //   0.23026 m) to 0.26104 m: about c^2 v^2 / 2g (0.2483) plus half a frame's climb (v dt / 2 = 0.0184) less
    //   the 20 % of the depth not pushed out (0.0060).
    // - dt = 1 ms: 452 frames, 4.328 mm deep at 4.43412 m/s, up at 2.21706 m/s from 1.351 mm; apex 0.25077 m.
    CHECK(bounce_height("bullet", 1.0 / 60) == doctest::Approx(0.26104).epsilon(1e-3));
    CHECK(bounce_height("bullet", 0.001) == doctest::Approx(0.25077).epsilon(1e-3));
    // Both within 5 % of c^2 h. With Bullet's 4 cm split-impulse threshold the ball rose 0.68 m at 1/60 s
    // (Baumgarte on the 3 cm of penetration); with its speculative contacts it did not bounce at 1 ms (the
    // contact aims at c |v| - gap / dt).
    CHECK(bounce_height("bullet", 1.0 / 60) == doctest::Approx(0.25).epsilon(0.05));
    CHECK(bounce_height("bullet", 0.001) == doctest::Approx(0.25).epsilon(0.05));
}
TEST_CASE("bullet: a box resting on the ground stays at rest") {
    check_box_rests("bullet", 0.005, 0.005);  // Bullet rocks on its corners: 2 mm
}
TEST_CASE("bullet: bodies come back as centre of mass, quaternion w,x,y,z and world-frame velocities") {
    check_state_hand_back("bullet");
}
#endif

#ifdef IMPULSE_HAVE_ODE
TEST_CASE("ode: a ball with restitution 0.5 bounces to 0.25 of its drop height") {
    // ODE's bounce: the separating speed is `bounce` times the closing speed, so the rise is c^2 h = 0.25 m.
    CHECK(bounce_height("ode") == doctest::Approx(0.25).epsilon(0.03));
}
TEST_CASE("ode: a box resting on the ground stays at rest") {
    check_box_rests("ode", 1e-4, 0.005);
}
TEST_CASE("ode: bodies come back as centre of mass, quaternion w,x,y,z and world-frame velocities") {
    check_state_hand_back("ode");
}
#endif

#ifdef IMPULSE_HAVE_MUJOCO
TEST_CASE("mujoco: a ball with restitution 0.5 bounces to about 0.25 of its drop height") {
    // The adapter sets the contact's damping ratio zeta so that a damped spring returns c of the speed:
    // exp(-pi zeta / sqrt(1 - zeta^2)) = 0.5. MuJoCo's contact lets go when its force reaches zero, a little
    // before the spring's rest length, so the rise is near c^2 h = 0.25 m, not exactly it.
    CHECK(bounce_height("mujoco") == doctest::Approx(0.25).epsilon(0.15));
}
TEST_CASE("mujoco: a box resting on the ground stays at rest") {
    // MuJoCo's contacts are soft: at 1/60 s the stiffest time constant is 2 dt, a spring of 1 / (0.95 x 2 dt)^2 =
    // 997 /s^2 (per unit mass), so gravity presses the box in by about 9.81 / 997 = 1 cm.
    check_box_rests("mujoco", 1e-4, 0.015);
}
TEST_CASE("mujoco: bodies come back as centre of mass, quaternion w,x,y,z and world-frame velocities") {
    check_state_hand_back("mujoco");
}
#endif

}  // namespace impulse::test
