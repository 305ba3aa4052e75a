#include "body/rigid_body.hpp"

namespace impulse {

Mat3 world_inverse_inertia(const RigidBody& body) {
    const Mat3 rotation = body.orientation.toRotationMatrix();
    return rotation * body.inverse_inertia_body * rotation.transpose();
}

bool is_immovable(const RigidBody& body) {
    return body.inverse_mass == 0.0 && body.inverse_inertia_body.isZero(0.0);
}

double kinetic_energy(const RigidBody& body) {
    double energy = 0.0;
    if (body.inverse_mass > 0.0) energy += 0.5 * body.velocity.squaredNorm() / body.inverse_mass;
    if (!body.inverse_inertia_body.isZero(0.0)) {
        const Mat3 inertia = world_inverse_inertia(body).completeOrthogonalDecomposition().pseudoInverse();
        energy += 0.5 * body.angular_velocity.dot(inertia * body.angular_velocity);
    }
    return energy;
}

}  // namespace impulse
