#pragma once
// Step 6, `impulse` and `impulse_world`: the impulse that makes the desired velocity change.
// Frictionless (the chapter, 14.3) when the contact's friction is exactly 0, as in the reference engine;
// otherwise the reference engine's chapter-15 friction impulse: a 3x3 solve in contact coordinates that
// also stops all sliding, limited by the friction cone.

#include "derivation/basis.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "math/full_pivot_lu.hpp"
#include "math/lanes.hpp"
#include "math/types.hpp"

#include <array>
#include <optional>

namespace impulse {

// Where the sliding impulse points when the impulse that would stop the slip lies outside the friction cone.
enum class SlidingFriction {
    // The reference engine's: along the in-plane part of the static 3x3 impulse (K^-1 target). At a corner,
    // where K couples the directions, that is not against the slip: only cos(angle between them) of the
    // friction opposes it, and the rest pushes the body sideways (docs/methods.md measures it).
    reference,
    // Coulomb's: exactly against the contact's current slip, -(v_t1, v_t2) / |v_t|.
    against_slip,
};

enum class ImpulseModel {
    frictionless,      // g = delta v / d along the normal only
    static_friction,   // the solve's impulse lies inside the cone: sliding stops
    sliding_friction,  // outside the cone: the tangential impulse is cut back to mu times the normal one
};

struct FrictionSolve {
    // K: change of contact velocity per unit impulse, both in contact coordinates,
    // K = C^T (sum_i m_i^-1 1 - [q_rel_i]x I_i^-1 [q_rel_i]x) C.
    Mat3 delta_velocity_matrix;
    Vec3 target_delta_velocity;  // (desired delta v, -v_t1, -v_t2): reach the bounce, stop the sliding
    bool solvable;               // K is invertible (false only when neither body can translate)
    Vec3 static_impulse;         // K^-1 target: the impulse if friction can hold
    double tangential_impulse;   // |(g_t1, g_t2)| of the static impulse
    double cone_limit;           // mu g_n of the static impulse
    // Sliding only: the unit tangential direction of the impulse (the static solution's, or against the slip,
    // as SlidingFriction says), and the normal velocity change per unit normal impulse when the tangential
    // impulse follows it on the cone, K00 + mu (K01 y + K02 z).
    std::optional<Eigen::Vector2d> sliding_direction;
    std::optional<double> sliding_normal_response;

    bool operator==(const FrictionSolve&) const = default;
};

struct Impulse {
    ImpulseModel impulse_model;
    std::optional<FrictionSolve> friction_solve;  // present when the contact has friction
    Vec3 impulse;                                 // (g_n, g_t1, g_t2)
    Vec3 impulse_world;                           // basis . impulse

    bool operator==(const Impulse&) const = default;
};

// K = C^T (sum_i m_i^-1 1 - [q_rel_i]x I_i^-1 [q_rel_i]x) C: the change of contact velocity per unit impulse,
// both in contact coordinates (step 3 for every direction at once; K00 is d up to rounding). In world coordinates
// an impulse g at the contact changes body i's point velocity by m^-1 g + (I^-1 (q_rel x g)) x q_rel =
// (m^-1 1 - [q_rel]x I^-1 [q_rel]x) g, the matrix form of the per-unit-impulse chain (14.2, 14.1, 9.5) for every
// direction at once. Inline, in plain doubles (math/products.hpp): the book's friction solve and every
// accumulating method's friction rows take K from here. Written as the matrix products it is, multiplications by
// the skew matrices' zeros included: they decide which zero an entry that sums to zero is, and the trace shows it.
// Written once over the matrix and vector types (math/products.hpp): in doubles here, and over four floats for soft
// step's wide records (methods/wide_records.hpp, a lane a contact), so every lane sums in a double's order.
// Body i's share of K in world axes, m^-1 1 - [q_rel]x I^-1 [q_rel]x (I^-1 world, m^-1 its inverse mass).
template <typename M, typename V, typename Inertia, typename Real>
IMPULSE_KERNEL M world_delta_velocity_matrix_of(const V& relative_position, const Inertia& inverse_inertia,
                                                const Real& m) {
    const M r = skew_of<M>(relative_position);
    const M turn = product_of<M>(product_of<M>(r, inverse_inertia), r);
    const Real one = splat<Real>(1.0), zero = splat<Real>(0.0);
    M w;
    w(0, 0) = m * one - turn(0, 0), w(1, 0) = m * zero - turn(1, 0), w(2, 0) = m * zero - turn(2, 0);
    w(0, 1) = m * zero - turn(0, 1), w(1, 1) = m * one - turn(1, 1), w(2, 1) = m * zero - turn(2, 1);
    w(0, 2) = m * zero - turn(0, 2), w(1, 2) = m * zero - turn(1, 2), w(2, 2) = m * one - turn(2, 2);
    return w;
}
// K from the bodies' shares (body 1's null for the world): added entry by entry to a matrix of zeros, as Eigen sums
// them, then turned into the contact's axes, C^T W C.
template <typename M, typename Real>
IMPULSE_KERNEL M delta_velocity_matrix_of(const M& contact_to_world, const M& body_0, const M* body_1) {
    M world;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) world(i, j) = splat<Real>(0.0) + body_0(i, j);
    if (body_1)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) world(i, j) += (*body_1)(i, j);
    return product_of<M>(transposed_product_of<M>(contact_to_world, world), contact_to_world);
}
IMPULSE_KERNEL Mat3 world_delta_velocity_matrix(const Vec3& relative_position, const MassProperties& mass) {
    return world_delta_velocity_matrix_of<Mat3>(relative_position, mass.inverse_inertia_world, mass.inverse_mass);
}
IMPULSE_KERNEL Mat3 delta_velocity_matrix(const Basis& basis, const std::array<Vec3, 2>& relative_position,
                                          const ContactMass& mass) {
    const Mat3 body_0 = world_delta_velocity_matrix(relative_position[0], *mass[0]);
    if (!mass[1]) return delta_velocity_matrix_of<Mat3, double>(basis.contact_to_world, body_0, nullptr);
    const Mat3 body_1 = world_delta_velocity_matrix(relative_position[1], *mass[1]);
    return delta_velocity_matrix_of<Mat3, double>(basis.contact_to_world, body_0, &body_1);
}

// K with its LU factors: everything the friction solve needs of the contact's geometry and masses. Both depend
// only on what preparation fixed, so a contact resolved again in the same frame can reuse them
// (methods/solver_common.hpp's FrictionMatrices keeps them once the first impulse has computed them). Gaussian
// elimination with complete pivoting (math/full_pivot_lu.hpp): K is singular only when neither body can translate,
// and nearly so for long lever arms, where the largest pivot first keeps it accurate.
struct FactoredDeltaVelocityMatrix {
    explicit FactoredDeltaVelocityMatrix(const Mat3& k) : matrix(k), factors(k) {}

    Mat3 matrix;           // K
    FullPivotLu3 factors;  // P K Q = L U
};

FrictionSolve friction_solve(const FactoredDeltaVelocityMatrix& k, const Vec3& contact_velocity,
                             double desired_delta_velocity, double friction,
                             SlidingFriction sliding = SlidingFriction::reference);

// The whole step: picks the model, returns the impulse in contact and world coordinates. `k` is the contact's
// K with its factors, read only when the contact has friction (null will do for a frictionless one).
Impulse calculate_impulse(const Basis& basis, const FactoredDeltaVelocityMatrix* k, const Vec3& contact_velocity,
                          double desired_delta_velocity, double delta_velocity_per_unit_impulse, double friction,
                          SlidingFriction sliding = SlidingFriction::reference);

}  // namespace impulse
