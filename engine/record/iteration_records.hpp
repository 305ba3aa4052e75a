#pragma once
// What one resolver iteration did, as plain structs: the contact chosen and why, the derivation values of
// the move or impulse, and every update it made to the bookkeeping of the contacts that share a body.

#include "derivation/desired_delta_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "record/avbd_records.hpp"
#include "record/position_resolution.hpp"

#include <optional>
#include <vector>

namespace impulse {

enum class Phase { position, velocity };

// One contact's penetration changed because one of its bodies moved:
// penetration -= (linear_change + angular_change x q_rel) . n for its body 0, += for its body 1.
struct PenetrationUpdate {
    int contact;   // the contact updated
    int body;      // the moved body (index in the body list)
    int slot;      // 0 or 1: which of the updated contact's bodies that is
    double delta;  // change of its penetration
    double before;
    double after;

    bool operator==(const PenetrationUpdate&) const = default;
};

// One contact's velocity changed because one of its bodies received an impulse:
// contact_velocity += +-C^T (velocity_change + rotation_change x q_rel), then step 5 again.
struct VelocityUpdate {
    int contact;
    int body;
    int slot;
    Vec3 delta;  // change of its contact velocity, contact coordinates
    Vec3 before;
    Vec3 after;
    double desired_delta_velocity_before;
    double desired_delta_velocity_after;

    bool operator==(const VelocityUpdate&) const = default;
};

struct PositionIteration {
    int iteration;
    int contact;                 // the contact chosen: the deepest above the epsilon
    double penetration;          // its penetration, compared with the epsilon
    double epsilon;              // the projections' (0 for the split impulse, which compares nothing: see slop)
    std::optional<double> slop;  // the split impulse's: the penetration its pushes leave, not an epsilon
    std::optional<int> pass;     // relaxation: which pass this iteration belongs to; the split impulse: which sweep
    // Absent when the recorder's contact filter leaves the chosen contact out.
    std::optional<PositionResolution> resolution;
    std::vector<PenetrationUpdate> updates;

    bool operator==(const PositionIteration&) const = default;
};

struct VelocityResolution {
    Vec3 contact_velocity;                 // step 4 as the bookkeeping has it now
    DesiredDeltaVelocity desired_terms;    // step 5 re-evaluated on that velocity; its position_bias is
                                           // Baumgarte's (or soft step's soft push): the separating speed
                                           // added to push the bodies apart (m/s)
    Impulse impulse_terms;                 // step 6 (for an accumulating solver: the clamped increment)
    VelocityChange velocity_change_terms;  // step 7

    bool operator==(const VelocityResolution&) const = default;
};

// Which limit an accumulating solver (projected Gauss-Seidel, soft step) applied to a contact's running total.
enum class ImpulseClamp {
    none,       // the total stayed inside its limits
    push_only,  // the normal total would have pulled (< 0): set to 0
    friction,   // the tangential total left the cone |f_t| <= mu f_n: scaled back onto it
    both,
};

// Sequential impulses keep a running total per contact; each visit changes it, and only the change is applied.
struct AccumulatedImpulse {
    Vec3 before;     // contact coordinates: the total before this visit
    Vec3 unclamped;  // before + this visit's raw impulse
    Vec3 after;      // after the clamp; the impulse applied this visit is after - before
    ImpulseClamp clamp = ImpulseClamp::none;

    bool operator==(const AccumulatedImpulse&) const = default;
};

// What a sweeping solver was doing when it visited the contact.
enum class SolverStage {
    warm_start,   // last frame's total applied again at the start
    solve,        // a sweep with the position bias
    relax,        // soft step: a sweep without the bias, removing the velocity the bias added
    restitution,  // soft step, AVBD: the bounce, applied once after the sub-steps (the iterations)
    push,         // split impulse: a sweep on the pseudo-velocities that only move positions
    stabilize,    // AVBD: the sweep after the velocities were taken, moving the bodies out of what penetration is left
    dual,         // AVBD: every contact's dual update after a sweep over the bodies
};

struct SweepPlace {
    int substep = 0;  // soft step's sub-step; 0 otherwise
    int pass = 0;     // sweep number within the stage
    SolverStage stage = SolverStage::solve;

    bool operator==(const SweepPlace&) const = default;
};

struct VelocityIteration {
    int iteration;
    int contact;                    // the contact chosen: the largest desired delta v above the epsilon (or the
                                    // contact a sweep visits)
    double desired_delta_velocity;  // its value, compared with the epsilon
    double epsilon;
    std::optional<SweepPlace> sweep;                // every method but worst-first: where in the sweeps
    std::optional<AccumulatedImpulse> accumulated;  // projected Gauss-Seidel and soft step
    std::optional<VelocityResolution> resolution;   // absent when filtered out
    std::vector<VelocityUpdate> updates;
    // AVBD (record/avbd_records.hpp): a body visit, whose `contact` is the first it gathered, or a contact's dual
    // update. Neither has a desired delta v or an epsilon (both 0, and not written).
    std::optional<BodyVisitRecord> body_visit;
    std::optional<DualUpdateRecord> dual_update;

    bool operator==(const VelocityIteration&) const = default;
};

enum class StopReason {
    resolved,         // nothing left above the epsilon
    iteration_limit,  // the limit was reached with something still above the epsilon
    passes_complete,  // relaxation ran all its passes; what remains above the epsilon is left by design
    unmovable_left,   // what remains above the epsilon the method cannot move (linear projection, bodies
                      // that cannot translate)
    sweeps_complete,  // a sweeping method ran all its sweeps with something still above the epsilon (or, for
                      // soft step, which always runs them all)
};

struct PhaseOutcome {
    int iteration_limit = 0;
    int iterations_used = 0;
    StopReason stop = StopReason::resolved;

    bool operator==(const PhaseOutcome&) const = default;
};

}  // namespace impulse
