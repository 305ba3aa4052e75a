#pragma once
// The accumulated-impulse rows of one contact, written once (solver2d's solve_common, Jolt's
// AxisConstraintPart) and used by every method that accumulates: projected Gauss-Seidel, the split impulse's
// push rows and soft step. A contact has three rows, the normal row and two friction rows in its tangent
// plane, and keeps its total impulse lambda = (lambda_n, lambda_t1, lambda_t2) in contact coordinates.
//
// The hot loop reads plain data (Box2D's contact constraint structs): a ContactRow per contact holding what a
// visit needs, copied once per frame from the contact's preparation, and a SolverBody per body holding its
// velocities and mass. The recorder sees the same numbers through the same functions: a method runs one loop
// templated on whether it records, so recording costs nothing when off and changes no bit when on.
//
// The normal row (K = the 3x3 velocity change per unit impulse in contact coordinates, K_nn = d of step 3):
//   delta lambda_n = normal_mass mass_scale (target - v_n) - impulse_scale lambda_n,   normal_mass = 1 / d
//   lambda_n       = max(lambda_n + delta lambda_n, 0)                                  push only
// A rigid row has mass_scale 1 and impulse_scale 0; soft step's soft contact scales both (soft_step.hpp).
//
// The friction rows, on the slip the normal change leaves, v_t' = v_t + K_tn (lambda_n after - before):
//   lambda_t,free  = lambda_t - K_tt^-1 v_t'   the total that stops the slip (a 2-D solve: at a corner K_tt
//                                               couples the two tangents)
//   static         |lambda_t,free| <= mu lambda_n:  lambda_t = lambda_t,free, the slip stops
//   sliding        otherwise: lambda_t = the point of the disc |lambda_t| <= mu lambda_n nearest lambda_t,free
//                  in K_tt's metric (clamp "friction"), found as below
//
// Why this projection. Coulomb's law (maximal dissipation) says a sliding contact's friction has size
// mu lambda_n and opposes the slip. The slip after the visit is v_t,after = v_t' + K_tt (lambda_t - lambda_t,old)
// = K_tt (lambda_t - lambda_t,free). Minimising |lambda_t - lambda_t,free|_K over the disc gives, by its
// optimality condition, K_tt (lambda_t - lambda_t,free) + nu lambda_t = 0 with nu >= 0, i.e.
//   v_t,after = -nu lambda_t:  the friction lies on the circle exactly against the slip the visit leaves,
// and lambda_t(nu) = (K_tt + nu 1)^-1 K_tt lambda_t,free with nu the root of |lambda_t(nu)| = mu lambda_n.
// nu is found by Newton's method on phi(nu) = 1/|lambda_t(nu)| - 1/(mu lambda_n) (the trust-region
// subproblem's secular equation, Moré and Sorensen 1983): phi is concave and increasing, so Newton from nu = 0
// climbs to the root without overshooting, to rounding in 3 or 4 steps; the result is then put exactly on the
// circle. The alternatives, and why not:
//   - scaling lambda_t,free back onto the circle (what this engine did before, and Jolt and Box2D's 3-D ports
//     do): its fixed point has lambda_t parallel to K_tt^-1 v_t, not to v_t. At a box corner K_tt is
//     anisotropic and only cos(angle between them) of the friction opposes the slip: a box sliding along x on
//     its four corners stopped 7.9 % too late and veered (docs/methods.md).
//   - putting lambda_t = -mu lambda_n v_t' / |v_t'| (against the slip before the visit): the same fixed point
//     for a steady slide, but when the cone shrinks under a contact that holds (lambda_n falls, v_t' is
//     rounding noise) it points the whole friction along the noise; a resting box under soft step lost
//     contacts that way.
//   - Bullet's slip-aligned tangent (one row along the slip as prepared, each row clamped alone to
//     +-mu lambda_n): opposes the slip as prepared, not as it turns within the frame, and a box clamp allows
//     sqrt(2) mu lambda_n across it.
// None of this depends on a basis: a turn of the tangents about the normal turns lambda_t, v_t and K_tt
// together, so the same scene turned as a whole gives the turned motion. When K_tt is singular (a body that
// turns about one axis only) lambda_t,free is scaled back onto the circle.
//
// Contact velocity (step 4 on the bodies' current motion, anchors and inverse inertia fixed at preparation):
//   v = C^T [(v0 + w0 x r0) - (v1 + w1 x r1)] + offset
// where offset is a method's constant term (projected Gauss-Seidel: step 4's tangential acceleration term).
// Applying an increment g (world) is step 7: body 0 gets +g, body 1 gets -g,
//   impulsive_torque = r x (+-g),  velocity_change = (+-g) m^-1,  rotation_change = I^-1 impulsive_torque.

#include "body/rigid_body.hpp"
#include "derivation/velocity_change.hpp"
#include "memory/contact_memory.hpp"
#include "record/iteration_records.hpp"
#include "resolver/prepared_contact.hpp"

#include <cmath>
#include <span>
#include <type_traits>
#include <vector>

namespace impulse {

// A body as the solver loop sees it (Box2D's b2BodyState): its velocities and its mass for the frame.
struct SolverBody {
    Vec3 velocity = Vec3::Zero();          // p-dot (m/s)
    Vec3 angular_velocity = Vec3::Zero();  // theta-dot (rad/s)
    double inverse_mass = 0.0;             // m^-1
    Mat3 inverse_inertia = Mat3::Zero();   // I^-1, world axes, as prepared
};

// The solver's bodies for a frame: velocities and mass copied from `bodies` and `contacts`' preparation.
std::vector<SolverBody> solver_bodies(std::span<const RigidBody> bodies, std::span<const PreparedContact> contacts);

// Copies the solver's velocities back to the bodies.
void store_velocities(std::span<const SolverBody> solver, std::vector<RigidBody>& bodies);

// One contact's rows: what a visit reads, fixed for the frame, and the total it accumulates.
struct ContactRow {
    int contact = 0;                 // index in the prepared list
    std::array<int, 2> body{0, -1};  // solver bodies; -1 = the world (body 1 only)
    Vec3 normal;                     // contact x, world
    Vec3 tangent1;                   // contact y
    Vec3 tangent2;                   // contact z
    std::array<Vec3, 2> anchor;      // r_i: contact point minus body centre (step 2); zero for the world
    double normal_mass = 0.0;        // 1 / d: impulse per unit change of normal velocity (step 3)
    Eigen::Vector2d normal_to_tangent = Eigen::Vector2d::Zero();  // K_tn: slip velocity per unit normal impulse
    Eigen::Matrix2d tangent_response = Eigen::Matrix2d::Zero();   // K_tt: slip velocity per unit friction impulse
    Eigen::Matrix2d tangent_mass = Eigen::Matrix2d::Zero();       // K_tt^-1 (its diagonal's inverse if singular)
    bool tangent_invertible = false;                              // K_tt is invertible
    double friction = 0.0;                                        // mu
    Eigen::Vector2d slip_offset = Eigen::Vector2d::Zero();        // a constant added to v_t (see above)
    Vec3 total_impulse = Vec3::Zero();                            // lambda, contact coordinates (N s)
};

// The rows of a prepared contact (K from derivation/impulse.hpp's delta_velocity_matrix); without
// `friction_rows` (the split impulse's pushes) only the normal row is filled.
ContactRow contact_row(int index, const PreparedContact& contact, bool friction_rows = true);

// What the normal row aims for in one visit.
struct NormalTarget {
    double velocity = 0.0;       // the normal velocity the row asks for (m/s)
    double mass_scale = 1.0;     // share of the rigid impulse applied (soft contact: < 1)
    double impulse_scale = 0.0;  // share of the total given back per visit (soft contact: > 0)
};

// Step 4 for the row: the contact velocity (v_n, v_t1, v_t2) from the bodies as they are now, plus slip_offset.
inline Vec3 row_velocity(const ContactRow& row, const SolverBody* bodies) {
    const SolverBody& a = bodies[row.body[0]];
    Vec3 relative = a.velocity + a.angular_velocity.cross(row.anchor[0]);  // (9.5)
    if (row.body[1] >= 0) {
        const SolverBody& b = bodies[row.body[1]];
        relative -= b.velocity + b.angular_velocity.cross(row.anchor[1]);
    }
    return {row.normal.dot(relative), row.tangent1.dot(relative) + row.slip_offset.x(),
            row.tangent2.dot(relative) + row.slip_offset.y()};
}

// The normal velocity alone (the split impulse's push rows).
inline double row_normal_velocity(const ContactRow& row, const SolverBody* bodies) {
    const SolverBody& a = bodies[row.body[0]];
    double v = row.normal.dot(a.velocity + a.angular_velocity.cross(row.anchor[0]));
    if (row.body[1] >= 0) {
        const SolverBody& b = bodies[row.body[1]];
        v -= row.normal.dot(b.velocity + b.angular_velocity.cross(row.anchor[1]));
    }
    return v;
}

// lambda_n after the normal row: the unclamped total first, then push only. True when the clamp acted.
inline double normal_row(double total, double normal_velocity, double normal_mass, const NormalTarget& target,
                         double& unclamped) {
    unclamped =
        total + normal_mass * target.mass_scale * (target.velocity - normal_velocity) - target.impulse_scale * total;
    return unclamped < 0.0 ? 0.0 : unclamped;
}

// The point of the disc |lambda_t| <= limit nearest `free` in K_tt's metric, for `free` outside it (see the
// header): lambda_t(nu) = (K_tt + nu 1)^-1 w, w = K_tt free, Newton on 1/|lambda_t(nu)| - 1/limit from nu = 0.
inline Eigen::Vector2d project_on_cone(const Eigen::Matrix2d& k, const Eigen::Vector2d& free, double limit) {
    const Eigen::Vector2d w = k * free;
    Eigen::Vector2d lambda = free;
    double nu = 0.0;
    for (int step = 0; step < 16; ++step) {
        const double size_squared = lambda.squaredNorm();
        const double size = std::sqrt(size_squared);
        if (size <= limit * (1.0 + 1e-13)) break;
        // (K + nu 1)^-1 by its adjugate: [[k11 + nu, -k01], [-k10, k00 + nu]] / det.
        const double a = k(0, 0) + nu, b = k(0, 1), c = k(1, 1) + nu;
        const double inverse_det = 1.0 / (a * c - b * b);
        const Eigen::Vector2d m_lambda((c * lambda.x() - b * lambda.y()) * inverse_det,
                                       (a * lambda.y() - b * lambda.x()) * inverse_det);
        // phi = 1/|lambda| - 1/limit,  dphi/dnu = lambda . (K + nu 1)^-1 lambda / |lambda|^3
        const double slope = lambda.dot(m_lambda) / (size_squared * size);
        nu -= (1.0 / size - 1.0 / limit) / slope;
        const double a2 = k(0, 0) + nu, c2 = k(1, 1) + nu;
        const double inverse_det2 = 1.0 / (a2 * c2 - b * b);
        lambda = Eigen::Vector2d((c2 * w.x() - b * w.y()) * inverse_det2, (a2 * w.y() - b * w.x()) * inverse_det2);
    }
    return lambda * (limit / std::sqrt(lambda.squaredNorm()));  // exactly on the circle
}

// lambda_t after the friction rows (see the header), from the total before, the slip v_t' once the normal
// change acts, and the cone's radius mu lambda_n. `unclamped` receives lambda_t,free; returns whether the
// contact slides (the cone clamped).
inline bool friction_rows(const ContactRow& row, const Eigen::Vector2d& total, const Eigen::Vector2d& slip,
                          double limit, Eigen::Vector2d& unclamped, Eigen::Vector2d& after) {
    unclamped = total - row.tangent_mass * slip;
    if (unclamped.squaredNorm() <= limit * limit) {
        after = unclamped;
        return false;
    }
    if (limit <= 0.0) {
        after = Eigen::Vector2d::Zero();
    } else if (row.tangent_invertible) {
        after = project_on_cone(row.tangent_response, unclamped, limit);
    } else {
        after = unclamped * (limit / std::sqrt(unclamped.squaredNorm()));
    }
    return true;
}

inline ImpulseClamp clamp_of(bool push_only, bool friction) {
    return push_only && friction ? ImpulseClamp::both
           : push_only           ? ImpulseClamp::push_only
           : friction            ? ImpulseClamp::friction
                                 : ImpulseClamp::none;
}

// One visit's three rows on the velocity `velocity` (row_velocity): the total before, unclamped and after,
// and which clamp acted. The row's total is not changed here (apply_increment does, with the bodies).
inline AccumulatedImpulse solve_rows(const ContactRow& row, const Vec3& velocity, const NormalTarget& target) {
    AccumulatedImpulse a;
    a.before = row.total_impulse;
    double unclamped_normal;
    const double normal = normal_row(a.before.x(), velocity.x(), row.normal_mass, target, unclamped_normal);
    a.unclamped.x() = unclamped_normal;
    a.after.x() = normal;
    bool sliding = false;
    if (row.friction != 0.0) {
        const Eigen::Vector2d slip = velocity.tail<2>() + row.normal_to_tangent * (normal - a.before.x());
        Eigen::Vector2d unclamped, after;
        sliding = friction_rows(row, a.before.tail<2>(), slip, row.friction * normal, unclamped, after);
        a.unclamped.tail<2>() = unclamped;
        a.after.tail<2>() = after;
    } else {
        a.unclamped.tail<2>() = a.before.tail<2>();
        a.after.tail<2>() = Eigen::Vector2d::Zero();
    }
    a.clamp = clamp_of(unclamped_normal < 0.0, sliding);
    return a;
}

// The normal row alone (soft step's restitution, the split impulse's pushes): tangential totals unchanged.
inline AccumulatedImpulse solve_normal_row(const ContactRow& row, double normal_velocity, const NormalTarget& target) {
    AccumulatedImpulse a;
    a.before = a.unclamped = a.after = row.total_impulse;
    double unclamped;
    a.after.x() = normal_row(a.before.x(), normal_velocity, row.normal_mass, target, unclamped);
    a.unclamped.x() = unclamped;
    a.clamp = clamp_of(unclamped < 0.0, false);
    return a;
}

// A total from elsewhere (last frame's, re-projected on this frame's basis) put inside the limits a total
// obeys: lambda_n >= 0 and |lambda_t| <= mu lambda_n (scaled back: there is no slip to oppose yet).
inline AccumulatedImpulse within_limits(const Vec3& total, double friction) {
    AccumulatedImpulse a;
    a.before = Vec3::Zero();
    a.unclamped = a.after = total;
    const bool pulled = total.x() < 0.0;
    if (pulled) a.after.x() = 0.0;
    const double limit = friction * a.after.x();
    const double tangential = a.after.tail<2>().squaredNorm();
    const bool coned = tangential > limit * limit;
    if (coned) a.after.tail<2>() *= tangential > 0.0 ? limit / std::sqrt(tangential) : 0.0;
    a.clamp = clamp_of(pulled, coned);
    return a;
}

// The impulse `increment` (contact coordinates) in world coordinates, g = C increment.
inline Vec3 world_impulse(const ContactRow& row, const Vec3& increment) {
    return row.normal * increment.x() + row.tangent1 * increment.y() + row.tangent2 * increment.z();
}

// Step 7: applies g (world) to the row's bodies, +g to body 0 and -g to body 1. With `Change` a VelocityChange,
// also records exactly what was added; with std::nullptr_t, records nothing.
template <typename Change>
inline void apply_impulse(const ContactRow& row, SolverBody* bodies, const Vec3& impulse, Change change) {
    for (int i = 0; i < 2; ++i) {
        if (row.body[i] < 0) continue;
        SolverBody& body = bodies[row.body[i]];
        const Vec3 g = i == 0 ? impulse : Vec3(-impulse);
        const Vec3 torque = row.anchor[i].cross(g);                  // u = q_rel x g  (14.2)
        const Vec3 velocity_change = g * body.inverse_mass;          // (7.5)
        const Vec3 rotation_change = body.inverse_inertia * torque;  // I^-1 u  (14.1)
        body.velocity += velocity_change;
        body.angular_velocity += rotation_change;
        if constexpr (!std::is_same_v<Change, std::nullptr_t>) {
            change->impulsive_torque[i] = torque;
            change->velocity_change[i] = velocity_change;
            change->rotation_change[i] = rotation_change;
        }
    }
}

// |K (after - before)|: how much a visit changed its own contact's velocity (m/s), squared. A norm, so the
// early stop of a sweeping method does not depend on the tangent basis.
inline double velocity_change_squared(const ContactRow& row, const Vec3& increment) {
    const double k_nn = 1.0 / row.normal_mass;
    const Eigen::Vector2d t = increment.tail<2>();
    const double normal = k_nn * increment.x() + row.normal_to_tangent.dot(t);
    const Eigen::Vector2d tangential = row.normal_to_tangent * increment.x() + row.tangent_response * t;
    return normal * normal + tangential.squaredNorm();
}

// Contacts of a frame that share a memory key (hand-written contacts carry no features): only the first is
// warm started, since the memory keeps the first one's total. For each row, last frame's total re-projected
// on its basis and put within its limits, or nothing.
std::vector<std::optional<AccumulatedImpulse>> remembered_totals(std::span<const ContactRow> rows,
                                                                 std::span<const PreparedContact> contacts,
                                                                 const ContactMemory& memory);

// Stores every row's total, in world coordinates, as this frame's memory.
void remember_totals(std::span<const ContactRow> rows, std::span<const PreparedContact> contacts,
                     ContactMemory& memory);

}  // namespace impulse
