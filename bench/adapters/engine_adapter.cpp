#include "bench/adapters/engine_adapter.hpp"

#include "formats/input_error.hpp"

#include <cmath>
#include <string>

namespace impulse::bench {

void check_scene_for_engine(const Scene& scene, std::string_view engine) {
    if (!scene.contacts.empty())
        throw formats::InputError("contacts", std::string(engine) +
                                                  " runs scenes with collision detection only; this scene has contacts "
                                                  "written by hand");
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const RigidBody& b = scene.bodies[i];
        if (b.inverse_mass == 0.0) continue;
        const Mat3& k = b.inverse_inertia_body;
        const bool diagonal =
            k(0, 1) == 0.0 && k(0, 2) == 0.0 && k(1, 0) == 0.0 && k(1, 2) == 0.0 && k(2, 0) == 0.0 && k(2, 1) == 0.0;
        if (!diagonal || !(k.diagonal().array() > 0.0).all())
            throw formats::InputError(
                formats::json_path_index("bodies", i),
                std::string(engine) +
                    " takes principal moments of inertia: the inverse inertia must be diagonal in "
                    "the body's axes and positive");
    }
}

double mass_of(const RigidBody& body) {
    return body.inverse_mass > 0.0 ? 1.0 / body.inverse_mass : 0.0;
}

Vec3 principal_inertia_of(const RigidBody& body) {
    if (body.inverse_mass == 0.0) return Vec3::Zero();
    return body.inverse_inertia_body.diagonal().cwiseInverse();
}

double damping_per_step(double kept_per_second, double dt) {
    return 1.0 - std::pow(kept_per_second, dt);
}

}  // namespace impulse::bench
