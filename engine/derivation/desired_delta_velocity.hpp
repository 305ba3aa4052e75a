#pragma once
// Step 5, `desired_delta_velocity`: the change of separating velocity the impulse must make.
// The chapter: v_s' = -c v_s, so delta v = -(1 + c) v_s. The reference engine adds two chapter-15
// refinements, each a named, recorded option here. Baumgarte stabilisation (settings `baumgarte`) adds a
// third term, the position bias: the separating speed that closes a share of the penetration in one frame.

#include "derivation/contact_velocity.hpp"
#include "math/types.hpp"

#include <array>

namespace impulse {

struct VelocityRefinements {
    // The reference engine's chapter-15 refinements as step 5 takes them; their defaults are the settings'
    // (ResolverSettings, whose velocity_refinements() builds this).
    double restitution_cutoff;        // m/s: closing slower bounces with restitution 0; 0 switches the cut-off off
    bool velocity_from_acceleration;  // remove last frame's acceleration's velocity from the bounce
    bool tangential_acceleration_velocity;  // add its tangential part to the contact velocity (step 4)

    bool operator==(const VelocityRefinements&) const = default;
};

struct DesiredDeltaVelocity {
    double separating_velocity;               // v_s = contact_velocity.x (negative = closing)
    double restitution;                       // c as given for the contact
    double restitution_cutoff;                // the cut-off speed in force (0 = off)
    bool restitution_cutoff_applied;          // |v_s| < cut-off, so the restitution used is 0
    double restitution_used;                  // c, or 0 when the cut-off applied
    bool velocity_from_acceleration_applied;  // the refinement is on
    double velocity_from_acceleration;        // (a0 - a1) . n x duration; 0 when off
    std::optional<double> position_bias;      // Baumgarte: beta max(penetration - slop, 0) / h; absent when off
    double desired_delta_velocity;            // -v_s - c_used (v_s - velocity_from_acceleration) + position_bias

    bool operator==(const DesiredDeltaVelocity&) const = default;
};

// `position_bias` is the Baumgarte term, given when it is on (it is fixed for the frame: the penetration as
// prepared), so every evaluation of step 5 (preparation, the bookkeeping's re-evaluations) includes it once.
DesiredDeltaVelocity desired_delta_velocity(double separating_velocity, double restitution, const Vec3& normal,
                                            const PerBody<BodyMotion>& motion, double duration,
                                            const VelocityRefinements& refinements,
                                            std::optional<double> position_bias = std::nullopt);

// (a0 - a1) . n x duration, the normal velocity last frame's acceleration built up; 0 with the refinement off.
double velocity_from_acceleration(const Vec3& normal, const PerBody<BodyMotion>& motion, double duration,
                                  const VelocityRefinements& refinements);
// The same from the two bodies' accelerations (body 1 null for the world).
double velocity_from_acceleration(const Vec3& normal, const std::array<const Vec3*, 2>& acceleration, double duration,
                                  const VelocityRefinements& refinements);

// Step 5 with that velocity already known. The bookkeeping re-runs step 5 after every impulse on a body of the
// contact, and the velocity from acceleration depends only on the motion when the contact was prepared, so it
// passes the prepared value.
DesiredDeltaVelocity desired_delta_velocity(double separating_velocity, double restitution,
                                            double velocity_from_acceleration, const VelocityRefinements& refinements,
                                            std::optional<double> position_bias = std::nullopt);

}  // namespace impulse
