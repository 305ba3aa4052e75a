#pragma once
// Soft step, Box2D v3's solver (solver.c, contact_solver.c; solver2d's solve_soft_step.c), in 3D.
//
// A frame of h = settings.duration is cut into n = settings.soft_step.substeps sub-steps of h_s = h / n, and
// the method integrates the bodies itself, so the world step detects contacts at the current positions and
// hands the frame to it. Per sub-step:
//   1. integrate velocities: v += g h_s, damping as in the world step (body/integrate.hpp);
//   2. warm start: apply each contact's accumulated impulse lambda (contact coordinates) again;
//   3. solve: `sweeps` sweeps over the contacts with the soft contact's bias;
//   4. integrate positions: x += v h_s, q turned by w h_s (settings.orientation_update);
//   5. relax: `sweeps` sweeps without the bias, removing the velocity the bias added.
// After the sub-steps:
//   6. restitution, once: contacts that closed faster than the cut-off when the frame began and were pushed
//      get the normal target -c v_n(before);
//   7. store each lambda in the ContactMemory (world coordinates) when settings.warm_start.
// Every stage visits the contacts in settings.soft_step.order: as detected, or colour by colour (Box3D's constraint
// graph, methods/graph_colouring.hpp), or colour by colour four pairs at a time in single precision (`wide`, Box3D's
// b3ContactConstraintWide: methods/wide_records.hpp); the order is fixed for the frame.
//
// The soft contact (Catto, "Solver2D" and Box2D v3's b2MakeSoft): the contact is a spring of stiffness
// k = m omega^2 and damper c = 2 m zeta omega on the effective mass m, omega = 2 pi hertz, stepped with implicit
// Euler over h_s. Solving m (v2 - v1) = -h_s (k (C + h_s v2) + c v2) for the impulse gives
//   a1 = 2 zeta + h_s omega,  a2 = h_s omega a1,
//   bias_rate = omega / a1,  mass_scale = a2 / (1 + a2),  impulse_scale = 1 / (1 + a2),
// and one visit changes the accumulated normal impulse by
//   delta lambda_n = -m_n mass_scale (v_n + bias) - impulse_scale lambda_n,   m_n = 1 / d (step 3),
//   bias = max(-bias_rate p, -max_push_velocity)   for penetration p >= 0,
// then lambda_n = max(lambda_n + delta, 0). Since mass_scale + impulse_scale = 1 the visit's fixed point is the
// soft impulse -m_n mass_scale (v_free + bias): the bodies are pushed apart at most at max_push_velocity, and
// softly, so a stack does not jitter. The hertz is capped at a quarter of the sub-step rate (the spring must
// not be stiffer than the sub-step can follow). A separated point (p < 0) is speculative: bias = -p / h_s,
// with mass_scale 1 and impulse_scale 0, so the bodies may close the gap in this sub-step but no further.
// Relax uses mass_scale 1, impulse_scale 0 and no bias for p >= 0: a rigid velocity solve.
// The rows are methods/contact_rows.hpp's: the normal row with the soft scales above, and the two friction rows
// solved together against the slip the normal increment leaves, the total on or inside the cone
// |lambda_t| <= mu lambda_n and, when sliding, exactly against the slip (rigid, as in Box2D).
//
// The penetration is recomputed from how the bodies moved since the frame began, with the anchors fixed in
// the bodies (Box2D: separation + dot(d, normal)):
//   p = p0 - n . [(dx0 + R0 r0 - r0) - (dx1 + R1 r1 - r1)],
// dx_i the body's move and R_i its turn since the frame began, r_i the relative position at preparation. The
// bodies move only when the positions are integrated, so p is computed once per contact per sub-step, there,
// and serves that sub-step's relax and the next one's solve. The velocities use the anchors and world
// inverse inertia fixed at preparation, as Box2D does.
//
// Warm starting across frames is `settings.warm_start`; within a frame every sub-step's warm start applies the
// current totals whatever the setting (as in Box2D v3, where the setting only scales last step's impulses).
//
// What is reported, when the recorder keeps the frame (docs/methods.md, "What is recorded"; the same loop either
// way, so recorded and unrecorded runs compute the same bits): every visit, with sweep = {substep, pass, stage},
// its totals, the velocity it read and desired delta v = target - v_n (a warm start, which has no target: the
// normal velocity change it makes, (K lambda)_n, from before = 0). Every visit counts as an iteration.

#include "math/lanes.hpp"
#include "methods/method.hpp"
#include "settings/settings.hpp"

namespace impulse {

// b2MakeSoft: the soft contact's coefficients for a spring of `hertz` and `damping_ratio` over a step `h`.
struct Softness {
    double bias_rate;      // 1/s: omega / (2 zeta + h omega)
    double mass_scale;     // share of the rigid impulse a visit applies, a2 / (1 + a2)
    double impulse_scale;  // share of the accumulated impulse a visit gives back, 1 / (1 + a2)

    bool operator==(const Softness&) const = default;
};

Softness soft_contact(double hertz, double damping_ratio, double h);

// The soft contact soft step uses for `settings`: hertz capped at a quarter of the sub-step rate.
Softness soft_step_softness(const ResolverSettings& settings);

// What a point at penetration p asks of the coming solve and relax (contact_solver.c's three cases), as the normal
// velocity each aims for, -bias. Over a double, or four floats (a wide record's lanes).
template <typename Real>
struct SoftAimOf {
    Real solve_velocity;  // -max(-bias_rate p, -max_push_velocity) when soft, else p / h_s
    Real relax_velocity;  // 0 when soft (relax: the rigid contact, no bias), else p / h_s
    MaskOf<Real> soft;    // p >= 0: the solve's target is the soft contact's (else speculative)
};

template <typename Real>
IMPULSE_KERNEL SoftAimOf<Real> soft_aim(Real penetration, Real bias_rate, Real max_push_velocity, Real substep) {
    const MaskOf<Real> soft = penetration >= splat<Real>(0.0);
    // Speculative: a gap of -p may close at up to -p / h_s in this sub-step, and no push is asked for.
    const Real speculative = penetration / substep;
    const Real bias = -bias_rate * penetration, most = -max_push_velocity;
    const Real pushed = -select(bias < most, most, bias);  // -max(bias, most), as std::max
    return {select(soft, pushed, speculative), select(soft, splat<Real>(0.0), speculative), soft};
}

// How far a body's anchor r moved since the frame began, dx + R r - r (R its turn): the term of p's update above.
template <typename V, typename M>
IMPULSE_KERNEL V anchor_move(const V& moved, const M& turned, const V& anchor) {
    const V r = times(turned, anchor);
    return {moved.x() + (r.x() - anchor.x()), moved.y() + (r.y() - anchor.y()), moved.z() + (r.z() - anchor.z())};
}

// The method itself is soft_step(FrameContext&) (methods/method_table.hpp): it owns the whole step, moving every
// body over settings.duration under frame.forces (contacts or not) while it resolves the contacts.

}  // namespace impulse
