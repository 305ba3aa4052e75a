#pragma once
// A contact as the accumulating methods' rows read it (projected Gauss-Seidel, the split impulse, soft step): the
// values of steps 1, 2, 4 and 5 that make a ContactRow and its target, without the intermediates the recorder
// keeps. (Step 3 the rows take from their own K: methods/contact_rows.hpp.)
//
// Two ways to the same numbers. When a recorder keeps the frame, or a method of the frame reads the full
// preparation, every contact is prepared in full (PreparedContact: steps 1-5 with every intermediate, 1.2 kB)
// and row_preparation() reads these values off it. Otherwise prepare_rows() computes them straight from the
// detected contacts, with the same functions on the same inputs (preparation/prepared_contact.hpp), and only
// the steps the frame's methods read: bit for bit the full preparation's values, so a method's result never
// depends on whether it was watched (tests/engine/test_methods.cpp runs every method both ways).

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "derivation/basis.hpp"
#include "preparation/prepared_contact.hpp"
#include "settings/settings.hpp"

#include <array>
#include <memory_resource>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// Steps 4 and 5 as a rigid row reads them.
struct RowVelocity {
    double separating_velocity = 0.0;  // step 4's x: v_s when the frame's resolution began
    // Step 4's tangential acceleration term, body 0's minus body 1's, along tangents 1 and 2 (0 with the
    // refinement off): the slip last frame's acceleration builds up, which friction is to remove too.
    std::array<double, 2> tangential_acceleration_velocity{0.0, 0.0};
    double desired_delta_velocity = 0.0;  // step 5, with Baumgarte's position bias when it is on

    bool operator==(const RowVelocity&) const = default;
};

struct RowPreparation {
    int contact = 0;                           // index in the input contact list
    bool swapped = false;                      // given with the world as body 0: bodies exchanged, normal negated
    std::array<int, 2> bodies{0, world_body};  // after swapping: body 1 may be the world
    ContactOrigin origin;                      // the test and features that made it (swapped with the bodies)
    Basis basis;                               // step 1 (contact x: the normal, from body 1 towards body 0)
    std::array<Vec3, 2> relative_position;     // step 2, q - p per body; zero for the world
    double penetration = 0.0;                  // m, as detected
    double restitution = 0.0;                  // c
    double friction = 0.0;                     // mu
    std::optional<RowVelocity> velocity;       // steps 4 and 5, when prepared with them

    bool operator==(const RowPreparation&) const = default;
};

// The row values of a contact prepared in full (with steps 4 and 5).
RowPreparation row_preparation(const PreparedContact& contact);

// The same values for contact `index`, computed without the full preparation's records; steps 4 and 5 only
// `with_velocity`.
RowPreparation prepare_row(int index, const Contact& contact, std::span<const RigidBody> bodies,
                           const ResolverSettings& settings, bool with_velocity);

// The same for every contact, into `rows` (one per contact, in order).
void prepare_rows(std::span<const Contact> contacts, std::span<const RigidBody> bodies,
                  const ResolverSettings& settings, bool with_velocity, std::pmr::vector<RowPreparation>& rows);

// Step 4's separating velocity v_s (as the frame's resolution began, from `bodies`' motion then): the prepared
// value, or for a row prepared without steps 4 and 5 the same function's on the same inputs.
double separating_velocity(const RowPreparation& row, std::span<const RigidBody> bodies,
                           const ResolverSettings& settings);

}  // namespace impulse
