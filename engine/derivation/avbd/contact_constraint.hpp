#pragma once
// A contact as AVBD sees it: three constraints on the bodies' positions, one along the normal and two in the
// tangent plane (the frictional pair), each a row a with axis u_a in {n, t1, t2} (step 1's basis: the paper's contact
// basis, Eq. 15).
//
// The constraint (Sec. 4, a truncated Taylor series: AVBD's contacts are linearised at the frame's start and the
// second-order term is dropped) is how far body 0's contact point has moved from body 1's along u_a:
//   C_a(x) = C_a(x-) + sum_i s_i [u_a . delta p_i + (r_i x u_a) . delta theta_i],    s_0 = +1, s_1 = -1,
// r_i = step 2's relative position, delta p_i, delta theta_i the bodies' displacement since the frame began
// (derivation/avbd/implicit_euler.hpp). So the gradient of C_a with respect to body i's six coordinates is
//   J_a,i = s_i (u_a, r_i x u_a),
// fixed for the frame. Along the normal C_n(x-) = slop - penetration: the contact is satisfied (C_n >= 0) while the
// bodies overlap by no more than the slop, and a resting contact settles at the slop, where detection still finds
// it next frame. In the tangent plane C_t(x-) = 0: the two points coincide when detected.
//
// Stabilisation (the paper's alpha): a penetration the frame began with is not removed at once (that would give the
// bodies the speed to leave it, energy from nowhere); the constraint the iterations enforce is
//   C*_a(x) = C_a(x) - alpha C_a(x-) = (1 - alpha) C_a(x-) + J_a . delta x,
// so a frame removes 1 - alpha of it (alpha = 0: all of it; 1: none, the frame only keeps it from growing).

#include "derivation/avbd/implicit_euler.hpp"
#include "derivation/basis.hpp"

#include <array>

namespace impulse {

// What the rows' gradients J_a,i = s_i (u_a, r_i x u_a) are made of (kept as the axes and anchors, not the six
// levers r_i x u_a: a sweep reads every contact twice, and the smaller the contact, the more of them stay in cache).
struct ConstraintJacobian {
    std::array<Vec3, 3> axis;               // u_a: the normal, tangent 1, tangent 2 (world)
    std::array<Vec3, 2> relative_position;  // r_i: step 2's, per body (zero for the world)
};

ConstraintJacobian constraint_jacobian(const Basis& basis, const std::array<Vec3, 2>& relative_position);

// Body i's six-vector J_a,i = s_i (u_a, r_i x u_a).
Vec6 constraint_gradient(const ConstraintJacobian& jacobian, int row, int body_slot);

struct ConstraintValue {
    Vec3 initial_constraint;  // C(x-), contact coordinates: (slop - penetration, 0, 0)  (m)
    Vec3 moved;               // J . delta x: how far the rows moved since the frame began (m)
    Vec3 constraint;          // C* = (1 - alpha) C(x-) + J . delta x  : what the force acts on (m)
};

// The contact's constraint for the bodies' current displacements (`displacement[1]` zero for the world). Inline:
// a sweep evaluates it for every contact of every body it visits.
[[gnu::always_inline]] inline ConstraintValue constraint_value(const ConstraintJacobian& jacobian,
                                                               double initial_normal,
                                                               const std::array<Displacement, 2>& displacement,
                                                               double alpha) {
    // A point moved with its body by dp + dtheta x r; J_a . dx = u_a . (how far body 0's point moved - body 1's),
    // since (dtheta x r) . u = dtheta . (r x u).
    const Vec3 moved0 = displacement[0].linear + displacement[0].angular.cross(jacobian.relative_position[0]);
    const Vec3 moved1 = displacement[1].linear + displacement[1].angular.cross(jacobian.relative_position[1]);
    const Vec3 apart = moved0 - moved1;
    ConstraintValue v;
    v.initial_constraint = {initial_normal, 0.0, 0.0};
    v.moved = {jacobian.axis[0].dot(apart), jacobian.axis[1].dot(apart), jacobian.axis[2].dot(apart)};
    v.constraint = (1.0 - alpha) * v.initial_constraint + v.moved;  // C*, stabilised
    return v;
}

}  // namespace impulse
