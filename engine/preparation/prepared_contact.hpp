#pragma once
// A contact made ready for resolution: derivation steps 1-5 computed once (the book computes basis,
// relative positions and the bodies' world inverse inertia once per frame and never re-derives geometry
// mid-resolve), plus the three values the resolver keeps up to date as other contacts are resolved.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "derivation/basis.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/desired_delta_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "settings/settings.hpp"

#include <array>
#include <span>
#include <vector>

namespace impulse {

// Steps 1-5 for one contact, exactly as the recorder stores them.
struct ContactPreparation {
    int contact;                // index in the input contact list
    bool swapped;               // given with the world as body 0: bodies exchanged and normal negated
    std::array<int, 2> bodies;  // after swapping; bodies[1] may be world_body
    Vec3 point;
    Vec3 normal;  // after swapping: from body 1 towards body 0
    double penetration;
    double restitution;
    double friction;
    ContactOrigin origin;                 // the test and features that made it (features swapped with the bodies)
    bool inert;                           // both bodies immovable: no impulse or move can change this contact
    Basis basis;                          // step 1
    PerBody<Vec3> relative_position;      // step 2
    UnitImpulseChain unit_impulse_chain;  // step 3
    ContactVelocityTerms velocity_terms;  // step 4
    DesiredDeltaVelocity desired_terms;   // step 5

    bool operator==(const ContactPreparation&) const = default;
};

// A value computed on first use and kept beside what it was computed from. Not part of the value of the struct
// holding it, so comparisons ignore it.
template <typename T>
struct Cached {
    std::optional<T> value;

    // Empty, not defaulted: then a prepared contact built with an empty cache is not cleared byte by byte first.
    Cached() {}
    bool operator==(const Cached&) const { return true; }
};

struct PreparedContact {
    // Bookkeeping, updated by the linearised formulas whenever a body of this contact moves or changes speed.
    // First, next to the derivation's bodies, basis and relative positions, which every update reads too.
    double penetration;
    Vec3 contact_velocity;
    DesiredDeltaVelocity desired_terms;
    ContactPreparation derivation;
    PerBody<MassProperties> mass;  // the bodies' inverse mass and world inverse inertia when prepared
    // K and its factors for the book's friction impulse (derivation/impulse.hpp): computed by the first impulse on
    // this contact and reused by the later ones, since they depend only on what preparation fixed.
    mutable Cached<FactoredDeltaVelocityMatrix> delta_velocity_matrix;

    bool operator==(const PreparedContact&) const = default;
};

// The Δv a velocity method compares with its epsilon and resolves: the bookkeeping's (with the Baumgarte term
// of step 5 when it is on).
inline double desired_of(const PreparedContact& c) {
    return c.desired_terms.desired_delta_velocity;
}

// The contact's K and its factors, computed on first use and then kept in the contact.
const FactoredDeltaVelocityMatrix& delta_velocity_matrix_of(const PreparedContact& contact);

// Each body's mass properties once per frame, with the world inverse inertia R I^-1 R^T.
std::vector<MassProperties> mass_properties(std::span<const RigidBody> bodies);

// What steps 1-5 are made of, shared by the full preparation below and the rows' (row_preparation.hpp), so the
// two compute each value the same way.

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
// Step 5's Baumgarte term, when the setting is on (preparation/position_bias.hpp).
std::optional<double> step_5_position_bias(double penetration, const ResolverSettings& settings);

PreparedContact prepare_contact(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                std::span<const MassProperties> mass, const ResolverSettings& settings);

std::vector<PreparedContact> prepare_contacts(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                                              std::span<const MassProperties> mass, const ResolverSettings& settings);

}  // namespace impulse
