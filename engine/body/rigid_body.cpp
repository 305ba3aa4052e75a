#include "body/rigid_body.hpp"

namespace impulse {

Mat3 world_inverse_inertia(const RigidBody& body) {
    const Mat3 rotation = body.orientation.toRotationMatrix();
    return rotation * body.inverse_inertia_body * rotation.transpose();
}

bool is_immovable(const RigidBody& body) {
    return body.inverse_mass == 0.0 && body.inverse_inertia_body.isZero(0.0);
}

PrincipalInertia principal_inertia(const RigidBody& body) {
    if (body.inverse_inertia_body.isZero(0.0)) return {};  // it does not turn: no moments
    // The eigen-decomposition of the stored inverse (closed form for a symmetric 3x3).
    Eigen::SelfAdjointEigenSolver<Mat3> eigen;
    eigen.computeDirect(body.inverse_inertia_body);
    return {eigen.eigenvectors(), eigen.eigenvalues()};
}

double kinetic_energy(const RigidBody& body, const PrincipalInertia& principal) {
    double energy = 0.0;
    if (body.inverse_mass > 0.0) energy += 0.5 * body.velocity.squaredNorm() / body.inverse_mass;
    // In body axes: 1/2 w_b . I_b w_b with w_b = R^T w, I_b the inverse of the stored inverse, along its principal
    // axes, so a body that turns about some axes only (zero eigenvalues) counts just those: the pseudo-inverse.
    const Vec3 spin = body.orientation.conjugate() * body.angular_velocity;
    const Vec3 along = principal.axes.transpose() * spin;
    for (int k = 0; k < 3; ++k)
        if (principal.inverse_moments[k] > 0.0) energy += 0.5 * along[k] * along[k] / principal.inverse_moments[k];
    return energy;
}

double kinetic_energy(const RigidBody& body) {
    return kinetic_energy(body, principal_inertia(body));
}

}  // namespace impulse
