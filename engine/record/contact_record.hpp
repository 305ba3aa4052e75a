#pragma once
// A contact's record: derivation steps 1-5 with every intermediate, as a trace keeps them. Built only when a
// recorder keeps the frame, from the contact as detected and the bodies before resolution, by the derivation's
// functions, the ones preparation/prepared_contact.hpp computes the resolution's values through: the record's
// values are the resolution's, by construction.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "derivation/basis.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "derivation/desired_delta_velocity.hpp"
#include "settings/settings.hpp"

#include <array>
#include <optional>
#include <span>

namespace impulse {

// Steps 1-5 for one contact, exactly as the recorder stores them.
struct ContactPreparation {
    int contact;                      // index in the input contact list
    bool swapped;                     // given with the world as body 0: bodies exchanged and normal negated
    std::array<int, 2> bodies;        // after swapping; bodies[1] may be world_body
    Vec3 point;                       // q: where body 0 is touched (and body 1, unless body1_point says otherwise)
    std::optional<Vec3> body1_point;  // where body 1 is touched when that is not `point`: a recycled contact's
                                      // bodies keep their own anchors (Contact::body1_point); empty otherwise
    Vec3 normal;                      // after swapping: from body 1 towards body 0
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

// Steps 1-5 of contact `index`, with the bodies and their mass as resolution began.
ContactPreparation contact_preparation(int index, const Contact& contact, std::span<const RigidBody> bodies,
                                       std::span<const MassProperties> mass, const ResolverSettings& settings);

}  // namespace impulse
