#pragma once
// A contact made ready for resolution, one plain struct for every method (solver2d's and qu3e's one constraint
// per contact): derivation steps 1-5 computed once per frame by the derivation's own functions (the book computes
// basis, relative positions and the bodies' world inverse inertia once per frame and never re-derives geometry
// mid-resolve), plus the book's bookkeeping, which its loops keep up to date as other contacts are resolved.
//
// Only the values are kept, not their intermediates: when a recorder keeps the frame, record/contact_record.hpp
// derives the full record of steps 1-5 from the same contact, the same bodies and the same functions. K, the
// friction rows' and the book's friction solve's matrix, is not kept either: it is computed where it is read
// (derivation/impulse.hpp), since the book needs it only for the contacts it resolves.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "derivation/basis.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "derivation/desired_delta_velocity.hpp"
#include "memory/contact_memory.hpp"
#include "settings/settings.hpp"

#include <array>
#include <memory_resource>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

struct PreparedContact {
    // Left unset: every member is written by prepare_contacts (a vector of them is not cleared byte by byte first).
    PreparedContact() {}

    // The bookkeeping, updated by the linearised formulas whenever a body of this contact moves or changes speed
    // (preparation/bookkeeping.hpp). First: every update reads and writes it. The position phase owns the
    // penetration and the velocity phase the rest, so a method reads its phase's values as prepared unless it
    // updates them itself.
    double penetration;             // m: as detected, then as the position phase's moves left it
    Vec3 contact_velocity;          // step 4, contact coordinates: v_s = x
    double desired_delta_velocity;  // step 5 on that velocity (with Baumgarte's term when it is on)

    int contact;                // index in the input contact list
    std::array<int, 2> bodies;  // after swapping: body 1 may be world_body
    bool swapped;               // given with the world as body 0: bodies exchanged and normal negated
    bool inert;                 // d <= 0: no impulse or move can change this contact
    ContactOrigin origin;       // the test and features that made it (features swapped with the bodies)
    // Step 3's d, beside the contact's identity: what the row solvers read first of every contact (whether it can
    // move, and its key), in one or two cache lines of the 272 bytes.
    double delta_velocity_per_unit_impulse;
    double restitution;                     // c
    double friction;                        // mu
    Basis basis;                            // step 1: basis.normal() points from body 1 towards body 0
    std::array<Vec3, 2> relative_position;  // step 2, q - p per body; zero for the world
    // Step 4's tangential acceleration term, body 0's minus body 1's, along tangents 1 and 2 (0 with the refinement
    // off): the slip last frame's acceleration builds up, which the accumulating methods' friction rows remove too.
    std::array<double, 2> tangential_acceleration_velocity;
    // What step 5 is judged again from, fixed at preparation (desired_again gives its terms in full):
    double velocity_from_acceleration;    // (a0 - a1) . n x duration; 0 with the refinement off
    std::optional<double> position_bias;  // Baumgarte's term, when it is on
};

// Each body's mass properties once per frame, with the world inverse inertia R I^-1 R^T.
std::vector<MassProperties> mass_properties(std::span<const RigidBody> bodies);

// Body 0 must be a body: a contact given as (world, body) becomes (body, world) with the normal reversed and
// the features exchanged, so the normal still points towards body 0.
struct OrientedContact {
    bool swapped;               // the bodies were exchanged
    std::array<int, 2> bodies;  // body 1 may be world_body
    ContactOrigin origin;       // features in the new order
    Vec3 normal;                // from body 1 towards body 0
};
OrientedContact oriented(const Contact& contact);

// What steps 4 and 5 read: the bodies' motion.
PerBody<BodyMotion> contact_motion(const std::array<int, 2>& bodies, std::span<const RigidBody> all_bodies);
// Step 5's Baumgarte term, when the setting is on (settings/settings.hpp).
std::optional<double> step_5_position_bias(double penetration, const ResolverSettings& settings);

// How much of steps 4 and 5 a frame prepares. Every method but one reads all of it. Soft step finds its own
// targets: it reads step 4's v_s but neither step 4's tangential refinement nor step 5. For it the contact velocity is
// prepared without the refinement, and the rest is left NaN (tangential_acceleration_velocity,
// velocity_from_acceleration, desired_delta_velocity) or empty (position_bias), unless the recorder keeps the frame:
// the recorder shows steps 1 to 5 whatever the method. (On Box3D's large pyramid, 60,000 contacts a frame, the
// functions of step 5 and the refinements took 2.4 % of soft step's profile.)
enum class Preparation { steps_1_to_4, steps_1_to_5 };

// Every contact, in order, into `prepared` (emptied first).
void prepare_contacts(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                      std::span<const MassProperties> mass, const ResolverSettings& settings,
                      std::pmr::vector<PreparedContact>& prepared, Preparation preparation = Preparation::steps_1_to_5);

// A prepared contact's bodies' mass, for the kernel (body 1 null for the world) and as the derivation's records
// take it (body 1 empty for the world).
ContactMass contact_mass(const PreparedContact& contact, std::span<const MassProperties> mass);
PerBody<MassProperties> mass_of(const PreparedContact& contact, std::span<const MassProperties> mass);
// Its relative positions as the derivation's records take them (body 1 empty for the world).
PerBody<Vec3> relative_positions(const PreparedContact& contact);

// The key the contact had as detected (before preparation put the world second), for ContactMemory.
ContactKey contact_key(const PreparedContact& contact);

}  // namespace impulse
