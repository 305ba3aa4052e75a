#pragma once
// After a move or an impulse, the book does not re-derive any geometry: it updates the penetration (or the
// contact velocity and desired delta v) of every contact that shares a moved body by the linearised
// formulas, using the relative positions fixed when the contacts were prepared.

#include "derivation/position_change.hpp"
#include "derivation/velocity_change.hpp"
#include "record/iteration_records.hpp"
#include "preparation/prepared_contact.hpp"

#include <array>
#include <span>
#include <vector>

namespace impulse {

// `moved` holds the resolved contact's bodies (body 1 may be the world, which never moves). Appends one
// record per (contact, moved body) pair to `log` when it is given. `candidates` (ascending) are the contacts
// to look at; each is updated only where it shares a moved body. Without them, every contact is looked at.
void update_penetrations(std::vector<PreparedContact>& contacts, std::span<const int> candidates,
                         const std::array<int, 2>& moved, const PositionChange& change,
                         std::vector<PenetrationUpdate>* log);
void update_penetrations(std::vector<PreparedContact>& contacts, const std::array<int, 2>& moved,
                         const PositionChange& change, std::vector<PenetrationUpdate>* log);

void update_contact_velocities(std::vector<PreparedContact>& contacts, std::span<const int> candidates,
                               const std::array<int, 2>& moved, const VelocityChange& change,
                               const ResolverSettings& settings, std::vector<VelocityUpdate>* log);
void update_contact_velocities(std::vector<PreparedContact>& contacts, const std::array<int, 2>& moved,
                               const VelocityChange& change, const ResolverSettings& settings,
                               std::vector<VelocityUpdate>* log);

}  // namespace impulse
