// Contact recycling (memory/contact_recycling.hpp): a pair's contacts kept from frame to frame while it moves
// little, their penetration found again from each body's anchor; forgotten when the pair moves or turns past the
// settings; off unless a scene or preset switches it on; and cleared with the world.

#include "formats/settings_json.hpp"
#include "methods/soft_step.hpp"
#include "math/rotation.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/contact_record.hpp"
#include "record/trace_recorder.hpp"
#include "support/shipped.hpp"
#include "support/simulate.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using namespace impulse;

namespace {

// A frame's detection with `recycling` (which keeps what it finds for the next call).
Detection detect(const Scene& scene, const std::vector<RigidBody>& bodies, ContactRecycling& recycling) {
    Detection detection;
    detect_contacts(scene, bodies, detection, nullptr, &recycling);
    return detection;
}

Quat turned_about_z(double degrees) {
    return Quat(Eigen::AngleAxisd(degrees * std::numbers::pi / 180.0, Vec3::UnitZ()));
}

}  // namespace

TEST_CASE("a resting box's contacts are kept across frames with the same features, normal and anchors") {
    const Scene scene = test::shipped_under("box_resting", "soft_step_recycled");
    REQUIRE(scene.settings.recycling.distance == 0.05);
    std::vector<RigidBody> bodies = scene.bodies;
    ContactRecycling recycling;
    const Detection first = detect(scene, bodies, recycling);
    CHECK(first.pairs_recycled == 0);  // nothing kept yet: the ground test ran
    CHECK(first.contacts == detect_contacts(scene, bodies).contacts);
    REQUIRE(first.contacts.size() == 4);
    CHECK(recycling.kept_pairs() == 1);

    // Lifted 1 mm and moved 2 mm along x, unturned: every anchor moved with the box, so each kept point is the old
    // one moved by d, and its penetration is p - n . d = p - 0.001 (n = +y, the ground's).
    const Vec3 d(0.002, 0.001, 0.0);
    bodies[0].position += d;
    const Detection second = detect(scene, bodies, recycling);
    CHECK(second.pairs_recycled == 1);
    REQUIRE(second.contacts.size() == 4);
    for (std::size_t k = 0; k < 4; ++k) {
        CAPTURE(k);
        const Contact& was = first.contacts[k];
        const Contact& is = second.contacts[k];
        CHECK(is.origin == was.origin);
        CHECK(is.normal == was.normal);
        CHECK(is.bodies == was.bodies);
        CHECK(is.friction == was.friction);
        CHECK((is.point - (was.point + d)).norm() < 1e-15);
        CHECK(is.penetration == doctest::Approx(was.penetration - 0.001).epsilon(1e-12));
        CHECK_FALSE(is.body1_point);  // the ground's anchor is the point itself
    }
    // A fresh test of the lifted box finds no contact at all (it is 1 mm above the ground): the kept ones are
    // speculative now, p = -1 mm.
    CHECK(detect_contacts(scene, bodies).contacts.empty());

    // Turned 3 degrees about z (within Box3D's 10) about its centre: the solver still pushes at the anchors as
    // detected, x + a, but the penetration follows the turned anchors, p = p0 - n . ((x + R a) - q0).
    bodies[0].orientation = turned_about_z(3.0);
    const Detection third = detect(scene, bodies, recycling);
    CHECK(third.pairs_recycled == 1);
    REQUIRE(third.contacts.size() == 4);
    const Mat3 turn = bodies[0].orientation.toRotationMatrix();
    for (std::size_t k = 0; k < 4; ++k) {
        CAPTURE(k);
        const Contact& was = first.contacts[k];
        const Vec3 anchor = was.point - scene.bodies[0].position;
        CHECK((third.contacts[k].point - (bodies[0].position + anchor)).norm() < 1e-15);
        const double lifted = (bodies[0].position + turn * anchor - was.point).y();
        CHECK(third.contacts[k].penetration == doctest::Approx(was.penetration - lifted).epsilon(1e-12));
        CHECK(third.contacts[k].origin == was.origin);
    }
}

TEST_CASE("a recycled pair of boxes pushes each body at its own anchor") {
    // Two boxes of stack_3 touching face to face; the upper one moved 1 cm sideways: its anchors went with it, the
    // lower box's stayed, so preparation takes a different point for each body, each at its own anchor.
    const Scene scene = test::shipped_under("stack_3", "soft_step_recycled");
    std::vector<RigidBody> bodies = scene.bodies;
    ContactRecycling recycling;
    const Detection first = detect(scene, bodies, recycling);
    std::size_t pair_contact = first.contacts.size();
    for (std::size_t k = 0; k < first.contacts.size(); ++k)
        if (first.contacts[k].bodies[1] != world_body) {
            pair_contact = k;
            break;
        }
    REQUIRE(pair_contact < first.contacts.size());
    const Contact& was = first.contacts[pair_contact];
    const int upper = was.bodies[0];
    const Vec3 d(0.01, 0.0, 0.0);
    bodies[static_cast<std::size_t>(upper)].position += d;
    const Detection second = detect(scene, bodies, recycling);
    CHECK(second.pairs_recycled > 0);
    const Contact* is = nullptr;
    for (const Contact& c : second.contacts)
        if (c.bodies == was.bodies && c.origin == was.origin) is = &c;
    REQUIRE(is != nullptr);
    REQUIRE(is->body1_point);
    CHECK((is->point - (was.point + d)).norm() < 1e-15);
    CHECK((*is->body1_point - was.point).norm() < 1e-15);
    CHECK(is->penetration == doctest::Approx(was.penetration - was.normal.dot(d)).epsilon(1e-12));

    const std::vector<MassProperties> mass = mass_properties(bodies);
    std::pmr::vector<PreparedContact> one;
    prepare_contacts({&*is, 1}, bodies, mass, scene.settings, one);
    const PreparedContact& prepared = one.front();
    for (int i = 0; i < 2; ++i) {
        const RigidBody& body = bodies[static_cast<std::size_t>(is->bodies[i])];
        CHECK(prepared.relative_position[i] == touch_point(*is, i) - body.position);
    }
    CHECK(prepared.relative_position[0] == was.point - scene.bodies[static_cast<std::size_t>(upper)].position);

    // The record says where each body is touched, so step 2 can be rebuilt from it: q_rel,1 = body1_point - p_1.
    const ContactPreparation record = contact_preparation(0, *is, bodies, mass, scene.settings);
    REQUIRE(record.body1_point);
    CHECK(record.point == is->point);
    CHECK(*record.body1_point == *is->body1_point);
    const Vec3 lower_centre = bodies[static_cast<std::size_t>(is->bodies[1])].position;
    CHECK(*record.relative_position[1] == *record.body1_point - lower_centre);
    CHECK_FALSE(contact_preparation(0, was, bodies, mass, scene.settings).body1_point);  // detected: one point
}

TEST_CASE("a pair that moves or turns past the recycling settings is tested afresh") {
    const Scene scene = test::shipped_under("box_resting", "soft_step_recycled");
    const auto after_move = [&scene](const Vec3& move, double degrees) {
        std::vector<RigidBody> bodies = scene.bodies;
        ContactRecycling recycling;
        detect(scene, bodies, recycling);
        bodies[0].position += move;
        bodies[0].orientation = turned_about_z(degrees) * bodies[0].orientation;
        const Detection detection = detect(scene, bodies, recycling);
        // Whatever happened, what the world resolves is either the kept contacts or a fresh test's.
        if (detection.pairs_recycled == 0) CHECK(detection.contacts == detect_contacts(scene, bodies).contacts);
        return detection.pairs_recycled;
    };
    CHECK(after_move(Vec3(0.04, 0.0, 0.0), 0.0) == 1);  // 4 cm < 5 cm
    CHECK(after_move(Vec3(0.06, 0.0, 0.0), 0.0) == 0);  // 6 cm: tested afresh
    CHECK(after_move(Vec3(0.0, -0.06, 0.0), 0.0) == 0);
    // A turn of 1 degree about the centre swings the cube's corners (reach sqrt(3)/2 m) by 2 sin(0.5 deg) 0.866 =
    // 1.5 cm: kept. 3 degrees: 4.5 cm, kept alone, but not with 1 cm of move besides (5.5 cm > 5 cm).
    CHECK(after_move(Vec3::Zero(), 1.0) == 1);
    CHECK(after_move(Vec3::Zero(), 3.0) == 1);
    CHECK(after_move(Vec3(0.01, 0.0, 0.0), 3.0) == 0);
    // Past the angle, whatever the distance allows.
    Scene far = scene;
    formats::apply_setting(far, "recycling.distance=10", "--set");
    std::vector<RigidBody> bodies = far.bodies;
    ContactRecycling recycling;
    detect(far, bodies, recycling);
    bodies[0].orientation = turned_about_z(9.0);
    CHECK(detect(far, bodies, recycling).pairs_recycled == 1);
    bodies[0].orientation = turned_about_z(11.0);
    CHECK(detect(far, bodies, recycling).pairs_recycled == 0);
}

TEST_CASE("kept pairs recycle the same contacts however often the store of kept contacts is compacted round them") {
    // The top box of stack_3 is moved 6 cm (past the 5 cm allowed) every other frame, one way and then back: its pair
    // is tested afresh and keeps new contacts, leaving the old ones behind in the store, which is compacted every few
    // frames. On the frames between, nothing moves and every pair is recycled: what they give must be what a fresh
    // recycler gives for the same bodies, a detection and then a recycling, wherever the contacts now lie.
    const Scene scene = test::shipped_under("stack_3", "soft_step_recycled");
    const std::size_t top = highest_body(scene);
    std::vector<RigidBody> bodies = scene.bodies;
    ContactRecycling recycling;
    detect(scene, bodies, recycling);
    for (int frame = 0; frame < 24; ++frame) {
        CAPTURE(frame);
        if (frame % 2 == 0) {
            bodies[top].position.x() += frame % 4 == 0 ? 0.06 : -0.06;
            CHECK(detect(scene, bodies, recycling).pairs_recycled == 2);  // the top box's pair tested afresh
            continue;
        }
        const Detection recycled = detect(scene, bodies, recycling);
        CHECK(recycled.pairs_recycled == 3);
        ContactRecycling fresh;
        detect(scene, bodies, fresh);
        CHECK(recycled.contacts == detect(scene, bodies, fresh).contacts);
    }
}

TEST_CASE("recycling is off unless switched on, and then every frame detects afresh") {
    CHECK_FALSE(ResolverSettings{}.recycling.on());
    CHECK(ResolverSettings{}.recycling.distance == 0.0);
    for (const std::string_view name : preset_names()) {
        CAPTURE(name);
        CHECK(preset(name)->recycling.on() ==
              (name == "soft_step_recycled" || name == "soft_step_coloured" || name == "soft_step_wide"));
    }
    // A world under soft_step keeps nothing: each frame's contacts are a fresh test's.
    const Scene scene = test::shipped_under("stack_3", "soft_step");
    World world(scene);
    for (int frame = 0; frame < 10; ++frame) {
        const std::vector<RigidBody> before = world.bodies();
        const StepReport report = world.step();
        CHECK(report.pairs_recycled == 0);
        CHECK(report.contacts == static_cast<int>(detect_contacts(scene, before).contacts.size()));
    }
    CHECK(world.contact_recycling().kept_pairs() == 0);
    // The same scene recycled from its second frame on.
    World recycled(test::shipped_under("stack_3", "soft_step_recycled"));
    CHECK(recycled.step().pairs_recycled == 0);
    CHECK(recycled.step().pairs_recycled > 0);
}

TEST_CASE("reset forgets the kept contacts, and the recycled run follows again bit for bit") {
    World world(test::shipped_under("stack_20", "soft_step_recycled"));
    for (int frame = 0; frame < 30; ++frame) world.step();
    const std::vector<RigidBody> first = world.bodies();
    CHECK(world.contact_recycling().kept_pairs() > 0);
    world.reset();
    CHECK(world.contact_recycling().kept_pairs() == 0);
    CHECK(world.step().pairs_recycled == 0);
    for (int frame = 1; frame < 30; ++frame) world.step();
    CHECK(world.bodies() == first);
}

TEST_CASE("recorded and unrecorded recycled runs are bit-identical") {
    // Recycling is the world's detection; the recorder sees the frames it resolves and changes nothing.
    const Scene scene = test::shipped_under("stack_20", "soft_step_recycled");
    World quiet(scene), traced(scene);
    Trace trace;
    trace.scene = scene;
    TraceRecorder recorder(trace);
    int recycled = 0;
    for (int frame = 0; frame < 120; ++frame) {
        recycled += quiet.step().pairs_recycled;
        traced.step(recorder);
    }
    CHECK(recycled > 0);
    CHECK(quiet.bodies() == traced.bodies());
}

TEST_CASE(
    "soft_step_recycled is soft_step with recycling, a stiffer spring of the same push-out rate and a 2 cm margin") {
    const ResolverSettings plain = *preset("soft_step");
    ResolverSettings recycled = *preset("soft_step_recycled");
    CHECK(recycled.recycling.distance == 0.05);
    CHECK(recycled.soft_step.contact_hertz == 36.0);
    CHECK(recycled.soft_step.damping_ratio == 12.0);
    CHECK(recycled.speculative_margin == 0.02);  // Box3D's speculative distance; plain soft_step keeps 0
    CHECK(plain.speculative_margin == 0.0);
    // Both scaled by 1.2: the soft contact's bias rate is soft_step's, its mass scale larger, at every sub-step count
    // from 3 (at 1 and 2 the cap of a quarter of the sub-step rate, 15 and 30 Hz, cuts the hertz).
    for (const int substeps : {3, 4, 8, 32}) {
        CAPTURE(substeps);
        ResolverSettings a = plain, b = recycled;
        a.soft_step.substeps = b.soft_step.substeps = substeps;
        CHECK(soft_step_softness(b).bias_rate == doctest::Approx(soft_step_softness(a).bias_rate).epsilon(1e-14));
        CHECK(soft_step_softness(b).mass_scale > soft_step_softness(a).mass_scale);
    }
    // Nothing else differs.
    recycled.preset = plain.preset;
    recycled.recycling = plain.recycling;
    recycled.soft_step.contact_hertz = plain.soft_step.contact_hertz;
    recycled.soft_step.damping_ratio = plain.soft_step.damping_ratio;
    recycled.speculative_margin = plain.speculative_margin;
    CHECK(recycled == plain);
}

TEST_CASE("stack_20 stands 10 s under soft_step_recycled, its top box within 5 cm sideways once settled") {
    // Issue 28's target, as the bench judges stack_20 (top_sideways_drift from 2 s). Measured: 4.55 cm at N = 4
    // (the preset's), 3.33 cm at N = 8; with Box3D's 30 Hz and damping ratio 10 it leans 6.1 and 5.3 cm.
    const Scene scene = test::shipped_under("stack_20", "soft_step_recycled");
    World world(scene);
    const std::size_t top = scene.bodies.size() - 1;
    const Vec3 up(0, 1, 0);
    const auto sideways = [&up](const Vec3& d) { return (d - d.dot(up) * up).norm(); };
    Vec3 settled = Vec3::Zero();
    double most = 0.0;
    for (int frame = 1; frame <= 600; ++frame) {
        world.step();
        const Vec3& at = world.bodies()[top].position;
        if (frame == 120) settled = at;
        if (frame >= 120) most = std::max(most, sideways(at - settled));
    }
    CHECK(world.bodies()[top].position.y() > 19.0);  // standing: the top box is still 19 boxes up
    CHECK(most < 0.05);
}
