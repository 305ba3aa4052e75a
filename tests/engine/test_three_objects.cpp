// The chapter's figure of three objects in the same collision (scenes/cases/three_objects.json): the same
// closing velocity and restitution give the same separating velocity at the contact, split differently
// between linear and angular motion.

#include "formats/scene_file.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"
#include "support/shipped.hpp"

using namespace impulse;
using namespace impulse::test;

namespace {

struct Figure {
    Scene c;
    Trace trace;
    std::vector<RigidBody> after;
};

Figure resolve_figure() {
    Figure f{shipped("cases/three_objects"), {}, {}};
    f.after = f.c.bodies;
    f.trace.scene = f.c;
    TraceRecorder recorder(f.trace);
    resolve_contacts(f.after, f.c.contacts, f.c.settings, recorder);
    return f;
}

// The share of the separating response that comes from turning: angular / (linear + angular) along n.
double rotation_share(const ContactPreparation& d) {
    const UnitImpulseResponse& r = *d.unit_impulse_chain.bodies[0];
    return r.angular_component / d.unit_impulse_chain.delta_velocity_per_unit_impulse;
}

}  // namespace

TEST_CASE("equal closing velocity and restitution give the same separating velocity at every contact") {
    const Figure f = resolve_figure();
    for (std::size_t i = 0; i < 3; ++i) {
        const ContactPreparation& d = f.trace.frames[0].contacts[i];
        const RigidBody& body = f.after[static_cast<std::size_t>(d.bodies[0])];
        CHECK_CLOSE(point_velocity(body, d.point).dot(d.normal), 0.5 * 2.0);  // -c v_s = 0.5 * 2 m/s
    }
}

TEST_CASE("the share of rotation grows as the moment of inertia shrinks") {
    // ruler and dumbbell: same mass and lever arm, inertia 0.02 against 5 about Z; the light object is
    // almost head on.
    const Figure f = resolve_figure();
    const auto& contacts = f.trace.frames[0].contacts;
    const double light = rotation_share(contacts[0]), ruler = rotation_share(contacts[1]),
                 dumbbell = rotation_share(contacts[2]);
    CHECK(light < 0.1);
    CHECK(dumbbell < ruler);
    CHECK(ruler > 0.9);
    CHECK(std::abs(f.after[1].angular_velocity.z()) > 10 * std::abs(f.after[2].angular_velocity.z()));
}

TEST_CASE("the heavy small-inertia ruler keeps moving down while its contact point bounces up") {
    const Figure f = resolve_figure();
    const RigidBody& ruler = f.after[1];
    CHECK(ruler.velocity.y() < 0.0);
    CHECK(point_velocity(ruler, f.c.contacts[1].point).y() > 0.0);
    // The light object and the large-inertia dumbbell bounce up as a whole.
    CHECK(f.after[0].velocity.y() > 0.0);
    CHECK(f.after[2].velocity.y() > 0.0);
}
