#include "derivation/contact_velocity.hpp"

namespace impulse {

ContactVelocityTerms contact_velocity(const Basis& basis, const PerBody<Vec3>& relative_position,
                                      const PerBody<BodyMotion>& motion, double duration,
                                      bool tangential_acceleration_velocity) {
    ContactVelocityTerms v;
    v.contact_velocity = Vec3::Zero();
    for (int i = 0; i < 2; ++i) {
        if (!relative_position[i]) continue;
        const BodyMotion& m = *motion[i];
        v.point_velocity[i] = point_velocity(m.velocity, m.angular_velocity, *relative_position[i]);  // (9.5)
        Vec3 local = to_contact(basis, *v.point_velocity[i]);
        if (tangential_acceleration_velocity) {
            Vec3 from_acceleration = to_contact(basis, m.last_frame_acceleration * duration);
            from_acceleration.x() = 0.0;  // only the sliding part; the normal part is for restitution (step 5)
            v.tangential_acceleration_velocity[i] = from_acceleration;
            local += from_acceleration;
        }
        v.contact_velocity += body_sign(i) * local;
    }
    return v;
}

}  // namespace impulse
