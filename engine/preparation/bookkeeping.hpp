#pragma once
// After a move or an impulse, the book does not re-derive any geometry: it updates the penetration (or the
// contact velocity and desired delta v) of every contact that shares a moved body by the linearised
// formulas, using the relative positions fixed when the contacts were prepared. The book's loops keep their
// bookkeeping this way, and the recorder keeps its copy the same way (record/visit_records.hpp), with these
// functions, so the two agree to the bit.

#include "derivation/position_change.hpp"
#include "derivation/velocity_change.hpp"
#include "preparation/prepared_contact.hpp"

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace impulse {

// Per body, the indices of the contacts touching it, ascending (one flat array with an offset per body).
class ContactsByBody {
public:
    // `contacts`: anything that holds each contact's two bodies in `bodies` (the prepared contacts, AVBD's).
    template <typename Contacts>
    ContactsByBody(const Contacts& contacts, std::size_t body_count) : first_(body_count + 1, 0) {
        // Count each body's contacts, turn the counts into starts, then place the contacts in index order.
        for (const auto& c : contacts)
            for (const int body : c.bodies)
                if (body != world_body) ++first_[static_cast<std::size_t>(body) + 1];
        for (std::size_t b = 0; b < body_count; ++b) first_[b + 1] += first_[b];
        contacts_.resize(static_cast<std::size_t>(first_[body_count]));
        std::vector<int> next(first_.begin(), first_.end() - 1);
        for (std::size_t i = 0; i < std::size(contacts); ++i)
            for (const int body : contacts[i].bodies)
                if (body != world_body)
                    contacts_[static_cast<std::size_t>(next[static_cast<std::size_t>(body)]++)] = static_cast<int>(i);
    }
    // The contacts touching `body`, ascending (none for the world).
    std::span<const int> contacts_of(int body) const;
    // The contacts touching either of `moved` (the world touches nothing), each once, ascending, into `out`.
    void sharing(const std::array<int, 2>& moved, std::vector<int>& out) const;

private:
    std::vector<int> first_;     // per body, where its contacts start in contacts_; one more at the end
    std::vector<int> contacts_;  // every body's contacts, body after body
};

// The desired delta v a velocity method compares with its epsilon and resolves: the bookkeeping's (with the
// Baumgarte term of step 5 when it is on); and the penetration a position method compares with its epsilon.
inline double desired_of(const PreparedContact& c) {
    return c.desired_delta_velocity;
}
inline double penetration_of(const PreparedContact& c) {
    return c.penetration;
}

// Whether any non-inert contact's `value` (desired_of, penetration_of) is still above `epsilon`: what tells
// "resolved" from the other stop reasons, one scan once per phase.
template <typename Value>
bool any_above(std::span<const PreparedContact> contacts, double epsilon, Value value) {
    for (const PreparedContact& c : contacts)
        if (!c.inert && value(c) > epsilon) return true;
    return false;
}

// Calls each(index, slot, m) for every contact `index` of `candidates` (ascending) whose body `slot` is the moved
// body moved[m] (0 or 1 of the resolved contact), in that order. The world never moves. A contact sharing both
// moved bodies is visited twice.
template <typename Each>
void for_each_sharing(std::span<const PreparedContact> contacts, std::span<const int> candidates,
                      const std::array<int, 2>& moved, Each each) {
    for (const int index : candidates) {
        const std::array<int, 2>& bodies = contacts[static_cast<std::size_t>(index)].bodies;
        for (int slot = 0; slot < 2; ++slot) {
            if (bodies[slot] == world_body) continue;
            for (int m = 0; m < 2; ++m)
                if (moved[m] == bodies[slot]) each(index, slot, m);
        }
    }
}

// The change of `contact`'s penetration when its body `slot` moves by `linear_change` and turns by
// `angular_change`: how far its point on that body travelled along its normal, the translation plus the
// rotation's linear effect at the point, (dtheta x q_rel) . n; body 0 moving along +n opens the contact, body 1
// closes it.
double penetration_change(const PreparedContact& contact, int slot, const Vec3& linear_change,
                          const Vec3& angular_change);

// The change of `contact`'s contact velocity when its body `slot` changes velocity by `velocity_change` and
// `rotation_change`: the change of its point's velocity (9.5), in contact coordinates, + for body 0, - for body 1.
Vec3 contact_velocity_change(const PreparedContact& contact, int slot, const Vec3& velocity_change,
                             const Vec3& rotation_change);

// Step 5 again on `contact`'s bookkeeping velocity, as the reference engine re-runs it on a partly resolved
// velocity: the restitution cut-off is judged again against the current closing speed; the restitution, the
// velocity from acceleration and the position bias are the prepared ones. Its desired delta v is the contact's
// (the bookkeeping keeps it so); the record of a visit takes the terms in full from here.
DesiredDeltaVelocity desired_again(const PreparedContact& contact, const VelocityRefinements& refinements);

// The book's loops: the bookkeeping of the `candidates` (ascending) sharing a body of `moved` (the resolved
// contact's bodies; body 1 may be the world) after that contact's move or impulse. Each update made is shown to
// `updated` (index, slot, m, its delta and the values before it): the recorder's records of them
// (record/visit_records.hpp), made by the same functions as the book's.
struct NotShown {
    void operator()(const auto&...) const {}
};
template <typename Updated = NotShown>
void update_penetrations(std::span<PreparedContact> contacts, std::span<const int> candidates,
                         const std::array<int, 2>& moved, const PositionChange& change, Updated updated = {}) {
    for_each_sharing(contacts, candidates, moved, [&](int index, int slot, int m) {
        PreparedContact& other = contacts[static_cast<std::size_t>(index)];
        const double delta = penetration_change(other, slot, *change.linear_change[m], *change.angular_change[m]);
        const double before = other.penetration;
        other.penetration += delta;
        updated(index, slot, m, delta, before);
    });
}
template <typename Updated = NotShown>
void update_contact_velocities(std::span<PreparedContact> contacts, std::span<const int> candidates,
                               const std::array<int, 2>& moved, const VelocityChange& change,
                               const VelocityRefinements& refinements, Updated updated = {}) {
    for_each_sharing(contacts, candidates, moved, [&](int index, int slot, int m) {
        PreparedContact& other = contacts[static_cast<std::size_t>(index)];
        const Vec3 delta = contact_velocity_change(other, slot, *change.velocity_change[m], *change.rotation_change[m]);
        const Vec3 before = other.contact_velocity;
        const double desired_before = other.desired_delta_velocity;
        other.contact_velocity += delta;
        other.desired_delta_velocity = desired_again(other, refinements).desired_delta_velocity;
        updated(index, slot, m, delta, before, desired_before);
    });
}
// The book's loops call them out of line, compiled once in bookkeeping.cpp: inlined into each loop, the book took 1.05
// of f60b8b3's CPU time on pyramid_20 (1.015 out of line).
extern template void update_penetrations(std::span<PreparedContact>, std::span<const int>, const std::array<int, 2>&,
                                         const PositionChange&, NotShown);
extern template void update_contact_velocities(std::span<PreparedContact>, std::span<const int>,
                                               const std::array<int, 2>&, const VelocityChange&,
                                               const VelocityRefinements&, NotShown);

}  // namespace impulse
