#pragma once
// The three interpenetration moves of the chapter (section 14.3): each takes one prepared contact and returns
// what it computed, a PositionResolution (record/position_resolution.hpp). The position phase
// (methods/position_phase.cpp) picks one by the settings' position method.

#include "preparation/prepared_contact.hpp"
#include "record/position_resolution.hpp"

namespace impulse {

// Each takes the contact's bodies' mass as the frame prepared it (mass_of).
PositionResolution linear_projection(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                     double amount);

PositionResolution nonlinear_projection(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                        double amount, const AngularLimitSettings& limit,
                                        OrientationUpdate orientation_update);

// Needs the bodies' current motion: in the book's order (positions first) that is the motion which made
// the penetration; after the velocity phase the contact no longer closes and everything is projected.
PositionResolution velocity_based(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                  const PerBody<BodyMotion>& motion, double time_left,
                                  const AngularLimitSettings& limit, OrientationUpdate orientation_update);

}  // namespace impulse
