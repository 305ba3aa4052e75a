#include "derivation/impulse.hpp"

#include "math/elementary.hpp"
#include "math/rotation.hpp"

#include <cmath>

namespace impulse {

FrictionSolve friction_solve(const FactoredDeltaVelocityMatrix& factored, const Vec3& contact_velocity,
                             double desired_delta_velocity, double friction, SlidingFriction sliding) {
    FrictionSolve s;
    s.delta_velocity_matrix = factored.matrix;
    s.target_delta_velocity = {desired_delta_velocity, -contact_velocity.y(), -contact_velocity.z()};
    s.solvable = factored.factors.invertible();
    s.static_impulse = s.solvable ? factored.factors.solve(s.target_delta_velocity) : Vec3::Zero();
    s.tangential_impulse = elementary::hypot(s.static_impulse.y(), s.static_impulse.z());
    s.cone_limit = friction * s.static_impulse.x();

    if (s.solvable && s.tangential_impulse > s.cone_limit) {
        // Outside the cone the contact slides: choose a unit tangential direction (y, z) (the reference engine
        // keeps the static tangential impulse's; against_slip opposes the current slip), put the tangential
        // impulse's size on the cone (mu g_n), and choose g_n so the normal velocity still changes by exactly
        // the desired amount: K00 g_n + K01 mu y g_n + K02 mu z g_n = desired.
        const Mat3& k = s.delta_velocity_matrix;
        // The test uses the unclamped normal impulse (as the reference engine does), so a contact with no
        // tangential impulse still counts as outside the cone when that normal impulse is negative; the
        // direction is then zero and only the normal impulse remains.
        Eigen::Vector2d direction = Eigen::Vector2d::Zero();
        if (sliding == SlidingFriction::reference) {
            if (s.tangential_impulse > 0.0)
                direction = Eigen::Vector2d(s.static_impulse.y(), s.static_impulse.z()) / s.tangential_impulse;
        } else {
            // Coulomb: the sliding impulse opposes the slip the contact has now. With no slip there is nothing
            // to oppose, and only the normal impulse remains, as above.
            const double slip = elementary::hypot(contact_velocity.y(), contact_velocity.z());
            if (slip > 0.0) direction = -Eigen::Vector2d(contact_velocity.y(), contact_velocity.z()) / slip;
        }
        s.sliding_direction = direction;
        s.sliding_normal_response = k(0, 0) + friction * (k(0, 1) * direction.x() + k(0, 2) * direction.y());
    }
    return s;
}

Impulse calculate_impulse(const Basis& basis, const FactoredDeltaVelocityMatrix* k, const Vec3& contact_velocity,
                          double desired_delta_velocity, double delta_velocity_per_unit_impulse, double friction,
                          SlidingFriction sliding) {
    Impulse g;
    g.impulse_model = ImpulseModel::frictionless;
    g.impulse = {desired_delta_velocity / delta_velocity_per_unit_impulse, 0.0, 0.0};  // g = v / d  (14.3), normal only
    if (friction != 0.0) {
        g.friction_solve = friction_solve(*k, contact_velocity, desired_delta_velocity, friction, sliding);
        const FrictionSolve& s = *g.friction_solve;
        if (!s.sliding_normal_response) {
            if (s.solvable) {
                g.impulse_model = ImpulseModel::static_friction;
                g.impulse = s.static_impulse;
            }
            // Not solvable: no body can translate, only the frictionless normal impulse is defined.
        } else if (*s.sliding_normal_response > 0.0) {
            g.impulse_model = ImpulseModel::sliding_friction;
            const double normal = desired_delta_velocity / *s.sliding_normal_response;
            g.impulse = {normal, friction * normal * s.sliding_direction->x(),
                         friction * normal * s.sliding_direction->y()};
        }
        // A non-positive sliding response means pushing along the cone would not separate the contact at
        // all (a long lever arm with strong coupling); the frictionless impulse is the only safe answer.
    }
    g.impulse_world = to_world(basis, g.impulse);
    return g;
}

}  // namespace impulse
