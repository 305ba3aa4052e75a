#pragma once
// The sliding box of docs/methods.md's friction measurements: a 0.8 x 0.5 x 0.6 m box of 2 kg on ground with
// mu = 0.5 (restitution 0), turned 30 degrees about the vertical and sent at 4 m/s along world x, and the same
// scene on a slope or turned as a whole.

#include "formats/settings_json.hpp"
#include "math/rotation.hpp"
#include "scene/scene.hpp"
#include "world/world.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace impulse::test {

inline constexpr double sliding_box_mass = 2.0;
inline constexpr double sliding_box_friction = 0.5;
inline const Vec3 sliding_box_half_size{0.4, 0.25, 0.3};

// The box at rest 1 mm into level ground (so every corner is a contact from the first frame, whichever way
// rounding falls), turned `yaw_deg` about +y, moving at `velocity`; the scene's settings are `preset`'s.
inline Scene sliding_box(const std::string& preset_name, double yaw_deg = 30.0, const Vec3& velocity = {4, 0, 0}) {
    Scene scene;
    formats::apply_setting(scene, "preset=" + preset_name, "--set");
    scene.materials[default_material] = Material{0.0, sliding_box_friction};
    scene.ground = Ground{};
    RigidBody box;
    box.inverse_mass = 1.0 / sliding_box_mass;
    box.inverse_inertia_body = box_inverse_inertia(box.inverse_mass, sliding_box_half_size);
    box.position = {0.0, sliding_box_half_size.y() - 0.001, 0.0};
    box.orientation = Quat(Eigen::AngleAxisd(yaw_deg * std::numbers::pi / 180.0, Vec3::UnitY()));
    box.velocity = velocity;
    scene.bodies = {box};
    scene.body_names = {"box"};
    scene.shapes = {Shape{Box{sliding_box_half_size}}};
    scene.body_materials = {default_material};
    return scene;
}

// The whole scene turned by `turn` about the origin: bodies (positions, orientations, velocities), the ground's
// normal and gravity. Physics has no preferred direction, so its motion is the original's, turned.
inline Scene turned(Scene scene, const Quat& turn) {
    const Mat3 r = turn.toRotationMatrix();
    for (RigidBody& b : scene.bodies) {
        b.position = r * b.position;
        b.orientation = (turn * b.orientation).normalized();
        b.velocity = r * b.velocity;
        b.angular_velocity = r * b.angular_velocity;
    }
    if (scene.ground) scene.ground->plane.normal = r * scene.ground->plane.normal;
    scene.world.gravity = r * scene.world.gravity;
    return scene;
}

// The scene on a slope of `degrees`: gravity tilted by that angle about +z, so the ground falls away along +x.
// (Turning gravity instead of the ground keeps the box on the ground as built.)
inline Scene on_slope(Scene scene, double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    scene.world.gravity = 9.81 * Vec3(std::sin(a), -std::cos(a), 0.0);
    return scene;
}

// Runs `frames` frames from the scene's start; returns the bodies.
inline std::vector<RigidBody> simulate_frames(const Scene& scene, int frames) {
    World world(scene);
    for (int frame = 0; frame < frames; ++frame) world.step();
    return world.bodies();
}

// The box's yaw about +y (radians), from where its x axis points.
inline double yaw_of(const RigidBody& box) {
    const Vec3 x = box.orientation * Vec3::UnitX();
    return std::atan2(-x.z(), x.x());
}

}  // namespace impulse::test
