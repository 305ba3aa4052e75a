// Physical properties over random contacts (1000+ each, rapidcheck, fixed seeds; shrinking on failure).
// Every check measures the bodies themselves after the impulse or move, not the resolver's own
// bookkeeping, so a wrong sign anywhere in the chain shows up.

#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "methods/projections.hpp"
#include "support/property.hpp"
#include "support/impulse.hpp"
#include "support/random_contacts.hpp"

using namespace impulse;
using namespace impulse::test;

namespace {

// The closing contact's impulse applied to its bodies; returns the bodies after.
struct Outcome {
    std::vector<RigidBody> before;
    std::vector<RigidBody> after;
    ContactPreparation prepared;
    Impulse impulse;
};

Outcome apply_impulse(const RandomContact& r) {
    Outcome o{r.bodies, r.bodies, derivation(r.contact, r.bodies), {}};
    const ContactPreparation& d = o.prepared;
    const PerBody<MassProperties> mass = mass_of(d.bodies, r.bodies);
    o.impulse = calculate_impulse(d.basis, d.relative_position, mass, d.velocity_terms.contact_velocity,
                                  d.desired_terms.desired_delta_velocity,
                                  d.unit_impulse_chain.delta_velocity_per_unit_impulse, r.contact.friction);
    const VelocityChange change = velocity_change(o.impulse.impulse_world, d.relative_position, mass);
    for (int i = 0; i < 2; ++i) {
        if (d.bodies[i] == world_body) continue;
        RigidBody& b = o.after[static_cast<std::size_t>(d.bodies[i])];
        b.velocity += *change.velocity_change[i];
        b.angular_velocity += *change.rotation_change[i];
    }
    return o;
}

// Relative velocity of the contact points (body 0 minus body 1), world, measured on the bodies.
Vec3 relative_point_velocity(const std::vector<RigidBody>& bodies, const Contact& c) {
    Vec3 v = point_velocity(bodies[0], c.point);
    if (c.bodies[1] != world_body) v -= point_velocity(bodies[1], c.point);
    return v;
}

// Skip contacts that are not closing by a clear margin: there is nothing to resolve.
void require_closing(const RandomContact& r) {
    RC_PRE(relative_point_velocity(r.bodies, r.contact).dot(r.contact.normal) < -0.01);
}

Mat3 world_inertia(const RigidBody& b) {
    return world_inverse_inertia(b).inverse();
}

}  // namespace

TEST_CASE("after one frictionless impulse the separating velocity is -c times the closing one") {
    check_property("separating velocity", [] {
        const RandomContact r = any_contact();
        require_closing(r);
        const Outcome o = apply_impulse(r);
        const double closing = relative_point_velocity(o.before, r.contact).dot(r.contact.normal);
        const double separating = relative_point_velocity(o.after, r.contact).dot(r.contact.normal);
        RC_ASSERT(std::abs(separating - (-r.contact.restitution * closing)) <= 1e-9 * std::abs(closing));
    });
}

TEST_CASE("a two-body impulse conserves linear momentum and angular momentum about a fixed point") {
    check_property("momentum", [] {
        const RandomContact r = any_contact(false);
        require_closing(r);
        const Vec3 origin = any_vector(3.0);
        const Outcome o = apply_impulse(r);
        const auto momenta = [&origin](const std::vector<RigidBody>& bodies) {
            Vec3 linear = Vec3::Zero(), angular = Vec3::Zero();
            for (const RigidBody& b : bodies) {
                const Vec3 p = b.velocity / b.inverse_mass;
                linear += p;
                angular += (b.position - origin).cross(p) + world_inertia(b) * b.angular_velocity;
            }
            return std::pair{linear, angular};
        };
        const auto [linear_before, angular_before] = momenta(o.before);
        const auto [linear_after, angular_after] = momenta(o.after);
        const double scale = 1.0 + o.impulse.impulse_world.norm() * 5.0;
        RC_ASSERT((linear_after - linear_before).norm() <= 1e-9 * scale);
        RC_ASSERT((angular_after - angular_before).norm() <= 1e-9 * scale);
    });
}

TEST_CASE("a frictionless impulse never raises the kinetic energy for c <= 1") {
    // Delta KE = (c^2 - 1) v_s^2 / (2 d) <= 0 for the impulse along the normal.
    check_property("kinetic energy", [] {
        const RandomContact r = any_contact();
        require_closing(r);
        const Outcome o = apply_impulse(r);
        double before = 0.0, after = 0.0;
        for (std::size_t i = 0; i < o.before.size(); ++i) {
            before += kinetic_energy(o.before[i]);
            after += kinetic_energy(o.after[i]);
        }
        RC_ASSERT(after <= before * (1.0 + 1e-12) + 1e-12);
    });
}

TEST_CASE("with friction the slip stops inside the cone and the impulse lies on the cone outside it") {
    int stuck = 0, slid = 0;
    check_property("friction cone", [&stuck, &slid] {
        RandomContact r = any_contact();
        r.contact.friction = *in_range(0.05, 1.5);
        require_closing(r);
        const Outcome o = apply_impulse(r);
        const ContactPreparation& d = o.prepared;
        const Vec3 after = to_contact(d.basis, relative_point_velocity(o.after, r.contact));
        const double closing = -o.prepared.velocity_terms.contact_velocity.x();
        // Either way the normal velocity reaches its target: -c times the closing speed.
        if (o.impulse.impulse_model != ImpulseModel::frictionless)
            RC_ASSERT(std::abs(after.x() - r.contact.restitution * closing) <= 1e-9 * (1.0 + closing));
        const Vec3& g = o.impulse.impulse;
        const double scale = 1.0 + o.prepared.velocity_terms.contact_velocity.norm();
        switch (o.impulse.impulse_model) {
            case ImpulseModel::static_friction:
                ++stuck;
                RC_ASSERT(std::hypot(after.y(), after.z()) <= 1e-9 * scale);
                RC_ASSERT(std::hypot(g.y(), g.z()) <= r.contact.friction * g.x() * (1 + 1e-12));
                break;
            case ImpulseModel::sliding_friction:
                ++slid;
                RC_ASSERT(std::abs(std::hypot(g.y(), g.z()) - r.contact.friction * g.x()) <= 1e-9 * std::abs(g.x()));
                break;
            case ImpulseModel::frictionless:
                // Only where sliding along the cone could not separate the contact at all.
                RC_ASSERT(o.impulse.friction_solve->sliding_normal_response.has_value());
                RC_ASSERT(*o.impulse.friction_solve->sliding_normal_response <= 0.0);
                break;
        }
    });
    // Both regimes must actually have been exercised.
    CHECK(stuck > 100);
    CHECK(slid > 100);
}

TEST_CASE("after a nonlinear projection the linearised penetration of that contact is zero") {
    check_property("projection removes penetration", [] {
        const RandomContact r = any_contact();
        const PreparedContact p = prepared(r.contact, r.bodies);
        const auto policy = *rc::gen::element(AngularLimitPolicy::none, AngularLimitPolicy::fixed,
                                              AngularLimitPolicy::lever_arm, AngularLimitPolicy::angle);
        const PositionResolution res =
            nonlinear_projection(p, mass_of(p.bodies, r.bodies), r.contact.penetration,
                                 {policy, default_angular_limit_factor(policy)}, OrientationUpdate::first_order);
        double removed = 0.0;
        for (int i = 0; i < 2; ++i) {
            if (!res.change.linear_change[i]) continue;
            const Vec3 move =
                *res.change.linear_change[i] + res.change.angular_change[i]->cross(p.relative_position[i]);
            removed += body_sign(i) * move.dot(r.contact.normal);
        }
        RC_ASSERT(std::abs(removed - r.contact.penetration) <= 1e-12 * (1.0 + r.contact.penetration));
    });
}

TEST_CASE("the angular limit keeps the total move of each body that can translate, and only changes its split") {
    check_property("angular limit keeps the total", [] {
        const RandomContact r = any_contact();
        const ContactPreparation d = derivation(r.contact, r.bodies);
        const PenetrationInertia inertia = penetration_inertia(d.unit_impulse_chain);
        const MoveSplit unlimited = move_split(r.contact.penetration, inertia);
        const auto policy =
            *rc::gen::element(AngularLimitPolicy::fixed, AngularLimitPolicy::lever_arm, AngularLimitPolicy::angle);
        const double factor = policy == AngularLimitPolicy::angle ? *in_range(1.0, 90.0) : *in_range(0.0, 0.5);
        const LimitedMoves limited = angular_limit(unlimited, {policy, factor}, r.contact.normal, d.relative_position,
                                                   d.unit_impulse_chain, OrientationUpdate::first_order);
        const MoveSplit& moves = limited.moves;
        const AngularLimit& limit = limited.limit;
        for (int i = 0; i < 2; ++i) {
            if (!moves.linear_move[i]) continue;
            const double total_before = *unlimited.linear_move[i] + *unlimited.angular_move[i];
            RC_ASSERT(std::abs(*moves.linear_move[i] + *moves.angular_move[i] - total_before) <=
                      1e-15 + 1e-12 * std::abs(total_before));
            RC_ASSERT(std::abs(*moves.angular_move[i]) <= *limit.maximum[i] * (1 + 1e-12) + 1e-15);
        }
    });
}
