// The reference engine's chapter-15 friction impulse: the 3x3 solve in contact coordinates and the cone.

#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"
#include "support/impulse.hpp"

using namespace impulse;
using namespace impulse::test;

namespace {

// Sphere m = 1 kg, r = 0.5 m at (0, 0.5, 0), sliding at 1 m/s along x while landing at 2 m/s; contact at the
// origin, n = (0, 1, 0), c = 0.
// K (world) = m^-1 1 - [r]x I^-1 [r]x with r = (0, -0.5, 0), I^-1 = 10:
//   -[r]x [r]x = |r|^2 1 - r r^T = diag(0.25, 0, 0.25), so K = diag(1 + 2.5, 1, 1 + 2.5) = diag(3.5, 1, 3.5).
// Basis n = (0, 1, 0), t1 = (0, 0, 1), t2 = (1, 0, 0): K_contact = diag(K_yy, K_zz, K_xx) = diag(1, 3.5, 3.5).
// contact velocity (n.v, t1.v, t2.v) = (-2, 0, 1); target (2, -0, -1);
// static impulse K^-1 target = (2, 0, -1/3.5) = (2, 0, -0.285714...).
struct LandingSphere {
    std::vector<RigidBody> bodies{sphere(1.0, 0.5, {0, 0.5, 0}, {1, -2, 0})};
    Contact c = contact(0, world_body, Vec3::Zero(), {0, 1, 0});
    ContactPreparation d = derivation(c, bodies);
    PerBody<MassProperties> mass = mass_of(d.bodies, bodies);

    Impulse impulse(double friction) const {
        return calculate_impulse(d.basis, d.relative_position, mass, d.velocity_terms.contact_velocity, 2.0,
                                 d.unit_impulse_chain.delta_velocity_per_unit_impulse, friction);
    }
};

}  // namespace

TEST_CASE("inside the friction cone the contact stops sliding: the sphere rolls") {
    // mu = 1: tangential impulse 0.2857 <= mu g_n = 2, so the static impulse applies. After it the sphere
    // moves at (1 - 0.2857, 0, 0) and spins at I^-1 (r x g) = (0, 0, -1.42857): its contact point is at rest.
    LandingSphere s;
    const Impulse g = s.impulse(1.0);
    REQUIRE(g.friction_solve.has_value());
    CHECK(g.impulse_model == ImpulseModel::static_friction);
    CHECK_CLOSE(g.friction_solve->delta_velocity_matrix, Vec3(1, 3.5, 3.5).asDiagonal().toDenseMatrix());
    CHECK_CLOSE(g.friction_solve->target_delta_velocity, Vec3(2, 0, -1));
    CHECK_CLOSE(g.friction_solve->static_impulse, Vec3(2, 0, -1 / 3.5));
    CHECK_CLOSE(g.friction_solve->tangential_impulse, 1 / 3.5);
    CHECK_CLOSE(g.friction_solve->cone_limit, 2.0);
    CHECK_CLOSE(g.impulse_world, Vec3(-1 / 3.5, 2, 0));

    const VelocityChange change = velocity_change(g.impulse_world, s.d.relative_position, s.mass);
    RigidBody after = s.bodies[0];
    after.velocity += *change.velocity_change[0];
    after.angular_velocity += *change.rotation_change[0];
    CHECK_CLOSE(after.angular_velocity, Vec3(0, 0, -10 / 7.0));
    CHECK_CLOSE(point_velocity(after, s.c.point), Vec3::Zero());
}

TEST_CASE("outside the friction cone the tangential impulse is cut back onto the cone") {
    // mu = 0.1: 0.2857 > 0.1 * 2, so the contact slides. The kept direction is the static one, (0, -1) in
    // (t1, t2); the normal response K00 + mu (K01 * 0 + K02 * -1) = 1, so g_n = 2 / 1 = 2 and the tangential
    // impulse is mu g_n = 0.2 along it: impulse (2, 0, -0.2), world (-0.2, 2, 0).
    LandingSphere s;
    const Impulse g = s.impulse(0.1);
    CHECK(g.impulse_model == ImpulseModel::sliding_friction);
    CHECK_CLOSE(Vec3(0, g.friction_solve->sliding_direction->x(), g.friction_solve->sliding_direction->y()),
                Vec3(0, 0, -1));
    CHECK_CLOSE(*g.friction_solve->sliding_normal_response, 1.0);
    CHECK_CLOSE(g.impulse, Vec3(2, 0, -0.2));
    CHECK_CLOSE(g.impulse_world, Vec3(-0.2, 2, 0));

    const VelocityChange change = velocity_change(g.impulse_world, s.d.relative_position, s.mass);
    RigidBody after = s.bodies[0];
    after.velocity += *change.velocity_change[0];
    after.angular_velocity += *change.rotation_change[0];
    const Vec3 slip = point_velocity(after, s.c.point);
    CHECK_CLOSE(slip.y(), 0.0);  // the normal target is still met exactly
    CHECK(slip.x() > 0.0);       // still sliding forwards, more slowly
}

TEST_CASE("a contact with friction exactly zero uses the frictionless impulse") {
    LandingSphere s;
    const Impulse g = s.impulse(0.0);
    CHECK(g.impulse_model == ImpulseModel::frictionless);
    CHECK_FALSE(g.friction_solve.has_value());
    CHECK_CLOSE(g.impulse, Vec3(2.0 / s.d.unit_impulse_chain.delta_velocity_per_unit_impulse, 0, 0));
}
