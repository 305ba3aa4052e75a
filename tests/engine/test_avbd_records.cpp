// What a trace records of AVBD (engine/record/avbd_records.hpp): a run is the same to the bit with and without the
// recorder; each body visit's block and move and each dual update are the method's own values (rebuilt here from
// the recorded inputs with the derivation steps of engine/derivation/avbd/); the trace writes, validates and reads
// back to the same records.

#include "derivation/avbd/block_solve.hpp"
#include "derivation/avbd/body_block.hpp"
#include "derivation/avbd/dual_update.hpp"
#include "derivation/avbd/mass_scaled_penalty.hpp"
#include "formats/json_text.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "support/approx.hpp"
#include "support/shipped.hpp"
#include "support/simulate.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <map>
#include <optional>

using namespace impulse;

namespace {

Scene avbd_scene(const std::string& name, const std::vector<std::string>& settings = {}) {
    return test::shipped_under(name, "avbd", settings);
}

using test::simulate;

bool same_bits(const std::vector<RigidBody>& a, const std::vector<RigidBody>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(a[i].position == b[i].position && a[i].orientation.coeffs() == b[i].orientation.coeffs() &&
              a[i].velocity == b[i].velocity && a[i].angular_velocity == b[i].angular_velocity))
            return false;
    return true;
}

}  // namespace

TEST_CASE("AVBD runs to the same bits with and without a trace, bounces, friction and post-stabilisation off too") {
    // Plain names, not a structured binding: doctest's INFO captures them in a lambda, and Debian 12's clang (the
    // sanitize build's) cannot capture a binding (C++20's P1091, in clang from version 16).
    for (const auto& run :
         std::vector<std::pair<std::string, std::vector<std::string>>>{{"mass_ratio_100", {}},
                                                                       {"pyramid_10", {}},
                                                                       {"sphere_drop", {}},
                                                                       {"box_on_slope", {}},
                                                                       {"stack_10", {"avbd.post_stabilize=false"}}}) {
        const std::string& name = run.first;
        const std::vector<std::string>& settings = run.second;
        INFO(name);
        const Scene scene = avbd_scene(name, settings);
        Trace trace;
        const std::vector<RigidBody> recorded = simulate(scene, 90, &trace);
        CHECK(same_bits(recorded, simulate(scene, 90)));
        REQUIRE(trace.frames.size() == 90);
        // The trace lists every iteration it counts.
        for (const FrameRecord& f : trace.frames)
            CHECK(static_cast<std::size_t>(f.velocity.outcome.iterations_used) == f.velocity.iterations.size());
    }
}

TEST_CASE("an AVBD frame records a sweep over the bodies, then every contact's dual update, in each iteration") {
    const Scene scene = avbd_scene("mass_ratio_100");
    Trace trace;
    simulate(scene, 30, &trace);
    const FrameRecord& f = trace.frames.back();
    const std::vector<VelocityIteration>& its = f.velocity.iterations;
    const int iterations = scene.settings.avbd.iterations;
    // Two boxes, each touching: the light one 8 contacts (4 below, 4 above), the heavy one 4.
    REQUIRE(f.contact_count == 8);
    REQUIRE(its.size() == static_cast<std::size_t>(2 * (iterations + 1) + 8 * iterations));
    std::size_t at = 0;
    for (int sweep = 0; sweep <= iterations; ++sweep) {
        const SolverStage stage = sweep < iterations ? SolverStage::solve : SolverStage::stabilize;
        for (int body = 0; body < 2; ++body, ++at) {
            REQUIRE(its[at].body_visit);
            CHECK(its[at].iteration == static_cast<int>(at));
            CHECK(its[at].sweep == SweepPlace{0, sweep, stage});
            CHECK(its[at].body_visit->body == body);
            CHECK(its[at].contact == its[at].body_visit->gathered.front().contact);
        }
        if (sweep == iterations) break;
        for (int contact = 0; contact < 8; ++contact, ++at) {
            REQUIRE(its[at].dual_update);
            CHECK(its[at].contact == contact);
            CHECK(its[at].sweep == SweepPlace{0, sweep, SolverStage::dual});
        }
    }
    CHECK(its[0].body_visit->gathered.size() + its[1].body_visit->gathered.size() == 12);
}

TEST_CASE("a body visit's block, move and displacement and a dual update's values are the method's own") {
    const Scene scene = avbd_scene("mass_ratio_100");
    Trace trace;
    simulate(scene, 30, &trace);
    const FrameRecord& f = trace.frames.back();
    const AvbdSettings& avbd = scene.settings.avbd;
    std::map<int, Displacement> last;   // per body: its displacement after its latest visit
    std::map<int, DualVariables> dual;  // per contact: lambda and k after its latest dual update
    int checked_blocks = 0, checked_duals = 0, between_boxes = 0;
    for (const VelocityIteration& it : f.velocity.iterations) {
        if (const auto& v = it.body_visit) {
            // The block solve of the recorded block gives the recorded move, to the bit (Eq. 4).
            const BlockSolution s = block_solve(BodyBlock{v->block_matrix, v->block_force});
            CHECK(s.position_change == v->position_change);
            CHECK((s.pivots.array() > 0.0).all());
            // The recorded block is the inertia's share plus the recorded forces' (Eqs. 5, 6, 13, 17): rebuilt from the
            // inertia alone, H - M/h^2 and f - M/h^2(y - x) are what the gathered contacts add.
            Mat6 contacts_h = Mat6::Zero();
            Vec6 contacts_f = Vec6::Zero();
            for (const AvbdContactRows& c : v->gathered) {
                const ContactPreparation& p = f.contacts.at(static_cast<std::size_t>(c.contact));
                const ConstraintJacobian j = constraint_jacobian(
                    p.basis, {*p.relative_position[0], p.relative_position[1].value_or(Vec3::Zero())});
                const ContactForce force = contact_force(c.lambda, c.stiffness, c.constraint, p.friction);
                CHECK(force.force == c.force);  // (Eq. 11)
                BodyBlock share{Mat6::Zero(), Vec6::Zero()};
                add_contact_force(j, c.slot, force, share);
                contacts_h += share.block_matrix;
                contacts_f += share.block_force;
                // The multiplier and stiffness it read are the last dual update's.
                if (dual.count(c.contact)) CHECK(dual[c.contact] == DualVariables{c.lambda, c.stiffness});
            }
            const Mat6 inertia_h = v->block_matrix - contacts_h;
            // What is left is M/h^2: diagonal in the move, the body's mass over h^2.
            const double h = scene.settings.duration;
            const double mass = 1.0 / scene.bodies.at(static_cast<std::size_t>(v->body)).inverse_mass;
            CHECK_CLOSE(inertia_h(1, 1), mass / (h * h));
            CHECK(std::abs(inertia_h(0, 1)) < 1e-6 * mass / (h * h));
            // The displacement grows by the move.
            if (last.count(v->body)) {
                CHECK(v->displacement.linear == Vec3(last[v->body].linear + v->position_change.linear));
                CHECK(v->displacement.angular == Vec3(last[v->body].angular + v->position_change.angular));
            }
            last[v->body] = v->displacement;
            ++checked_blocks;
        }
        if (const auto& d = it.dual_update) {
            const ContactPreparation& p = f.contacts.at(static_cast<std::size_t>(it.contact));
            const ContactForce force = contact_force(d->rows.lambda, d->rows.stiffness, d->rows.constraint, p.friction);
            CHECK(force.force == d->rows.force);
            // beta and k_max per kg, times the lighter of the contact's bodies that translate (mass_ratio_100: the
            // 1 kg box's on the ground and under the 100 kg box), read off the scene as a trace reader would.
            std::array<double, 2> mass{0.0, 0.0};
            for (int i = 0; i < 2; ++i)
                if (p.bodies[i] != world_body)
                    mass[i] = 1.0 / scene.bodies.at(static_cast<std::size_t>(p.bodies[i])).inverse_mass;
            const PenaltyParameters penalty = mass_scaled_penalty(avbd, mass);
            CHECK(dual_update(force, d->rows.stiffness, d->rows.constraint, penalty) == d->updated);  // (Eqs. 11, 16)
            if (p.bodies[1] != world_body) ++between_boxes;
            CHECK(penalty.mass == 1.0);
            dual[it.contact] = d->updated;
            ++checked_duals;
        }
    }
    CHECK(checked_blocks == 22);
    CHECK(checked_duals == 80);
    CHECK(between_boxes == 40);  // the four corners between the boxes, each sweep: 1 kg, not 100
    // The bodies end where their last visit left them (the post-stabilisation sweep's displacement).
    for (const auto& moved : last) {
        const auto body = static_cast<std::size_t>(moved.first);
        CHECK_CLOSE(f.bodies_after[body].position, Vec3(f.bodies_before[body].position + moved.second.linear));
    }
}

TEST_CASE("an AVBD trace validates against the schema and reads back to the same records") {
    for (const std::string name : {"mass_ratio_100", "sphere_drop"}) {
        INFO(name);
        Trace trace;
        simulate(avbd_scene(name), 40, &trace);
        const std::string text = formats::format_json(formats::trace_json(trace));
        const Trace back = formats::read_trace_text(text);
        REQUIRE(back.frames.size() == trace.frames.size());
        for (std::size_t i = 0; i < trace.frames.size(); ++i) {
            INFO("frame " << i);
            const auto& a = back.frames[i].velocity.iterations;
            const auto& b = trace.frames[i].velocity.iterations;
            REQUIRE(a.size() == b.size());
            for (std::size_t k = 0; k < a.size(); ++k) {
                INFO("iteration " << k);
                CHECK(a[k].body_visit == b[k].body_visit);
                CHECK(a[k].dual_update == b[k].dual_update);
                CHECK(a[k].sweep == b[k].sweep);
                CHECK(a[k].resolution == b[k].resolution);
                CHECK(a[k].accumulated == b[k].accumulated);
                CHECK(a[k].desired_delta_velocity == b[k].desired_delta_velocity);
            }
            CHECK(back.frames[i].velocity == trace.frames[i].velocity);
        }
        // The JSON written of what was read is the same text.
        CHECK(formats::format_json(formats::trace_json(back)) == text);
    }
}

TEST_CASE("a contact filter keeps a body visit with only the recorded contacts it gathered") {
    Scene scene = avbd_scene("mass_ratio_100");
    Trace trace;
    trace.recording.contacts = std::vector<int>{0, 5};
    simulate(scene, 5, &trace);
    const FrameRecord& f = trace.frames.back();
    int dual_lines = 0;
    for (const VelocityIteration& it : f.velocity.iterations) {
        if (it.body_visit)
            for (const AvbdContactRows& c : it.body_visit->gathered) CHECK((c.contact == 0 || c.contact == 5));
        if (it.sweep->stage == SolverStage::dual && !it.dual_update) {
            CHECK((it.contact != 0 && it.contact != 5));
            ++dual_lines;
        }
    }
    CHECK(dual_lines > 0);
    const Trace back = formats::read_trace_text(formats::format_json(formats::trace_json(trace)));
    CHECK(back.frames.back().velocity == f.velocity);
}
