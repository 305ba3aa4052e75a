#pragma once
// The accumulated-impulse rows of one contact, written once (solver2d's solve_common, Jolt's
// AxisConstraintPart) and used by every method that accumulates: projected Gauss-Seidel, the split impulse's
// push rows and soft step. A contact has three rows, the normal row and two friction rows in its tangent
// plane, and keeps its total impulse lambda = (lambda_n, lambda_t1, lambda_t2) in contact coordinates.
//
// The hot loop reads plain data (Box2D's contact constraint structs): a ContactRow per contact holding what a
// visit needs, copied once per frame from the contact's preparation, and a SolverBody per body holding its
// velocities and mass; the row functions are always inlined (IMPULSE_KERNEL), so a sweep compiles to one loop. The rows
// derive nothing themselves: step 3's d, K's entries, step 4's point velocity and step 7's apply are the derivation's
// own inline forms (derivation/*.hpp), the ones the book's methods use. A method runs one loop and reports each visit
// only when the recorder keeps the frame (record/visits.hpp): recording costs a branch per visit when off, and changes
// no bit when on.
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
// Why this projection (docs/methods.md, "The accumulating methods", with the alternatives measured): the slip the
// visit leaves is v_t,after = K_tt (lambda_t - lambda_t,free), and the optimality condition of the projection,
// K_tt (lambda_t - lambda_t,free) + nu lambda_t = 0 with nu >= 0, makes it v_t,after = -nu lambda_t: the friction
// lies on the circle exactly against the slip the visit leaves (Coulomb's maximal dissipation). With
// lambda_t(nu) = (K_tt + nu 1)^-1 K_tt lambda_t,free, nu is the root of |lambda_t(nu)| = mu lambda_n, found by
// Newton's method on 1/|lambda_t(nu)| - 1/(mu lambda_n) (Moré and Sorensen 1983's secular equation: concave and
// increasing, so Newton from nu = 0 climbs to it without overshooting). No basis decides any of it; when K_tt is
// singular (a body that turns about one axis only) lambda_t,free is scaled back onto the circle.

#include "body/rigid_body.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "math/lanes.hpp"
#include "math/products.hpp"
#include "memory/contact_memory.hpp"
#include "memory/fetch_ahead.hpp"
#include "methods/method.hpp"
#include "record/iteration_records.hpp"
#include "preparation/prepared_contact.hpp"

#include <cmath>
#include <cstdint>
#include <memory_resource>
#include <new>
#include <span>
#include <vector>

namespace impulse {

// Three numbers along a contact's axes, (normal, tangent 1, tangent 2): a velocity or an impulse in contact
// coordinates, as the row functions carry them. Over a double (one visit), or four floats (a wide record's four
// pairs side by side: math/lanes.hpp), the row functions below written once over either.
template <typename Real>
struct AxesOf {
    Real n{};
    Real t1{};
    Real t2{};
};
using Axes = AxesOf<double>;

inline Vec3 vector_of(const Axes& a) {
    return {a.n, a.t1, a.t2};
}

// A body as the solver loop sees it (Box2D's b2BodyState): its velocities and its mass for the frame.
struct SolverBody {
    Vec3 velocity = Vec3::Zero();          // p-dot (m/s)
    Vec3 angular_velocity = Vec3::Zero();  // theta-dot (rad/s)
    MassProperties mass;                   // m^-1 and I^-1 (world axes), as prepared
};

// The solver's bodies for a frame: velocities from `bodies`, mass as the contacts were prepared with (in `memory`:
// the frame's scratch, FrameContext::scratch).
std::pmr::vector<SolverBody> solver_bodies(std::span<const RigidBody> bodies, std::span<const MassProperties> mass,
                                           std::pmr::memory_resource* memory = std::pmr::new_delete_resource());

// One contact's rows: what a visit reads, fixed for the frame, and the total it accumulates.
struct ContactRow {
    int contact = 0;                  // index in the prepared list
    std::array<int, 2> body{0, -1};   // solver bodies; -1 = the world (body 1 only)
    bool tangent_invertible = false;  // K_tt is invertible (here, beside the ints: a row is read whole every visit)
    Mat3 basis;                       // step 1's contact_to_world: columns normal (contact x), tangent 1, tangent 2
    std::array<Vec3, 2> anchor;       // r_i: contact point minus body centre (step 2); zero for the world
    double normal_mass = 0.0;         // 1 / K_nn = 1 / d: impulse per unit change of normal velocity
    double normal_response = 0.0;     // K_nn = step 3's d: normal velocity per unit normal impulse
    double friction = 0.0;            // mu
    std::array<double, 2> normal_to_tangent{0.0, 0.0};      // K_tn: slip velocity per unit normal impulse
    std::array<double, 3> tangent_response{0.0, 0.0, 0.0};  // K_tt (11, 12, 22): slip per unit friction impulse
    std::array<double, 3> tangent_mass{0.0, 0.0, 0.0};      // K_tt^-1 (11, 12, 22) (its diagonal's inverse if singular)
    std::array<double, 2> slip_offset{0.0, 0.0};            // a constant added to v_t (see above)
    Axes total_impulse;                                     // lambda (N s)
};

// The solver bodies of a prepared contact's rows (ContactRow::body): -1 for the world.
inline std::array<int, 2> row_bodies(const PreparedContact& contact) {
    return {contact.bodies[0] == world_body ? -1 : contact.bodies[0],
            contact.bodies[1] == world_body ? -1 : contact.bodies[1]};
}

// Whether an impulse can move the contact at all (K_nn > 0): a contact that cannot has no rows and is never visited.
inline bool can_move(const PreparedContact& contact) {
    return contact.delta_velocity_per_unit_impulse > 0.0;
}

// The friction rows' entries of K (contact coordinates; derivation/impulse.hpp's delta_velocity_matrix_of): K_tn,
// K_tt, and K_tt^-1, or its diagonal's inverse when K_tt is singular (a body that turns about one axis only: each
// tangent row then solved on its own). Over a double, or four floats (a wide record's lanes). K_tt counts as singular
// when det <= Lanes<Real>::singular_tolerance k_11 k_22: 0 in doubles, a millionth in floats, where rounding the
// inputs can leave a singular K_tt a determinant of a few ulps, whose inverse would be nothing but that rounding.
template <typename Real>
struct FrictionMatrixOf {
    std::array<Real, 2> normal_to_tangent;  // K_tn
    std::array<Real, 3> tangent_response;   // K_tt (11, 12, 22)
    std::array<Real, 3> tangent_mass;       // K_tt^-1 (11, 12, 22), or its diagonal's inverse
    MaskOf<Real> tangent_invertible;
};

template <typename Real, typename M>
IMPULSE_KERNEL FrictionMatrixOf<Real> friction_matrix(const M& k) {
    const Real zero = splat<Real>(0.0), one = splat<Real>(1.0);
    const Real k_11 = k(1, 1), k_12 = k(1, 2), k_22 = k(2, 2);
    FrictionMatrixOf<Real> f{{k(1, 0), k(2, 0)}, {k_11, k_12, k_22}, {zero, zero, zero}, {}};
    const Real det = k_11 * k_22 - k_12 * k_12;
    f.tangent_invertible = det > splat<Real>(Lanes<Real>::singular_tolerance) * (k_11 * k_22);
    // Both, lane by lane (a double takes the one its branch needs).
    if (any(f.tangent_invertible)) {
        const Real inverse_det = one / select(f.tangent_invertible, det, one);
        f.tangent_mass[0] = k_22 * inverse_det, f.tangent_mass[1] = -k_12 * inverse_det;
        f.tangent_mass[2] = k_11 * inverse_det;
    }
    if (any(negated(f.tangent_invertible))) {
        const MaskOf<Real> singular = negated(f.tangent_invertible);
        const MaskOf<Real> has_11 = k_11 > zero, has_22 = k_22 > zero;
        const Real inverse_11 = one / select(has_11, k_11, one), inverse_22 = one / select(has_22, k_22, one);
        f.tangent_mass[0] = select(singular, select(has_11, inverse_11, zero), f.tangent_mass[0]);
        f.tangent_mass[1] = select(singular, zero, f.tangent_mass[1]);
        f.tangent_mass[2] = select(singular, select(has_22, inverse_22, zero), f.tangent_mass[2]);
    }
    return f;
}

// What fill_contact_row fills beside the normal row.
enum class FrictionFill {
    rows,         // the friction rows, with K's entries (friction_matrix)
    none,         // no friction rows (the split impulse's pushes): mu = 0
    coefficient,  // mu only: K's entries are found four contacts at a time (soft step's wide records)
};

// Fills `row` with the rows of a prepared contact that can_move, with its bodies' mass from `bodies` (K_nn = d of
// step 3, the other entries derivation/impulse.hpp's delta_velocity_matrix), the friction rows as `friction` says.
// (In place: a row is 264 bytes, and a frame builds one per contact.)
void fill_contact_row(ContactRow& row, const PreparedContact& contact, const SolverBody* bodies,
                      FrictionFill friction = FrictionFill::rows);

// What the normal row aims for in one visit.
template <typename Real>
struct NormalTargetOf {
    Real velocity = splat<Real>(0.0);       // the normal velocity the row asks for (m/s)
    Real mass_scale = splat<Real>(1.0);     // share of the rigid impulse applied (soft contact: < 1)
    Real impulse_scale = splat<Real>(0.0);  // share of the total given back per visit (soft contact: > 0)
};
using NormalTarget = NormalTargetOf<double>;

// The normal velocity a rigid row asks for all frame: step 5's desired delta v on top of the separating velocity
// it was judged on, v_s + desired delta v (the bounce, and Baumgarte's term when it is on).
inline double prepared_normal_velocity(const PreparedContact& c) {
    return c.contact_velocity.x() + c.desired_delta_velocity;
}
// A body's point velocity at the row's anchor (step 4's, 9.5), world, added to `out` with `sign`.
IMPULSE_KERNEL void add_point_velocity(const SolverBody& b, const Vec3& r, double sign, double* out) {
    const Vec3 v = point_velocity(b.velocity, b.angular_velocity, r);
    out[0] += sign * v.x();
    out[1] += sign * v.y();
    out[2] += sign * v.z();
}

// The contact's normal, world.
inline Vec3 normal_of(const ContactRow& row) {
    return row.basis.col(0);
}

// Body 0's point velocity minus body 1's at the row's anchors, world.
IMPULSE_KERNEL Vec3 relative_velocity(const ContactRow& row, const SolverBody* bodies) {
    double relative[3] = {0.0, 0.0, 0.0};
    add_point_velocity(bodies[row.body[0]], row.anchor[0], 1.0, relative);
    if (row.body[1] >= 0) add_point_velocity(bodies[row.body[1]], row.anchor[1], -1.0, relative);
    return {relative[0], relative[1], relative[2]};
}

// Step 4 for the row: the contact velocity (v_n, v_t1, v_t2) from the bodies as they are now, plus slip_offset.
IMPULSE_KERNEL Axes row_velocity(const ContactRow& row, const SolverBody* bodies) {
    const Vec3 v = transposed_times(row.basis, relative_velocity(row, bodies));
    return {v.x(), v.y() + row.slip_offset[0], v.z() + row.slip_offset[1]};
}

// lambda_n after the normal row; `unclamped` receives the total before the push-only clamp. Over a double (one
// visit) or four floats (a wide record's four pairs: math/lanes.hpp), lane by lane the same operations.
template <typename Real>
IMPULSE_KERNEL Real normal_row(Real total, Real normal_velocity, Real normal_mass, const NormalTargetOf<Real>& target,
                               Real& unclamped) {
    unclamped =
        total + normal_mass * target.mass_scale * (target.velocity - normal_velocity) - target.impulse_scale * total;
    return select(unclamped < splat<Real>(0.0), splat<Real>(0.0), unclamped);
}

// The point of the disc |lambda_t| <= limit nearest (x, y) in K_tt's metric, for (x, y) outside it (see the
// header): lambda_t(nu) = (K_tt + nu 1)^-1 w, w = K_tt (x, y), Newton on 1/|lambda_t(nu)| - 1/limit from nu = 0.
// K_tt is `tangent_response` (11, 12, 22: a ContactRow's own, or kept beside a wide record's point), its inverse the
// row's tangent_mass. Returns the point in (x, y), in the lanes `project` sets.
// In floats two guards keep Newton's numbers within range (docs/bench.md, "the wide record"): the projection scales
// with (x, y, limit) and nu does not, so it is solved on them divided by max(|x|, |y|); and a cone smaller than
// float's precision of the free point takes Newton's limit, nu -> infinity, lambda_t along w.
template <typename Real, typename Row>
IMPULSE_KERNEL void project_on_cone(const Row& row, const std::array<Real, 3>& tangent_response, Real& x, Real& y,
                                    Real limit, MaskOf<Real> project) {
    const Real k11 = tangent_response[0], k12 = tangent_response[1], k22 = tangent_response[2];
    constexpr bool single = !std::is_same_v<Real, double>;
    const Real one = splat<Real>(1.0);
    Real size0 = one;
    if constexpr (single) {
        const Real ax = select(x < splat<Real>(0.0), -x, x), ay = select(y < splat<Real>(0.0), -y, y);
        size0 = select(project, select(ax > ay, ax, ay), one);
        const Real inverse_size0 = one / size0;
        x = x * inverse_size0;
        y = y * inverse_size0;
        limit = select(project, limit * inverse_size0, one);
    }
    const Real wx = k11 * x + k12 * y, wy = k12 * x + k22 * y;  // w = K_tt free
    const Real inverse_limit = one / limit;
    // (K + nu 1)^-1 at nu = 0 is K^-1; after that, its adjugate [[k22 + nu, -k12], [-k12, k11 + nu]] / det.
    Real m00 = row.tangent_mass[0], m01 = row.tangent_mass[1], m11 = row.tangent_mass[2];
    Real nu = splat<Real>(0.0);
    MaskOf<Real> stepping = project;
    if constexpr (single) stepping = both(stepping, negated(limit < splat<Real>(0x1p-24)));
    for (int step = 0; step < 16; ++step) {
        const Real size_squared = x * x + y * y;
        const Real size = square_root(size_squared);
        stepping = both(stepping, negated(size <= limit * (one + splat<Real>(Lanes<Real>::projection_tolerance))));
        if (!any(stepping)) break;
        // Newton on phi = 1/|lambda| - 1/limit, dphi/dnu = lambda . (K + nu 1)^-1 lambda / |lambda|^3:
        // nu += |lambda|^2 (|lambda| / limit - 1) / (lambda . (K + nu 1)^-1 lambda).
        const Real curvature = x * (m00 * x + m01 * y) + y * (m01 * x + m11 * y);
        nu = select(stepping, nu + size_squared * (size * inverse_limit - one) / curvature, nu);
        const Real a = k11 + nu, b = k12, c = k22 + nu;
        const Real inverse_det = one / (a * c - b * b);
        m00 = c * inverse_det, m01 = -b * inverse_det, m11 = a * inverse_det;
        x = select(stepping, m00 * wx + m01 * wy, x);
        y = select(stepping, m01 * wx + m11 * wy, y);
    }
    if constexpr (single) {
        const MaskOf<Real> far = both(project, limit < splat<Real>(0x1p-24));
        x = select(far, wx, x);
        y = select(far, wy, y);
    }
    const Real scale = limit / square_root(x * x + y * y);  // exactly on the circle
    x = select(project, x * scale, x);
    y = select(project, y * scale, y);
    if constexpr (single) {
        x = x * size0;
        y = y * size0;
    }
}

// One visit's three rows, as plain numbers: the total before, unclamped and after, and the clamps that acted.
template <typename Real>
struct RowVisitOf {
    AxesOf<Real> before;
    AxesOf<Real> unclamped;
    AxesOf<Real> after;
    MaskOf<Real> pushed_only{};  // the normal total would have pulled
    MaskOf<Real> sliding{};      // the friction total left the cone

    ImpulseClamp clamp() const {
        return pushed_only && sliding ? ImpulseClamp::both
               : pushed_only          ? ImpulseClamp::push_only
               : sliding              ? ImpulseClamp::friction
                                      : ImpulseClamp::none;
    }
    AxesOf<Real> increment() const { return {after.n - before.n, after.t1 - before.t1, after.t2 - before.t2}; }
    // As the trace records it.
    AccumulatedImpulse accumulated() const {
        return {vector_of(before), vector_of(unclamped), vector_of(after), clamp()};
    }
};
using RowVisit = RowVisitOf<double>;

// The friction rows (see the header) on the slip (s1, s2) once the normal change acts, from the tangential total
// (x, y) before, and the cone's radius mu lambda_n: (x, y) becomes lambda_t,free in (free_x, free_y) and the total
// after in (x, y); returns whether the contact slides (the cone clamped). Plain numbers in and out, so the caller's
// values stay in registers; the row's K_tt^-1 (or its diagonal's inverse) is its tangent_mass, and K_tt, which only
// the cone's projection reads, is `tangent_response`.
template <typename Real, typename Row>
IMPULSE_KERNEL MaskOf<Real> friction_rows(const Row& row, const std::array<Real, 3>& tangent_response, Real s1, Real s2,
                                          Real limit, Real& free_x, Real& free_y, Real& x, Real& y) {
    const auto& m = row.tangent_mass;
    free_x = x - (m[0] * s1 + m[1] * s2);  // lambda_t,free = lambda_t - K_tt^-1 v_t'
    free_y = y - (m[1] * s1 + m[2] * s2);
    x = free_x;
    y = free_y;
    const MaskOf<Real> outside = negated(x * x + y * y <= limit * limit);
    if (!any(outside)) return outside;
    const MaskOf<Real> apex = both(outside, limit <= splat<Real>(0.0));  // a point that pushes nothing
    const MaskOf<Real> on_circle = both(outside, negated(apex));
    const MaskOf<Real> project = both(on_circle, row.tangent_invertible);
    const MaskOf<Real> scaled = both(on_circle, negated(row.tangent_invertible));
    if (any(project)) project_on_cone<Real>(row, tangent_response, x, y, limit, project);
    if (any(scaled)) {
        const Real scale = limit / square_root(select(scaled, x * x + y * y, splat<Real>(1.0)));
        x = select(scaled, x * scale, x);
        y = select(scaled, y * scale, y);
    }
    x = select(apex, splat<Real>(0.0), x);
    y = select(apex, splat<Real>(0.0), y);
    return outside;
}

// One visit's three rows on the velocity `velocity` (row_velocity), from the total `before` (the row's, or a kept
// visit's when the recorder is shown it). The row's total is not changed here. `Row` is a ContactRow, or a wide
// record's point (methods/wide_records.hpp: the same fields, four lanes each, but K_tt, kept apart since only a
// sliding visit reads it: `tangent_response`); a row without friction (mu = 0) keeps no tangential total.
template <typename Real, typename Row>
IMPULSE_KERNEL RowVisitOf<Real> solve_rows(const Row& row, const std::array<Real, 3>& tangent_response,
                                           const AxesOf<Real>& before, const AxesOf<Real>& velocity,
                                           const NormalTargetOf<Real>& target) {
    const Real zero = splat<Real>(0.0);
    Real unclamped_n;
    const Real n = normal_row<Real>(before.n, velocity.n, row.normal_mass, target, unclamped_n);
    Real free_x = before.t1, free_y = before.t2, x = zero, y = zero;
    MaskOf<Real> sliding{};
    const MaskOf<Real> has_friction = row.friction != zero;
    if (any(has_friction)) {
        // The slip once the normal change acts: v_t' = v_t + K_tn (lambda_n after - before).
        const Real change = n - before.n;
        Real fx, fy, tx = before.t1, ty = before.t2;
        const MaskOf<Real> slides =
            friction_rows<Real>(row, tangent_response, velocity.t1 + row.normal_to_tangent[0] * change,
                                velocity.t2 + row.normal_to_tangent[1] * change, row.friction * n, fx, fy, tx, ty);
        free_x = select(has_friction, fx, free_x);
        free_y = select(has_friction, fy, free_y);
        x = select(has_friction, tx, zero);
        y = select(has_friction, ty, zero);
        sliding = both(has_friction, slides);
    }
    return {before, {unclamped_n, free_x, free_y}, {n, x, y}, unclamped_n < zero, sliding};
}
IMPULSE_KERNEL RowVisit solve_rows(const ContactRow& row, const Axes& before, const Axes& velocity,
                                   const NormalTarget& target) {
    return solve_rows<double>(row, row.tangent_response, before, velocity, target);
}

// The normal row alone (soft step's restitution, the split impulse's pushes): tangential totals unchanged.
IMPULSE_KERNEL RowVisit solve_normal_row(const ContactRow& row, double normal_velocity, const NormalTarget& target) {
    RowVisit v;
    v.before = v.unclamped = v.after = row.total_impulse;
    v.after.n = normal_row<double>(v.before.n, normal_velocity, row.normal_mass, target, v.unclamped.n);
    v.pushed_only = v.unclamped.n < 0.0;
    return v;
}

// A visit as a method keeps it for the recorder while its loop runs: what it read, the velocity and the total
// before. Kept in a buffer, before the visit is solved, and reported once the sweep is over with the visit solved
// again from them by the same solve_rows (same inputs, same bits): a call to the recorder inside the loop would keep
// every value of the visit alive across it, and so would keeping the visit's results (its totals unclamped and
// after, the clamps), on every visit, recorded or not (what the two kept velocity and total need is live anyway).
struct KeptVisit {
    Axes velocity;
    Axes before;
};

// Keeps a visit, value by value: a copy of the structs whole would keep them in memory through the whole loop.
IMPULSE_KERNEL void keep_visit(KeptVisit& kept, const Axes& velocity, const Axes& before) {
    const auto copy = [](Axes& to, const Axes& from) {
        to.n = from.n;
        to.t1 = from.t1;
        to.t2 = from.t2;
    };
    copy(kept.velocity, velocity);
    copy(kept.before, before);
}

// The impulse `a` (contact coordinates) in world coordinates, g = C a.
IMPULSE_KERNEL Vec3 world_impulse(const ContactRow& row, const Axes& a) {
    return to_world(row.basis, vector_of(a));
}

// Step 7 for one body (derivation/velocity_change.hpp): adds g m^-1 and I^-1 (r x g) to it.
IMPULSE_KERNEL void apply_to_body(SolverBody& body, const Vec3& r, const Vec3& impulse) {
    const BodyVelocityChange c = body_velocity_change(impulse, r, body.mass);
    body.velocity.x() += c.velocity_change.x();
    body.velocity.y() += c.velocity_change.y();
    body.velocity.z() += c.velocity_change.z();
    body.angular_velocity.x() += c.rotation_change.x();
    body.angular_velocity.y() += c.rotation_change.y();
    body.angular_velocity.z() += c.rotation_change.z();
}

// Step 7: applies g (world) to the row's bodies, +g to body 0 and -g to body 1.
IMPULSE_KERNEL void apply_impulse(const ContactRow& row, SolverBody* bodies, const Vec3& impulse) {
    apply_to_body(bodies[row.body[0]], row.anchor[0], impulse);
    if (row.body[1] >= 0)
        apply_to_body(bodies[row.body[1]], row.anchor[1], Vec3(-impulse.x(), -impulse.y(), -impulse.z()));
}

// Keeps `after` as the row's total, field by field (a copy of the struct can become one 16-byte load of values
// just stored 8 bytes at a time, which the processor cannot forward).
IMPULSE_KERNEL void keep_total(ContactRow& row, const Axes& after) {
    row.total_impulse.n = after.n;
    row.total_impulse.t1 = after.t1;
    row.total_impulse.t2 = after.t2;
}

// |K (after - before)|^2: how much a visit changed its own contact's velocity (m/s), squared. A norm, so the
// early stop of a sweeping method does not depend on the tangent basis.
IMPULSE_KERNEL double velocity_change_squared(const ContactRow& row, const Axes& d) {
    const std::array<double, 2>& k_tn = row.normal_to_tangent;
    const std::array<double, 3>& k_tt = row.tangent_response;
    const double n = row.normal_response * d.n + k_tn[0] * d.t1 + k_tn[1] * d.t2;
    const double t1 = k_tn[0] * d.n + k_tt[0] * d.t1 + k_tt[1] * d.t2;
    const double t2 = k_tn[1] * d.n + k_tt[1] * d.t1 + k_tt[2] * d.t2;
    return n * n + t1 * t1 + t2 * t2;
}

// Last frame's totals for this frame's rows, each remembered impulse given to one contact only: contacts of a
// frame that share a memory key (hand-written contacts carry no features) leave it to the first, since the
// memory kept the first one's total.
class RememberedTotals {
public:
    RememberedTotals(const ContactMemory& memory, std::pmr::memory_resource* scratch)
        : memory_(memory), taken_(memory.size(), 0, scratch) {}

    // The remembered total of the contact with `key` (contact_key), re-projected on this frame's basis (step 1's
    // contact_to_world) and put within the limits a total obeys, lambda_n >= 0 and |lambda_t| <= mu lambda_n (scaled
    // back: there is no slip to oppose yet), or nothing.
    std::optional<RowVisit> of(const Mat3& basis, double friction, const ContactKey& key);

private:
    const ContactMemory& memory_;
    std::pmr::vector<char> taken_;
    std::ptrdiff_t next_ = 0;  // the slot after the last one found: where the next row's contact most likely is
};

// What the two row solvers, projected Gauss-Seidel and soft step, share: the frame's solver bodies; the rows of the
// contacts that can_move, each placed in its slot in the order of the visits (contact order, or soft step's colours:
// methods/graph_colouring.hpp) as it is filled, in storage from the frame's scratch that nothing writes before (a
// vector's resize would write every row once more: 16 MB a frame on Box3D's large pyramid); their keys in detection's
// order, in which the warm start looks last frame's totals up and the memory keeps this frame's (the memory gives a key
// two contacts share to the first; most look-ups find their entry next to the last one found); the visits kept for the
// recorder (KeptVisit).
class RowSolver {
public:
    RowSolver(const RowSolver&) = delete;
    RowSolver& operator=(const RowSolver&) = delete;

    // Stores every contact's total, in world coordinates (g = C lambda, as world_impulse), under its key, as this
    // frame's memory: the rows' totals, or world(slot) for a method that finds g itself (soft step's wide records).
    void remember(ContactMemory& memory) const {
        memory.remember(keys_, [this](std::size_t k) {
            // Each contact's basis is fetched from memory again (the contacts, 272 bytes each, have long left the
            // cache): asked for a dozen contacts ahead, as the hardware does not for a stride this long (on Box3D's
            // large pyramid, under soft step before its records found g, this loop's share of the profile was 4 %,
            // 2.7 % with).
            if (k + 12 < moving_.size()) fetch_ahead(frame_.contacts[moving_[k + 12]].basis);
            return to_world(frame_.contacts[moving_[k]].basis.contact_to_world,
                            vector_of(rows_[slots_[k]].total_impulse));
        });
    }
    template <typename World>
    void remember_world(ContactMemory& memory, World world) const {
        memory.remember(keys_, [this, &world](std::size_t k) { return world(std::size_t{slots_[k]}); });
    }

protected:
    // `with_rows`: the rows are placed (place_rows); without, a method builds what it solves from the contacts
    // itself (soft step's wide records), and rows_ is empty.
    RowSolver(FrameContext& frame, bool in_colours, bool with_rows = true);
    ~RowSolver();

    // Fills every row, in detection's order, and calls fill(row, slot, contact) for what the method adds beside it.
    template <typename Fill>
    void place_rows(Fill fill) {
        for (std::size_t k = 0; k < moving_.size(); ++k) {
            const PreparedContact& contact = frame_.contacts[moving_[k]];
            ContactRow* row = new (rows_.data() + slots_[k]) ContactRow;  // the slot's row begins here
            fill_contact_row(*row, contact, bodies_.data());
            fill(*row, std::size_t{slots_[k]}, contact);
        }
    }

    // When warm starting: calls take(slot, total) for each contact that has a total remembered from last frame, in
    // detection's order.
    template <typename Take>
    void recall(Take take) {
        std::optional<RememberedTotals> remembered = remembered_totals();
        if (!remembered) return;
        for (std::size_t k = 0; k < keys_.size(); ++k)
            if (const std::optional<RowVisit> total = recalled(*remembered, k)) take(std::size_t{slots_[k]}, *total);
    }
    // The same one contact at a time, for a method that builds each row as it recalls its total (soft step's wide
    // records): last frame's totals when warm starting, else nothing; then moving contact k's, each k once, in turn.
    // (From the prepared contacts, whose basis and friction a row copies: rows or not.)
    std::optional<RememberedTotals> remembered_totals() const {
        if (!settings_.warm_start || !frame_.memory) return std::nullopt;
        return std::optional<RememberedTotals>(std::in_place, *frame_.memory, frame_.scratch);
    }
    std::optional<RowVisit> recalled(RememberedTotals& remembered, std::size_t k) const {
        const PreparedContact& contact = frame_.contacts[moving_[k]];
        return remembered.of(contact.basis.contact_to_world, contact.friction, keys_[k]);
    }

    // Shows the recorder a visit to row r at `place`: the velocity it read, step 5 as the method judged it (`terms`,
    // against `epsilon`), its totals.
    void report_visit(std::size_t r, const SweepPlace& place, const Axes& velocity, const RowVisit& visit,
                      const DesiredDeltaVelocity& terms, double epsilon, DesiredFollows updates,
                      bool friction_rows = true) const {
        frame_.recorder.velocity_visit({.contact = rows_[r].contact,
                                        .sweep = place,
                                        .epsilon = epsilon,
                                        .updates = updates,
                                        .contact_velocity = vector_of(velocity),
                                        .desired_terms = terms,
                                        .accumulated = visit.accumulated(),
                                        .friction_rows = friction_rows && rows_[r].friction != 0.0});
    }

    // Copies the solver's velocities back to the bodies.
    void store_velocities() const {
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            frame_.bodies[b].velocity = bodies_[b].velocity;
            frame_.bodies[b].angular_velocity = bodies_[b].angular_velocity;
        }
    }

    // Stamps every moving contact for LastTouch, as the order of the visits has them (rows or not), from the indices
    // alone (FrameContext::contacts is in the input's order, which the constructor asserts): a read of each prepared
    // contact took 2 % of the profile on Box3D's large pyramid, its 60,000 contacts fetched from memory again.
    void stamp() const {
        if (!frame_.touch) return;
        const LastTouch::Run visits = frame_.touch->run(moving_.size());
        for (std::size_t k = 0; k < moving_.size(); ++k) visits.visit(static_cast<int>(moving_[k]), slots_[k]);
    }

    FrameContext& frame_;
    const ResolverSettings& settings_;
    // Every buffer in the frame's scratch (FrameContext::scratch).
    std::pmr::vector<SolverBody> bodies_;
    std::pmr::vector<std::uint32_t> moving_;  // the contacts that can_move, by index, in detection's order
    std::pmr::vector<std::uint32_t> slots_;   // per moving contact: its row's slot in rows_
    std::pmr::vector<std::uint32_t> order_;   // per slot: its contact's place in moving_ (slots_'s inverse)
    std::span<ContactRow> rows_;              // in the order of the visits; each valid once placed
    std::pmr::vector<ContactKey> keys_;       // per moving contact: its key in the ContactMemory
    std::pmr::vector<KeptVisit> kept_;        // per row: its visit in the sweep under way, when the frame is recorded
    std::pmr::vector<int> colours_;           // per moving contact: its pair's colour (in colours)
    std::pmr::vector<std::array<int, 2>> pairs_;  // per moving contact: its row's bodies (in colours)
};

}  // namespace impulse
