#include "derivation/avbd/body_block.hpp"

namespace impulse {

BodyMass body_mass(const RigidBody& body, const MassProperties& mass) {
    BodyMass m;
    m.translates = mass.inverse_mass > 0.0;
    m.mass = m.translates ? 1.0 / mass.inverse_mass : 0.0;
    // Cholesky of I^-1 (square roots only, so native and WebAssembly agree to the bit): I = (L L^T)^-1.
    const Eigen::LLT<Mat3> factor(mass.inverse_inertia_world);
    if (factor.info() == Eigen::Success && factor.matrixLLT().diagonal().minCoeff() > 0.0) {
        m.inertia = factor.solve(Mat3::Identity());
        return m;
    }
    // I^-1 singular (or zero): invert it on the principal axes it turns about, hold the others. A body-frame I^-1
    // given diagonal (the usual way to let a body turn about some axes only) is its own principal form, exactly;
    // otherwise principal_inertia's closed form, whose zero moments come out near 1e-9 of the largest.
    m.turns_freely = false;
    m.turn_axes = Mat3::Zero();
    const Mat3& inverse_body = body.inverse_inertia_body;
    const bool diagonal = Mat3(inverse_body - Mat3(inverse_body.diagonal().asDiagonal())).isZero(0.0);
    const PrincipalInertia principal =
        diagonal ? PrincipalInertia{Mat3::Identity(), inverse_body.diagonal()} : principal_inertia(body);
    const double largest = principal.inverse_moments.cwiseAbs().maxCoeff();
    const double zero = diagonal ? 0.0 : 1e-6 * largest;
    const Mat3 rotation = body.orientation.toRotationMatrix();
    for (int k = 0; k < 3; ++k) {
        const double e = principal.inverse_moments[k];
        if (largest == 0.0 || e <= zero) continue;
        const Vec3 axis = rotation * principal.axes.col(k);  // world
        m.inertia += (axis * axis.transpose()) / e;
        m.turn_axes += axis * axis.transpose();
    }
    return m;
}

BodyBlock inertial_block(const BodyMass& mass, double h, const Displacement& target, const Displacement& displacement) {
    const double inv_h2 = 1.0 / (h * h);
    BodyBlock b;
    b.block_matrix.setZero();
    b.block_matrix.topLeftCorner<3, 3>().diagonal().setConstant(mass.mass * inv_h2);  // m / h^2  (Eq. 6)
    b.block_matrix.bottomRightCorner<3, 3>() = mass.inertia * inv_h2;                 // I / h^2
    b.block_force << (mass.mass * inv_h2) * (target.linear - displacement.linear),    // M / h^2 (y - x)  (Eq. 5)
        (mass.inertia * inv_h2) * (target.angular - displacement.angular);
    return b;
}

void hold_fixed_directions(const BodyMass& mass, BodyBlock& io_block) {
    Mat6& H = io_block.block_matrix;
    Vec6& f = io_block.block_force;
    if (!mass.translates) {
        H.topRows<3>().setZero();
        H.leftCols<3>().setZero();
        H.topLeftCorner<3, 3>().setIdentity();
        f.head<3>().setZero();
    }
    if (!mass.turns_freely) {
        // P H P + (1 - P) on the rotation rows, P on their couplings: the solve's turn lies along P's axes.
        const Mat3& P = mass.turn_axes;
        const Mat3 rotation = P * H.bottomRightCorner<3, 3>() * P + (Mat3::Identity() - P);
        H.bottomRightCorner<3, 3>() = rotation;
        H.topRightCorner<3, 3>() = H.topRightCorner<3, 3>() * P;
        H.bottomLeftCorner<3, 3>() = P * H.bottomLeftCorner<3, 3>();
        f.tail<3>() = P * f.tail<3>();
    }
}

}  // namespace impulse
