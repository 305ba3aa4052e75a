#pragma once
// The force a contact's constraints exert (AVBD's hard constraints, inequalities (Sec. 3.2) and friction). Each row a
// is a hard constraint held by an augmented Lagrangian: the energy (1/2) k C*^2 - lambda C* (with this project's sign:
// lambda >= 0 pushes, the paper's lambda is its negative) exerts the force
//   F_a = lambda_a - k_a C*_a                                        along J_a (Eq. 11's right-hand side)
// on body 0 and its opposite on body 1, bounded as the contact allows (the clamped force, Sec. 3.2):
//   normal       F_n = max(lambda_n - k_n C*_n, 0)                  it pushes, never pulls
//   friction     F_t = lambda_t - k_t C*_t  while |F_t| <= mu F_n   sticking: the pair holds the points together
//                F_t on the circle |F_t| = mu F_n, pointing the same way, otherwise   sliding
// The tangential pair shares one stiffness k_t and is bounded as a vector on the disc, so the force does not depend
// on which way step 1's tangents point (a box clamp would allow sqrt(2) mu F_n across it; docs/methods.md).
//
// The block (derivation/avbd/body_block.hpp) needs how the force changes with the constraint, -dF/dC*: k_n, also
// when F_n is clamped to 0, where the energy is flat and the exact value is 0 (the reference demo keeps k_n too:
// with the exact value a resting contact flips between pushing and not from one iteration to the next, the body
// pushed out on one and falling back to its inertial target on the next, and never settles); k_t while sticking,
// and while sliding k_t scaled by mu F_n / |F_t,unclamped|, the share of a change that survives the cut back onto
// the circle (Giles's AVBD for solver2d). Both keep the block symmetric positive definite (Sec. 3.5).

#include "math/types.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

struct Stiffness {
    double normal = 0.0;      // k_n (N/m): the normal row's penalty
    double tangential = 0.0;  // k_t (N/m): the frictional pair's penalty

    bool operator==(const Stiffness&) const = default;
};

struct ContactForce {
    Vec3 unclamped;             // lambda - k C*, contact coordinates (N): the force before its bounds
    Vec3 force;                 // F: what acts, contact coordinates (N); body 0 gets +F along the rows, body 1 -F
    Stiffness block_stiffness;  // -dF/dC* as the block takes it (N/m): see above
    bool pushing = false;       // F_n > 0
    bool sliding = false;       // the tangential force was cut back onto the circle |F_t| = mu F_n
};

// Inline: a sweep evaluates it for every contact of every body it visits.
[[gnu::always_inline]] inline ContactForce contact_force(const Vec3& lambda, const Stiffness& stiffness,
                                                         const Vec3& constraint, double friction) {
    ContactForce f;
    // lambda - k C*  (Eq. 11's right-hand side, with this project's sign)
    f.unclamped = {lambda.x() - stiffness.normal * constraint.x(), lambda.y() - stiffness.tangential * constraint.y(),
                   lambda.z() - stiffness.tangential * constraint.z()};
    // Push only (Sec. 3.2); +0 for -0 too, on every platform (as in dual_update.cpp's warm start).
    const double normal = f.unclamped.x() > 0.0 ? f.unclamped.x() : 0.0;
    f.pushing = normal > 0.0;
    f.force = {normal, 0.0, 0.0};
    f.block_stiffness.normal = stiffness.normal;  // even when clamped to 0: see the header
    if (friction == 0.0) return f;                // frictionless: the tangential rows exert nothing
    const double bound = friction * normal;       // |F_t| <= mu F_n: the frictional pair's bound
    const double size2 = f.unclamped.y() * f.unclamped.y() + f.unclamped.z() * f.unclamped.z();
    if (size2 <= bound * bound) {  // (squared: the root only when it slides)
        f.force.y() = f.unclamped.y();
        f.force.z() = f.unclamped.z();
        f.block_stiffness.tangential = stiffness.tangential;
        return f;
    }
    const double scale = bound / std::sqrt(size2);  // onto the circle, the same way
    f.force.y() = scale * f.unclamped.y();
    f.force.z() = scale * f.unclamped.z();
    f.block_stiffness.tangential = scale * stiffness.tangential;
    f.sliding = true;
    return f;
}

}  // namespace impulse
