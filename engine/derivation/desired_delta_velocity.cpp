#include "derivation/desired_delta_velocity.hpp"

#include "math/products.hpp"

#include <cmath>

namespace impulse {

DesiredDeltaVelocity desired_delta_velocity(double separating_velocity, double restitution, const Vec3& normal,
                                            const PerBody<BodyMotion>& motion, double duration,
                                            const VelocityRefinements& refinements,
                                            std::optional<double> position_bias) {
    return desired_delta_velocity(separating_velocity, restitution,
                                  velocity_from_acceleration(normal, motion, duration, refinements), refinements,
                                  position_bias);
}

double velocity_from_acceleration(const Vec3& normal, const PerBody<BodyMotion>& motion, double duration,
                                  const VelocityRefinements& refinements) {
    const auto of = [&](int i) { return motion[i] ? &motion[i]->last_frame_acceleration : nullptr; };
    return velocity_from_acceleration(normal, {of(0), of(1)}, duration, refinements);
}

double velocity_from_acceleration(const Vec3& normal, const std::array<const Vec3*, 2>& acceleration, double duration,
                                  const VelocityRefinements& refinements) {
    double velocity = 0.0;
    if (refinements.velocity_from_acceleration) {
        for (int i = 0; i < 2; ++i)
            if (acceleration[i]) velocity += body_sign(i) * dot(*acceleration[i] * duration, normal);
    }
    return velocity;
}

DesiredDeltaVelocity desired_delta_velocity(double separating_velocity, double restitution,
                                            double velocity_from_acceleration, const VelocityRefinements& refinements,
                                            std::optional<double> position_bias) {
    DesiredDeltaVelocity d;
    d.separating_velocity = separating_velocity;
    d.restitution = restitution;
    d.restitution_cutoff = refinements.restitution_cutoff;
    d.restitution_cutoff_applied = std::abs(separating_velocity) < refinements.restitution_cutoff;
    d.restitution_used = d.restitution_cutoff_applied ? 0.0 : restitution;
    d.velocity_from_acceleration_applied = refinements.velocity_from_acceleration;
    d.velocity_from_acceleration = velocity_from_acceleration;
    // v_s' = -c v_s  =>  delta v = -v_s - c v_s = -(1 + c) v_s; the velocity gravity added during the
    // last step is not bounced back, so a resting contact asks only to stop, not to leap.
    d.desired_delta_velocity =
        -separating_velocity - d.restitution_used * (separating_velocity - d.velocity_from_acceleration);
    // Baumgarte: also separate at the bias speed, so the bodies drift apart over the next frames.
    d.position_bias = position_bias;
    if (position_bias) d.desired_delta_velocity += *position_bias;
    return d;
}

}  // namespace impulse
