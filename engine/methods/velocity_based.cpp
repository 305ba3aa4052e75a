// Velocity-based resolution: "move the bodies back to the point of first collision ... we can move these
// two points back along the paths they followed until they no longer overlap in the direction of the
// contact normal". Each body goes back by the same time t along its straight-line and rotational path;
// t is the penetration divided by the closing speed of the contact points, and never more than what is left
// of the frame for either body (a body on several contacts cannot go back before the frame began, however
// many of them rewind it). What the paths cannot explain (a contact that was not closing, or one deeper than
// the travel left) is removed by nonlinear projection, recorded beside the rewind. The angular limit applies
// to that projection only: the rewind's turn is the body's own motion undone, so with the `angle` policy
// the whole turn can exceed the limit by theta-dot t.

#include "methods/projections.hpp"
#include "methods/phases.hpp"

#include <algorithm>

namespace impulse {

PositionResolution velocity_based(const PreparedContact& contact, const PerBody<MassProperties>& mass,
                                  const PerBody<BodyMotion>& motion, double time_left,
                                  const AngularLimitSettings& limit, OrientationUpdate orientation_update) {
    // Only the motion a body can undo counts: an immovable body stays where it is even if it has a speed.
    PerBody<Vec3> path_velocity, path_rotation;
    Rewind rewind{};
    double separating = 0.0;
    for (int i = 0; i < 2; ++i) {
        if (!mass[i]) continue;
        const bool translates = mass[i]->inverse_mass > 0.0;
        const bool turns = !mass[i]->inverse_inertia_world.isZero(0.0);
        path_velocity[i] = translates ? motion[i]->velocity : Vec3::Zero();
        path_rotation[i] = turns ? motion[i]->angular_velocity : Vec3::Zero();
        const Vec3 point_velocity = path_rotation[i]->cross(contact.relative_position[i]) + *path_velocity[i];
        separating += body_sign(i) * point_velocity.dot(contact.basis.normal());
    }
    rewind.closing_velocity = -separating;
    rewind.time_limit = std::max(time_left, 0.0);
    rewind.time = rewind.closing_velocity > 0.0
                      ? std::min(contact.penetration / rewind.closing_velocity, rewind.time_limit)
                      : 0.0;
    rewind.removed_penetration = rewind.closing_velocity * rewind.time;

    // The rest, if any, by nonlinear projection; each body's move is the rewind's and the projection's.
    PositionResolution r = nonlinear_projection(contact, mass, contact.penetration - rewind.removed_penetration, limit,
                                                orientation_update);
    r.method = PositionMethod::velocity_based;
    for (int i = 0; i < 2; ++i) {
        if (!mass[i]) continue;
        rewind.linear_change[i] = -*path_velocity[i] * rewind.time;
        rewind.angular_change[i] = -*path_rotation[i] * rewind.time;
        *r.change.linear_change[i] += *rewind.linear_change[i];
        *r.change.angular_change[i] += *rewind.angular_change[i];
    }
    r.rewind = rewind;
    return r;
}

namespace {

// The bodies' motion as it is now, and the time left of the frame for the body that has used most of it.
PositionResolution project(const PreparedContact& contact, double /*amount*/, const PositionPhaseState& state,
                           const FrameContext& frame) {
    const ResolverSettings& settings = frame.settings;
    PerBody<BodyMotion> motion;
    double time_left = settings.duration;
    for (int i = 0; i < 2; ++i) {
        const int id = contact.bodies[i];
        if (id == world_body) continue;
        const RigidBody& body = frame.bodies[static_cast<std::size_t>(id)];
        motion[i] = BodyMotion{body.velocity, body.angular_velocity, body.last_frame_acceleration};
        time_left = std::min(time_left, settings.duration - state.rewound_time[static_cast<std::size_t>(id)]);
    }
    return velocity_based(contact, mass_of(contact, frame.mass), motion, time_left, settings.angular_limit,
                          settings.orientation_update);
}

}  // namespace

PhaseOutcome velocity_based_positions(FrameContext& frame) {
    return worst_first_positions(frame, project, nullptr);
}

}  // namespace impulse
