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
        // In body axes: 1/2 w_b . I_b w_b with w_b = R^T w. A singular inverse inertia (a body that turns about
        // some axes only) takes the pseudo-inverse.
        const Vec3 spin = body.orientation.conjugate() * body.angular_velocity;
        const Mat3& inverse = body.inverse_inertia_body;
        const Mat3 inertia = inverse.determinant() != 0.0
                                 ? Mat3(inverse.inverse())
                                 : Mat3(inverse.completeOrthogonalDecomposition().pseudoInverse());
        energy += 0.5 * spin.dot(inertia * spin);
    }
    return energy;
}

}  // namespace impulse
