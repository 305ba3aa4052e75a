#pragma once
// Another engine (Bullet, ODE, MuJoCo) running one of our scenes beside our methods. An adapter turns a scene
// (boxes, spheres, the ground plane, masses and inertias, materials, gravity, damping, the frame's duration)
// into that engine's world, steps it one frame at a time, and hands the bodies back in our conventions, so the
// bench's own metric code (bench_metrics) measures every column the same way. The settings each engine is
// given, and why, are in docs/bench.md ("Other engines").

#include "scene/scene.hpp"

#include <memory>
#include <span>
#include <string_view>
#include <vector>

namespace impulse::bench {

class EngineWorld {
public:
    virtual ~EngineWorld() = default;

    // One frame of the scene's settings.duration, as one step of the engine (no sub-steps of its own).
    virtual void step() = 0;

    // Writes each body's state after the last step into `ioBodies` (scene order, one per scene body): position
    // of the centre of mass, orientation body -> world (our Quat, written [w,x,y,z]), velocity and angular
    // velocity, all in the world frame. Masses and inertias are left as they are.
    virtual void read_bodies(std::vector<RigidBody>& ioBodies) const = 0;

    // Contact points the last step's collision detection found touching or penetrating (distance <= 0), so
    // "the first contact" means the same frame as for our methods (speculative points within a margin are not
    // counted).
    virtual int touching_contacts() const = 0;
};

struct EngineRow {
    std::string_view name;               // the method name on the command line: "bullet", "ode", "mujoco"
    std::string_view iteration_setting;  // the engine's setting N is written to, for the results
    std::string_view version;            // the library's version, for results.json
    // Builds the scene in the engine with `iterations` solver iterations. Throws formats::InputError for a scene
    // the engine cannot run (hand-written contacts, a body whose inertia is not along its axes, ...).
    std::unique_ptr<EngineWorld> (*make)(const Scene& scene, int iterations);
};

// The engines this build has (each is compiled only when its Debian package was found), in chart order.
std::span<const EngineRow> built_engines();
const EngineRow* find_engine(std::string_view name);

// What every adapter needs from a scene, checked once: no hand-written contacts, each movable body's inverse
// inertia diagonal in body axes and positive (the engines take principal moments). Throws formats::InputError naming
// `engine` and the body.
void check_scene_for_engine(const Scene& scene, std::string_view engine);

// A body's mass and principal moments of inertia (kg, kg m^2) from our inverse values; zero for an immovable body.
double mass_of(const RigidBody& body);
Vec3 principal_inertia_of(const RigidBody& body);

// The share of a velocity a damping setting keeps per second (WorldSettings) as the share lost per step of `dt`:
// v *= d^dt  <=>  v *= 1 - (1 - d^dt).
double damping_per_step(double kept_per_second, double dt);

}  // namespace impulse::bench
