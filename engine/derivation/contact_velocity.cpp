#include "derivation/contact_velocity.hpp"

namespace impulse {

ContactVelocityTerms contact_velocity(const Basis& basis, const PerBody<Vec3>& relative_position,
                                      const PerBody<BodyMotion>& motion, double duration,
                                      bool tangential_acceleration_velocity) {
    ContactVelocityTerms v;
    v.contact_velocity = Vec3::Zero();
    for (int i = 0; i < 2; ++i) {
        if (!relative_position[i]) continue;
        const BodyContactVelocity body = body_contact_velocity(basis.contact_to_world, *relative_position[i],
                                                               *motion[i], duration, tangential_acceleration_velocity);
        v.point_velocity[i] = body.point_velocity;
        if (tangential_acceleration_velocity)
            v.tangential_acceleration_velocity[i] = body.tangential_acceleration_velocity;
        v.contact_velocity += body_sign(i) * body.local;
    }
    return v;
}

}  // namespace impulse
