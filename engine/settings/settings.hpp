#pragma once
// Everything that chooses how contacts are resolved, in one struct that travels with each run (no global
// toggles). Presets fill it; a case file or flag may then change single fields.

#include "derivation/avbd/avbd_settings.hpp"
#include "derivation/desired_delta_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/position_change.hpp"
#include "math/rotation.hpp"

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace impulse {

enum class PhaseOrder { positions_first, velocities_first };

// The methods, each described by its row in methods/method_table.hpp (its name, what it does, what it reads);
// `count` is not a method but how many there are.
enum class PositionMethod {
    linear_projection,
    nonlinear_projection,
    velocity_based,
    relaxation,
    split_impulse,
    none,
    count
};

enum class VelocityMethod { worst_first, sequential_sweep, projected_gauss_seidel, soft_step, avbd, count };

// How worst-first finds its next contact. Both choose the same contacts in the same order and give identical
// results; full_scan is the reference engine's loop over every contact per iteration (cost ~ contacts^2).
enum class WorstFirstSearch {
    priority_queue,  // a tournament tree of contacts; after each resolution only the contacts sharing a body
                     // replay their matches
    full_scan,       // the book's scan of every contact per iteration
};

// The order soft step visits its contacts in, each sweep (methods/graph_colouring.hpp).
enum class SolveOrder {
    contacts,  // as detection listed them: pair by pair, in the broad phase's order
    colours,   // Box3D's constraint graph: colour by colour, no two pairs of a colour sharing a moving body, the pairs
               // with a static body (the ground) in the last colours
    wide,      // the colours, four pairs at a time in single precision (methods/wide_records.hpp)
};

// The velocity-level position correction of `baumgarte` (a term of step 5) and of split_impulse (the push's
// target): instead of moving the bodies, ask the contact to separate at a speed that would close a share of the
// penetration within one frame. Baumgarte (1972) for constraint drift; in games Catto's sequential impulses and
// Bullet.
struct PositionBiasSettings {
    double factor = 0.2;  // beta: share of the penetration removed per frame
    double slop = 0.005;  // m: penetration left alone, so resting contacts do not jitter between touching and parting

    bool operator==(const PositionBiasSettings&) const = default;
};

// position_bias = beta x max(penetration - slop, 0) / h, h the frame duration.
inline double position_bias(double penetration, const PositionBiasSettings& bias, double duration) {
    return bias.factor * std::max(penetration - bias.slop, 0.0) / duration;
}

// Box2D v3's soft step (solver.c, contact_solver.c): `substeps` sub-steps per frame, each integrating the
// velocities, solving with a soft contact of stiffness `contact_hertz` and damping ratio `damping_ratio`,
// integrating the positions and relaxing without the bias; restitution is applied once after the sub-steps.
struct SoftStepSettings {
    int substeps = 4;
    double contact_hertz = 30.0;
    double damping_ratio = 10.0;
    double max_push_velocity = 3.0;           // m/s: the fastest the soft contact pushes overlapping bodies apart
    SolveOrder order = SolveOrder::contacts;  // the contacts' order in every sweep

    bool operator==(const SoftStepSettings&) const = default;
};

// Contact recycling (Box3D, Catto 2026: physics_world.c's collide task; memory/contact_recycling.hpp): a pair's
// contacts, as detected, are kept from frame to frame (normal, features, each body's own anchor) while the pair's
// relative pose has moved less than `distance` and neither body has turned more than `angle` since they were
// detected; each kept contact's penetration is found again from its anchors. distance 0 (every preset but
// soft_step_recycled): every frame detects afresh.
struct RecyclingSettings {
    double distance = 0.0;  // m: the relative move (with the turn's arc at the shapes' reach) a kept pair may make
    double angle = 10.0;    // degrees: the most either body may turn (Box3D: cos^2(angle / 2) > 0.99240388)

    bool on() const { return distance > 0.0; }
    bool operator==(const RecyclingSettings&) const = default;
};

struct RelaxationSettings {
    double fraction = 0.5;  // share of a contact's current penetration removed when it is visited
    int passes = 4;         // each pass visits every contact above the epsilon once, worst first

    bool operator==(const RelaxationSettings&) const = default;
};

struct ResolverSettings {
    std::string preset = "book";
    PhaseOrder phase_order = PhaseOrder::positions_first;
    PositionMethod position_method = PositionMethod::nonlinear_projection;
    VelocityMethod velocity_method = VelocityMethod::worst_first;
    WorstFirstSearch worst_first_search = WorstFirstSearch::priority_queue;
    SlidingFriction sliding_friction = SlidingFriction::reference;  // worst_first, sequential_sweep
    AngularLimitSettings angular_limit{};
    RelaxationSettings relaxation{};
    double position_epsilon = 0.01;  // m: penetrations at or below this are left alone
    double velocity_epsilon = 0.01;  // m/s: desired velocity changes at or below this are left alone
    // A phase's iteration limit: iterations_per_contact x number of contacts, unless the phase's fixed limit is
    // set (methods/method_table.hpp lists the methods that read them).
    int iterations_per_contact = 4;
    std::optional<int> position_iterations;  // a fixed limit for the position phase
    std::optional<int> velocity_iterations;  // a fixed limit for the velocity phase
    int sweeps = 10;         // sequential_sweep, projected_gauss_seidel, soft_step (per sub-step), split_impulse
    bool warm_start = true;  // projected_gauss_seidel and soft_step: start from last frame's impulses
    // Baumgarte stabilisation: step 5 gains the term position_bias = factor max(penetration - slop, 0) / h
    // (position_bias below), so the velocity methods that read step 5 push the bodies apart.
    bool baumgarte = false;
    PositionBiasSettings position_bias{};
    SoftStepSettings soft_step{};
    AvbdSettings avbd{};
    RecyclingSettings recycling{};  // off unless distance > 0: contacts detected afresh every frame
    // m: a face contact between two boxes also keeps the clipped points up to this far outside the reference face,
    // as speculative points (negative penetration), so a face landing on a slight tilt is stopped on all its
    // corners at once (Box3D's manifold keeps its points within 2 cm). 0: only the points that touch.
    double speculative_margin = 0.0;
    // The reference engine's chapter-15 refinements of steps 4 and 5 (velocity_refinements() below gives them to
    // step 5). Contacts closing slower than restitution_cutoff (m/s) bounce with restitution 0, so resting
    // contacts do not jitter; 0 switches the cut-off off. Reference engine: 0.25.
    double restitution_cutoff = 0.25;
    // Remove from the bounce the velocity that last frame's acceleration built up along the normal.
    bool velocity_from_acceleration = true;
    // Add the tangential part of last frame's acceleration to the contact velocity (step 4).
    bool tangential_acceleration_velocity = true;
    OrientationUpdate orientation_update = OrientationUpdate::first_order;
    double duration = 1.0 / 60.0;  // s: the frame the contacts come from (for the acceleration terms)

    bool operator==(const ResolverSettings&) const = default;
};

// The refinements as step 5 takes them.
inline VelocityRefinements velocity_refinements(const ResolverSettings& s) {
    return {s.restitution_cutoff, s.velocity_from_acceleration, s.tangential_acceleration_velocity};
}

// A phase's iteration limit: its `fixed` limit (position_iterations, velocity_iterations) when set, else
// iterations_per_contact x the contacts.
inline int iteration_limit(std::optional<int> fixed, const ResolverSettings& settings, int contact_count) {
    return fixed.value_or(settings.iterations_per_contact * contact_count);
}

// The named presets:
//   book     the reference engine: positions then velocities, worst-first, epsilons 0.01, lever-arm limit
//            0.2, iterations 4 x contacts per phase, restitution cut-off 0.25 m/s, both acceleration
//            refinements, first-order orientation update then normalise.
//   chapter  the chapter's text as written: velocities then positions, delta v = -(1 + c) v_s with no
//            chapter-15 refinements, the text's fixed angular limit of 0.5; otherwise as book.
//   sweep    the book's impulses and projections, but contacts visited in order, `sweeps` sweeps.
//   pgs      sequential impulses as production engines use them: projected Gauss-Seidel with accumulated,
//            clamped, warm-started impulses, no position phase and Baumgarte bias 0.2 (Bullet's defaults,
//            10 iterations).
//   pgs_split   pgs with split impulse instead of Baumgarte (Bullet's split-impulse mode).
//   soft_step   Box2D v3: 4 sub-steps of soft contacts, one relax sweep each, restitution after.
//   soft_step_recycled  soft_step with Box3D's contact recycling: a pair's contacts kept while it moves less than
//            5 cm (Box3D's 10 linear slops) and turns less than 10 degrees; contacts of 36 Hz, damping ratio 12;
//            box-box face points kept up to 2 cm outside as speculative points (Box3D's 4 linear slops).
//   soft_step_coloured  soft_step_recycled with its contacts solved colour by colour (soft_step.order = colours).
//   soft_step_wide  soft_step_coloured four pairs of a colour at a time, in single precision (soft_step.order = wide).
//   avbd        augmented vertex block descent: 10 iterations of block solves and dual updates (AvbdSettings).
std::span<const std::string_view> preset_names();
// "book", "chapter", ... as one line for error messages.
std::string preset_list_text();
std::optional<ResolverSettings> preset(std::string_view name);

}  // namespace impulse
