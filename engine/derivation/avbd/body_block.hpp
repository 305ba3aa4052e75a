#pragma once
// One body's block (AVBD's primal update; VBD's vertex block, for a rigid body six coordinates at once). With the other
// bodies held where they are, the part of G (derivation/avbd/implicit_euler.hpp) that moves with body i is
//   G_i(x_i) = 1/(2h^2) |x_i - y_i|^2_M_i + sum over its contacts of their energy,
// and one Newton step on it is the block solve H_i delta x_i = f_i (Eq. 4) with
//   H_i = M_i / h^2 + sum_c sum_a k_a J_a,i J_a,i^T                              (Eqs. 6, 17)
//   f_i = M_i / h^2 (y_i - x_i) + sum_c sum_a F_a J_a,i                           (Eqs. 5, 13)
// f_i is minus G_i's gradient: the inertial pull towards the target y_i and the contact forces (N, and N m for the
// rotation rows); H_i its Hessian, M_i = diag(m 1, I) with I the world inertia at the frame's start. The Hessian of a
// constraint energy is k J J^T + F d^2C/dx^2; AVBD keeps H symmetric positive definite by approximating the second
// term with a lumped diagonal of its size (Sec. 3.5, Eq. 17). A linearised contact (Sec. 4) has d^2C/dx^2 = 0, so
// for contacts that term is exactly zero here, and H is M/h^2 (positive definite) plus sums of k J J^T (k >= 0).

#include "derivation/avbd/contact_constraint.hpp"
#include "derivation/avbd/contact_force.hpp"
#include "derivation/avbd/implicit_euler.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"

namespace impulse {

// A body's mass as its block reads it: M = diag(m 1, I). A body that cannot translate (m^-1 = 0) or turns about
// only some axes (I^-1 singular) is held along the other directions.
struct BodyMass {
    double mass = 0.0;                  // m (kg); 0 when it cannot translate
    Mat3 inertia = Mat3::Zero();        // I, world (kg m^2): the inverse of I^-1 on the axes it turns about
    Mat3 turn_axes = Mat3::Identity();  // the projector onto those axes
    bool translates = true;             // m^-1 > 0
    bool turns_freely = true;           // I^-1 invertible: turn_axes = 1
};

// From the mass as the contacts were prepared (the world inverse inertia R I^-1 R^T); a body whose I^-1 is singular
// is inverted on its principal axes (body/rigid_body.hpp's principal_inertia, turned to the world with `body`).
BodyMass body_mass(const RigidBody& body, const MassProperties& mass);

struct BodyBlock {
    Mat6 block_matrix;  // H_i: M/h^2 + sum k J J^T (N/m; N and N m/rad off the diagonal blocks)
    Vec6 block_force;   // f_i: M/h^2 (y - x) + sum F J (N; N m)
};

// The inertia's share (Eqs. 5, 6): H = M/h^2, f = M/h^2 (y - x), with y - x- the inertial target and x - x- the
// body's displacement so far.
BodyBlock inertial_block(const BodyMass& mass, double h, const Displacement& target, const Displacement& displacement);

// A contact's share on the body in `body_slot` (Eqs. 13, 17): f += sum_a F_a J_a,i, H += sum_a k_a J_a,i J_a,i^T,
// with the contact's force and its block stiffness (derivation/avbd/contact_force.hpp).
[[gnu::always_inline]] inline void add_contact_force(const ConstraintJacobian& jacobian, int body_slot,
                                                     const ContactForce& force, BodyBlock& io_block) {
    // The three rows at once. With w_a = (u_a, r x u_a) = (1; [r]x) u_a and J_a,i = s_i w_a (s_i^2 = 1):
    //   sum_a F_a J_a,i     = s_i (F; r x F),                F = sum_a F_a u_a, the force in world axes (Eq. 13)
    //   sum_a k_a J J^T     = (1; [r]x) K (1; [r]x)^T,       K = sum_a k_a u_a u_a^T = k_t 1 + (k_n - k_t) n n^T
    // (Eq. 17): the tangential pair shares k_t, so K needs no tangent and the block turns with the scene.
    const Vec3& n = jacobian.axis[0];
    const Vec3& r = jacobian.relative_position[body_slot];
    const double kn = force.block_stiffness.normal, kt = force.block_stiffness.tangential;
    const Vec3 F = force.force.x() * n + force.force.y() * jacobian.axis[1] + force.force.z() * jacobian.axis[2];
    const Vec3 push = body_sign(body_slot) * F;
    io_block.block_force.head<3>() += push;
    io_block.block_force.tail<3>() += r.cross(push);
    // K, then A = [r]x K (column j: r x K_j) and [r]x K [r]x^T = A [r]x^T (row i: r x A_i).
    const double d = kn - kt;
    double K[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) K[i][j] = d * (n[i] * n[j]) + (i == j ? kt : 0.0);  // symmetric to the bit
    double A[3][3];                                                                     // A = [r]x K
    for (int j = 0; j < 3; ++j) {
        A[0][j] = r.y() * K[2][j] - r.z() * K[1][j];
        A[1][j] = r.z() * K[0][j] - r.x() * K[2][j];
        A[2][j] = r.x() * K[1][j] - r.y() * K[0][j];
    }
    Mat6& H = io_block.block_matrix;
    for (int i = 0; i < 3; ++i) {
        // B = A [r]x^T: B_ij = sum_k A_ik [r]x_jk = (r x A_i)_j, with A_i the i-th row of A; symmetric, so the
        // lower triangle is computed and mirrored.
        const double b[3] = {r.y() * A[i][2] - r.z() * A[i][1], r.z() * A[i][0] - r.x() * A[i][2],
                             r.x() * A[i][1] - r.y() * A[i][0]};
        for (int j = 0; j < 3; ++j) {
            H(i, j) += K[i][j];
            H(3 + i, j) += A[i][j];
            H(j, 3 + i) += A[i][j];
        }
        for (int j = 0; j <= i; ++j) {
            H(3 + i, 3 + j) += b[j];
            if (j != i) H(3 + j, 3 + i) += b[j];
        }
    }
}

// Holds the directions the body cannot move along: there H = 1 and f = 0, so the solve moves it by 0.
void hold_fixed_directions(const BodyMass& mass, BodyBlock& io_block);

}  // namespace impulse
