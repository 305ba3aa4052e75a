// Every derivation step on cases small enough to do on paper; the paper derivation is in each test's
// comment, and the test checks the engine's step functions against it value by value.

#include "derivation/impulse.hpp"
#include "derivation/position_change.hpp"
#include "derivation/velocity_change.hpp"
#include "methods/projections.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"
#include "support/impulse.hpp"

using namespace impulse;
using namespace impulse::test;

TEST_CASE("a 2 kg sphere meeting the ground at 5 m/s with c = 0.5 gets a 15 N s impulse and no spin") {
    // Sphere m = 2 kg, r = 0.5 m, centre p = (0, 0.49, 0), falling at (0, -5, 0); contact q = (0, -0.01, 0),
    // n = (0, 1, 0), c = 0.5.
    //  1. |n.x| = 0 is not > |n.y| = 1, so tangent 1 = normalise(X x n) = (0, 0, 1); tangent 2 = n x t1 = (1, 0, 0).
    //  2. q_rel = q - p = (0, -0.5, 0).
    //  3. u = q_rel x n = 0 (the impulse passes through the centre): no turning. d = m^-1 = 0.5.
    //  4. point velocity (0, -5, 0); in contact coordinates (n.v, t1.v, t2.v) = (-5, 0, 0).
    //  5. v_s = -5, |v_s| >= 0.25 so c stays 0.5: delta v = -(1 + 0.5)(-5) = 7.5 m/s.
    //  6. g = delta v / d = 7.5 / 0.5 = 15 N s, impulse_world = (0, 15, 0).
    //  7. velocity change = g m^-1 = (0, 7.5, 0): it leaves at (0, 2.5, 0) = -c v_s; rotation change 0.
    const std::vector<RigidBody> bodies{sphere(2.0, 0.5, {0, 0.49, 0}, {0, -5, 0})};
    const Contact c = contact(0, world_body, {0, -0.01, 0}, {0, 1, 0}, 0.01, 0.5);
    const ContactPreparation d = derivation(c, bodies, *preset("book"));
    const PerBody<MassProperties> mass = mass_of(d.bodies, bodies);

    CHECK(d.basis.seed == TangentSeed::world_x);
    CHECK_CLOSE(d.basis.tangent1(), Vec3(0, 0, 1));
    CHECK_CLOSE(d.basis.tangent2(), Vec3(1, 0, 0));
    CHECK_CLOSE(*d.relative_position[0], Vec3(0, -0.5, 0));
    CHECK_FALSE(d.relative_position[1].has_value());

    const UnitImpulseResponse& r = *d.unit_impulse_chain.bodies[0];
    CHECK_CLOSE(r.torque_per_unit_impulse, Vec3::Zero());
    CHECK_CLOSE(r.angular_component, 0.0);
    CHECK_CLOSE(r.linear_component, 0.5);
    CHECK_CLOSE(d.unit_impulse_chain.delta_velocity_per_unit_impulse, 0.5);

    CHECK_CLOSE(d.velocity_terms.contact_velocity, Vec3(-5, 0, 0));
    CHECK_FALSE(d.desired_terms.restitution_cutoff_applied);
    CHECK_CLOSE(d.desired_terms.restitution_used, 0.5);
    CHECK_CLOSE(d.desired_terms.desired_delta_velocity, 7.5);

    const Impulse g = calculate_impulse(d.basis, d.relative_position, mass, d.velocity_terms.contact_velocity, 7.5,
                                        d.unit_impulse_chain.delta_velocity_per_unit_impulse, c.friction);
    CHECK(g.impulse_model == ImpulseModel::frictionless);
    CHECK_CLOSE(g.impulse, Vec3(15, 0, 0));
    CHECK_CLOSE(g.impulse_world, Vec3(0, 15, 0));

    const VelocityChange change = velocity_change(g.impulse_world, d.relative_position, mass);
    CHECK_CLOSE(*change.velocity_change[0], Vec3(0, 7.5, 0));
    CHECK_CLOSE(*change.rotation_change[0], Vec3::Zero());
    CHECK_CLOSE(bodies[0].velocity + *change.velocity_change[0], Vec3(0, 2.5, 0));
}

TEST_CASE("a head-on contact is removed by a linear move only") {
    // Same sphere, 0.01 m deep: linear inertia m^-1 = 0.5, angular inertia 0, so the whole 0.01 m is
    // linear: linear_change = n * 0.01 and no rotation.
    const std::vector<RigidBody> bodies{sphere(2.0, 0.5, {0, 0.49, 0})};
    const PreparedContact p = prepared(contact(0, world_body, {0, -0.01, 0}, {0, 1, 0}, 0.01), bodies);
    const PositionResolution r = nonlinear_projection(p, mass_of(p.bodies, bodies), 0.01,
                                                      {AngularLimitPolicy::none, 0.0}, OrientationUpdate::first_order);
    CHECK_CLOSE(*r.inertia.linear_inertia[0], 0.5);
    CHECK_CLOSE(*r.inertia.angular_inertia[0], 0.0);
    CHECK_CLOSE(*r.moves.linear_move[0], 0.01);
    CHECK_CLOSE(*r.moves.angular_move[0], 0.0);
    CHECK_CLOSE(*r.change.linear_change[0], Vec3(0, 0.01, 0));
    CHECK_CLOSE(*r.change.angular_change[0], Vec3::Zero());
}

namespace {

// Box m = 3 kg, half-sizes (a, b, c) = (1, 0.5, 0.5) at p = (0, 0.5, 0), hitting the ground at its corner
// edge q = (1, 0, 0) with n = (0, 1, 0).
// I = diag(m(b^2 + c^2)/3, m(a^2 + c^2)/3, m(a^2 + b^2)/3) = diag(0.5, 1.25, 1.25), I^-1 = diag(2, 0.8, 0.8).
std::vector<RigidBody> off_centre_box() {
    return {box(3.0, {1, 0.5, 0.5}, {0, 0.5, 0}, {0, -2, 0})};
}

}  // namespace

TEST_CASE("an off-centre box contact gets an angular term of 0.8 beside the linear 1/3") {
    //  2. q_rel = (1, -0.5, 0).
    //  3. u = q_rel x n = (1, -0.5, 0) x (0, 1, 0) = (0, 0, 1); I^-1 u = (0, 0, 0.8);
    //     (I^-1 u) x q_rel = (0, 0, 0.8) x (1, -0.5, 0) = (0.4, 0.8, 0); its normal part 0.8.
    //     d = 0.8 + 1/3 = 17/15.
    //  5. v_s = -2, c = 0: delta v = 2.   6. g = 2 / (17/15) = 30/17.
    //  7. velocity change g/m n = (0, 10/17, 0); rotation change I^-1 (q_rel x g n) = (0, 0, 24/17).
    //  After: the point moves at v + w x q_rel = (0, -24/17, 0) + (12/17, 24/17, 0) = (12/17, 0, 0):
    //  no normal speed left (c = 0), and a sideways slide a frictionless contact does not touch.
    std::vector<RigidBody> bodies = off_centre_box();
    const Contact c = contact(0, world_body, {1, 0, 0}, {0, 1, 0});
    const ContactPreparation d = derivation(c, bodies);
    const PerBody<MassProperties> mass = mass_of(d.bodies, bodies);
    const UnitImpulseResponse& r = *d.unit_impulse_chain.bodies[0];
    CHECK_CLOSE(*d.relative_position[0], Vec3(1, -0.5, 0));
    CHECK_CLOSE(r.torque_per_unit_impulse, Vec3(0, 0, 1));
    CHECK_CLOSE(r.rotation_per_unit_impulse, Vec3(0, 0, 0.8));
    CHECK_CLOSE(r.point_velocity_per_unit_impulse, Vec3(0.4, 0.8, 0));
    CHECK_CLOSE(r.angular_component, 0.8);
    CHECK_CLOSE(r.linear_component, 1.0 / 3.0);
    CHECK_CLOSE(d.unit_impulse_chain.delta_velocity_per_unit_impulse, 17.0 / 15.0);
    CHECK_CLOSE(d.desired_terms.desired_delta_velocity, 2.0);

    const Impulse g = calculate_impulse(d.basis, d.relative_position, mass, d.velocity_terms.contact_velocity, 2.0,
                                        d.unit_impulse_chain.delta_velocity_per_unit_impulse, 0.0);
    CHECK_CLOSE(g.impulse, Vec3(30.0 / 17.0, 0, 0));
    const VelocityChange change = velocity_change(g.impulse_world, d.relative_position, mass);
    CHECK_CLOSE(*change.impulsive_torque[0], Vec3(0, 0, 30.0 / 17.0));
    CHECK_CLOSE(*change.velocity_change[0], Vec3(0, 10.0 / 17.0, 0));
    CHECK_CLOSE(*change.rotation_change[0], Vec3(0, 0, 24.0 / 17.0));

    bodies[0].velocity += *change.velocity_change[0];
    bodies[0].angular_velocity += *change.rotation_change[0];
    CHECK_CLOSE(point_velocity(bodies[0], c.point), Vec3(12.0 / 17.0, 0, 0));
}

TEST_CASE("the off-centre box's penetration splits 5:12 between moving and turning") {
    // Penetration 0.1: linear inertia 1/3, angular 0.8, total 17/15.
    // linear_move = 0.1 (1/3)/(17/15) = 0.1 * 5/17; angular_move = 0.1 * 0.8/(17/15) = 0.1 * 12/17.
    // Lever arm: q_rel without its normal part = (1, 0, 0), length 1, so the book's limit is 0.2: not reached.
    // angular_change = I^-1 (q_rel x n) angular_move / angular_inertia = (0, 0, 0.8) * (1.2/17) / 0.8 = (0, 0, 1.2/17).
    const std::vector<RigidBody> bodies = off_centre_box();
    const PreparedContact p = prepared(contact(0, world_body, {1, 0, 0}, {0, 1, 0}, 0.1), bodies);
    const PositionResolution r = nonlinear_projection(
        p, mass_of(p.bodies, bodies), 0.1, {AngularLimitPolicy::lever_arm, 0.2}, OrientationUpdate::first_order);
    CHECK_CLOSE(r.inertia.penetration_inertia, 17.0 / 15.0);
    CHECK_CLOSE(*r.moves.linear_move[0], 0.5 / 17.0);
    CHECK_CLOSE(*r.moves.angular_move[0], 1.2 / 17.0);
    CHECK_CLOSE(*r.angular_limit->maximum[0], 0.2);
    CHECK_FALSE(*r.angular_limit->applied[0]);
    CHECK_CLOSE(*r.change.linear_change[0], Vec3(0, 0.5 / 17.0, 0));
    CHECK_CLOSE(*r.change.angular_change[0], Vec3(0, 0, 1.2 / 17.0));

    // The text's fixed limit 0.05 cuts the angular move to 0.05 and gives the rest to the linear move:
    // 0.1 - 0.05 = 0.05.
    const PositionResolution fixed = nonlinear_projection(
        p, mass_of(p.bodies, bodies), 0.1, {AngularLimitPolicy::fixed, 0.05}, OrientationUpdate::first_order);
    CHECK(*fixed.angular_limit->applied[0]);
    CHECK_CLOSE(*fixed.moves.angular_move[0], 0.05);
    CHECK_CLOSE(*fixed.moves.linear_move[0], 0.05);
    CHECK_CLOSE(*fixed.angular_limit->before.angular_move[0], 1.2 / 17.0);
}

TEST_CASE("two spheres meeting obliquely exchange 2.31 N s along the normal and keep their slide") {
    // Body 0: 1 kg at (0.4, 0.3, 0) moving (-1, 0, 0); body 1: 3 kg at (-0.4, -0.3, 0) moving (1, 1, 0);
    // contact at the origin, n = (0.8, 0.6, 0), c = 0.4.
    //  1. |n.x| = 0.8 > |n.y| = 0.6: tangent 1 = normalise(Y x n) = normalise(0, 0, -0.8) = (0, 0, -1);
    //     tangent 2 = n x t1 = (-0.6, 0.8, 0). (The reference engine's tangent 2 would have x = 0 here.)
    //  2. q_rel0 = (-0.4, -0.3, 0) = -0.5 n, q_rel1 = (0.4, 0.3, 0) = 0.5 n: no torque on either.
    //  3. d = 1/1 + 1/3 = 4/3.
    //  4. v0 - v1 = (-2, -1, 0): contact velocity (n.(-2,-1,0), t1.., t2..) = (-2.2, 0, 0.4).
    //  5. delta v = -(1 + 0.4)(-2.2) = 3.08.   6. g = 3.08 / (4/3) = 2.31.
    //  7. body 0 gains 2.31 n = (1.848, 1.386, 0) -> (0.848, 1.386, 0);
    //     body 1 loses 2.31 n / 3 = (0.616, 0.462, 0) -> (0.384, 0.538, 0).
    //  Separating velocity after: n.(0.464, 0.848, 0) = 0.88 = 0.4 * 2.2; the slide 0.4 is untouched;
    //  momentum (2, 3, 0) before and after.
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0.4, 0.3, 0}, {-1, 0, 0}),
                                  sphere(3.0, 0.5, {-0.4, -0.3, 0}, {1, 1, 0})};
    const Contact c = contact(0, 1, Vec3::Zero(), {0.8, 0.6, 0}, 0.0, 0.4);
    const ContactPreparation d = derivation(c, bodies);
    const PerBody<MassProperties> mass = mass_of(d.bodies, bodies);
    CHECK(d.basis.seed == TangentSeed::world_y);
    CHECK_CLOSE(d.basis.tangent1(), Vec3(0, 0, -1));
    CHECK_CLOSE(d.basis.tangent2(), Vec3(-0.6, 0.8, 0));
    CHECK_CLOSE(*d.relative_position[0], Vec3(-0.4, -0.3, 0));
    CHECK_CLOSE(*d.relative_position[1], Vec3(0.4, 0.3, 0));
    CHECK_CLOSE(d.unit_impulse_chain.bodies[1]->linear_component, 1.0 / 3.0);
    CHECK_CLOSE(d.unit_impulse_chain.delta_velocity_per_unit_impulse, 4.0 / 3.0);
    CHECK_CLOSE(d.velocity_terms.contact_velocity, Vec3(-2.2, 0, 0.4));
    CHECK_CLOSE(d.desired_terms.desired_delta_velocity, 3.08);

    const Impulse g =
        calculate_impulse(d.basis, d.relative_position, mass, d.velocity_terms.contact_velocity, 3.08, 4.0 / 3.0, 0.0);
    CHECK_CLOSE(g.impulse, Vec3(2.31, 0, 0));
    const VelocityChange change = velocity_change(g.impulse_world, d.relative_position, mass);
    CHECK_CLOSE(*change.velocity_change[0], Vec3(1.848, 1.386, 0));
    CHECK_CLOSE(*change.velocity_change[1], Vec3(-0.616, -0.462, 0));
    for (int i = 0; i < 2; ++i) bodies[static_cast<std::size_t>(i)].velocity += *change.velocity_change[i];
    CHECK_CLOSE(bodies[0].velocity, Vec3(0.848, 1.386, 0));
    CHECK_CLOSE(bodies[1].velocity, Vec3(0.384, 0.538, 0));
    const Vec3 relative = to_contact(d.basis, bodies[0].velocity - bodies[1].velocity);
    CHECK_CLOSE(relative, Vec3(0.88, 0, 0.4));
}

TEST_CASE("slow contacts bounce with restitution 0 below the 0.25 m/s cut-off") {
    // v_s = -0.2: |v_s| < 0.25, so c_used = 0 and delta v = 0.2 (stop, do not bounce). With the cut-off off
    // the same contact asks for -(1 + 0.5)(-0.2) = 0.3.
    VelocityRefinements on{0.25, false, false};
    const DesiredDeltaVelocity slow = desired_delta_velocity(-0.2, 0.5, {0, 1, 0}, {}, 1.0 / 60.0, on);
    CHECK(slow.restitution_cutoff_applied);
    CHECK(slow.restitution_used == 0.0);
    CHECK_CLOSE(slow.desired_delta_velocity, 0.2);
    const DesiredDeltaVelocity off = desired_delta_velocity(-0.2, 0.5, {0, 1, 0}, {}, 1.0 / 60.0, {0.0, false, false});
    CHECK_FALSE(off.restitution_cutoff_applied);
    CHECK_CLOSE(off.desired_delta_velocity, 0.3);
    // Exactly at the cut-off the contact still bounces: the test is |v_s| < 0.25, as in the reference engine.
    const DesiredDeltaVelocity at = desired_delta_velocity(-0.25, 0.5, {0, 1, 0}, {}, 1.0 / 60.0, on);
    CHECK_FALSE(at.restitution_cutoff_applied);
    CHECK_CLOSE(at.desired_delta_velocity, 0.375);
}

TEST_CASE("the velocity last frame's gravity added is not bounced back") {
    // A box resting on the ground picked up g dt = 9.81/60 = 0.1635 m/s downwards in the last step:
    // v_s = -0.1635, velocity_from_acceleration = (a0 . n) dt = -0.1635. With c = 0.5 and no cut-off,
    // delta v = -v_s - c (v_s - v_acc) = 0.1635 - 0.5 * 0 = 0.1635: it stops without leaping.
    const double dt = 1.0 / 60.0;
    PerBody<BodyMotion> motion;
    motion[0] = BodyMotion{{0, -9.81 * dt, 0}, Vec3::Zero(), {0, -9.81, 0}};
    const DesiredDeltaVelocity d = desired_delta_velocity(-9.81 * dt, 0.5, {0, 1, 0}, motion, dt, {0.0, true, false});
    CHECK(d.velocity_from_acceleration_applied);
    CHECK_CLOSE(d.velocity_from_acceleration, -9.81 * dt);
    CHECK_CLOSE(d.desired_delta_velocity, 9.81 * dt);
}

TEST_CASE("last frame's sideways acceleration is added to the sliding velocity only") {
    // A body accelerating at (2, -9.81, 0) for dt = 0.1 on ground with n = (0, 1, 0): a dt = (0.2, -0.981, 0);
    // in contact coordinates (normal, t1 = z, t2 = x) = (-0.981, 0, 0.2); the normal part is dropped, so the
    // contact velocity gains (0, 0, 0.2) and its separating velocity is unchanged.
    PerBody<BodyMotion> motion;
    motion[0] = BodyMotion{Vec3::Zero(), Vec3::Zero(), {2, -9.81, 0}};
    PerBody<Vec3> q_rel;
    q_rel[0] = Vec3(0, -0.5, 0);
    const ContactVelocityTerms v = contact_velocity(basis({0, 1, 0}), q_rel, motion, 0.1, true);
    CHECK_CLOSE(*v.tangential_acceleration_velocity[0], Vec3(0, 0, 0.2));
    CHECK_CLOSE(v.contact_velocity, Vec3(0, 0, 0.2));
    const ContactVelocityTerms without = contact_velocity(basis({0, 1, 0}), q_rel, motion, 0.1, false);
    CHECK_FALSE(without.tangential_acceleration_velocity[0].has_value());
    CHECK_CLOSE(without.contact_velocity, Vec3::Zero());
}
