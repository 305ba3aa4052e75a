// The production baselines beside the book's method: the sequential sweep, projected Gauss-Seidel with
// accumulated, clamped and warm-started impulses, Baumgarte's bias and the split impulse. Checked against
// answers derived by hand: a bounce, the resting impulses of a stack, the clamps, and energy.

#include "formats/json_text.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "methods/method_table.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/bodies.hpp"
#include "support/gravity_and_frame.hpp"
#include "support/shipped.hpp"
#include "support/sliding_box.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace impulse;

namespace {

using impulse::test::g;
using impulse::test::h;

ResolverSettings settings_of(std::string_view name) {
    ResolverSettings s = *preset(name);
    // -c v_s exactly, no chapter-15 terms
    s.restitution_cutoff = 0.0;
    s.velocity_from_acceleration = false;
    s.tangential_acceleration_velocity = false;
    return s;
}

// Spheres of radius 0.5 stacked on the ground, each touching the one below at a single point straight
// under its centre: contact k joins sphere k (body 0) and the sphere below it (or the ground), normal up.
// Every sphere falls at g h, as one integration step from rest leaves it.
struct SphereStack {
    std::vector<RigidBody> bodies;
    std::vector<Contact> contacts;
};

SphereStack sphere_stack(const std::vector<double>& masses) {
    SphereStack s;
    for (std::size_t k = 0; k < masses.size(); ++k) {
        const double y = 0.5 + static_cast<double>(k);
        s.bodies.push_back(test::sphere(masses[k], 0.5, {0, y, 0}, {0, -g * h, 0}));
        const int below = k == 0 ? world_body : static_cast<int>(k) - 1;
        s.contacts.push_back(test::contact(static_cast<int>(k), below, {0, y - 0.5, 0}, {0, 1, 0}));
    }
    return s;
}

// The normal impulse each contact of the stack carries when every sphere comes to rest: the momentum
// g h x (the mass of the sphere on it and of everything above).
std::vector<double> resting_impulses(const std::vector<double>& masses) {
    std::vector<double> impulses(masses.size(), 0.0);
    double above = 0.0;
    for (std::size_t k = masses.size(); k-- > 0;) {
        above += masses[k];
        impulses[k] = g * h * above;
    }
    return impulses;
}

double largest_relative_error(const SphereStack& stack, const ContactMemory& memory, const std::vector<double>& exact) {
    double worst = 0.0;
    for (std::size_t k = 0; k < exact.size(); ++k) {
        const std::ptrdiff_t slot = memory.slot_of({stack.contacts[k].bodies, stack.contacts[k].origin});
        REQUIRE(slot >= 0);
        worst = std::max(worst, std::abs(memory.impulse_at(slot).y() - exact[k]) / exact[k]);
    }
    return worst;
}

ResolverSettings stack_settings(int sweeps, bool warm_start) {
    ResolverSettings s = settings_of("pgs");
    s.sweeps = sweeps;
    s.warm_start = warm_start;
    s.velocity_epsilon = 1e-9;
    return s;
}

Scene scene_with(const std::string& name, const std::vector<std::string>& settings) {
    Scene scene = test::shipped(name);
    for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
    return scene;
}

// The configurations of this file's methods: each preset that uses one, and Baumgarte under the book's
// velocity methods.
const std::vector<std::vector<std::string>> method_runs{
    {"preset=sweep"},
    {"preset=pgs"},
    {"preset=pgs_split"},
    {"preset=pgs", "warm_start=false"},
    {"position_method=none", "baumgarte=true"},
    {"preset=sweep", "position_method=none", "baumgarte=true"},
};

}  // namespace

TEST_CASE("every preset turns a closing speed v_s into a separating speed of -c v_s on an isolated contact") {
    // A sphere of 1 kg closing on the ground at 2 m/s through a frictionless contact under its centre,
    // c = 0.5: the bounce leaves it separating at 1 m/s, whichever method finds the impulse (it is one
    // contact: every method's first impulse is g = (1 + c) 2 / d = 3 N s, and nothing is left after it).
    for (const std::string_view name : preset_names()) {
        CAPTURE(name);
        std::vector<RigidBody> bodies{test::sphere(1.0, 0.5, {0, 0.5, 0}, {0, -2, 0})};
        const Contact contact = test::contact(0, world_body, {0, 0, 0}, {0, 1, 0}, 0.0, 0.5);
        ContactMemory memory;
        Recorder nobody;
        resolve_contacts(bodies, std::span(&contact, 1), settings_of(name), nobody, {.frame = 0, .memory = &memory});
        const double separating = test::point_velocity(bodies[0], contact.point).dot(contact.normal);
        CHECK(separating == doctest::Approx(-0.5 * -2.0).epsilon(1e-12));
    }
}

TEST_CASE("projected Gauss-Seidel converges to the resting impulses of a stack, g h times the mass above") {
    // Three spheres of 1, 2 and 3 kg (bottom to top): the contacts carry g h x (6, 5, 3) kg.
    const std::vector<double> masses{1.0, 2.0, 3.0};
    SphereStack stack = sphere_stack(masses);
    ContactMemory memory;
    Recorder nobody;
    const ResolutionSummary summary = resolve_contacts(stack.bodies, stack.contacts, stack_settings(400, false), nobody,
                                                       {.frame = 0, .memory = &memory});
    CHECK(summary.velocity.stop == StopReason::resolved);
    CHECK(largest_relative_error(stack, memory, resting_impulses(masses)) < 1e-6);
    for (const RigidBody& body : stack.bodies) CHECK(body.velocity.norm() < 1e-8);
}

TEST_CASE("a warm-started frame of a resting stack starts from last frame's totals and needs fewer sweeps") {
    // Two frames of the same four-sphere stack; between them gravity adds g h to every speed again. Warm
    // started, the second frame begins at the first frame's totals, which already hold the stack.
    const std::vector<double> masses{1.0, 1.0, 1.0, 1.0};
    const auto second_frame = [&](bool warm_start, Trace* trace) {
        SphereStack stack = sphere_stack(masses);
        ContactMemory memory;
        Recorder nobody;
        const ResolverSettings s = stack_settings(500, warm_start);
        resolve_contacts(stack.bodies, stack.contacts, s, nobody, {.frame = 0, .memory = &memory});
        for (RigidBody& body : stack.bodies) body.velocity.y() -= g * h;
        if (!trace) return resolve_contacts(stack.bodies, stack.contacts, s, nobody, {.frame = 1, .memory = &memory});
        TraceRecorder recorder(*trace);
        return resolve_contacts(stack.bodies, stack.contacts, s, recorder, {.frame = 1, .memory = &memory});
    };
    Trace warm_trace;
    const ResolutionSummary warm = second_frame(true, &warm_trace);
    const ResolutionSummary cold = second_frame(false, nullptr);
    CHECK(warm.velocity.stop == StopReason::resolved);
    CHECK(cold.velocity.stop == StopReason::resolved);
    // Warm: 4 warm starts and a few sweeps that only remove what the first frame left within its epsilon
    // (measured: 20 visits warm, 480 cold).
    CHECK(warm.velocity.iterations_used <= 4 + 4 * 4);
    CHECK(cold.velocity.iterations_used > 5 * warm.velocity.iterations_used);
    const std::vector<VelocityIteration>& iterations = warm_trace.frames.at(0).velocity.iterations;
    const std::vector<double> exact = resting_impulses(masses);
    for (int k = 0; k < 4; ++k) {
        const VelocityIteration& it = iterations.at(static_cast<std::size_t>(k));
        CHECK(it.sweep->stage == SolverStage::warm_start);
        CHECK(it.accumulated->after.x() == doctest::Approx(exact[static_cast<std::size_t>(k)]).epsilon(1e-6));
    }
}

TEST_CASE("a separating contact keeps a zero total and records the push-only clamp") {
    // Rising at 1 m/s: the target 0 asks for a pull of 1 N s, the clamp sets the total to 0, nothing applies.
    std::vector<RigidBody> bodies{test::sphere(1.0, 0.5, {0, 0.5, 0}, {0, 1, 0})};
    const Contact contact = test::contact(0, world_body, {0, 0, 0}, {0, 1, 0});
    Trace trace;
    TraceRecorder recorder(trace);
    ContactMemory memory;
    resolve_contacts(bodies, std::span(&contact, 1), settings_of("pgs"), recorder, {.frame = 0, .memory = &memory});
    CHECK(bodies[0].velocity == Vec3(0, 1, 0));
    const VelocityIteration& it = trace.frames.at(0).velocity.iterations.at(0);
    CHECK(it.accumulated->unclamped.x() == doctest::Approx(-1.0));
    CHECK(it.accumulated->after == Vec3::Zero());
    CHECK(it.accumulated->clamp == ImpulseClamp::push_only);
    REQUIRE(memory.slot_of({contact.bodies, contact.origin}) >= 0);
    CHECK(memory.impulse_at(memory.slot_of({contact.bodies, contact.origin})) == Vec3::Zero());
}

TEST_CASE("a box sliding fast on mu 0.3 gets its friction total clamped to the cone") {
    // 1 kg, 5 m/s sideways, falling at g h onto one contact under its centre. Holding it takes g h = 0.1635
    // N s; stopping the slide would take 5 N s, far outside mu g h = 0.049 N s: the total sits on the cone.
    std::vector<RigidBody> bodies{test::box(1.0, {0.5, 0.5, 0.5}, {0, 0.5, 0}, {5, -g * h, 0})};
    const Contact contact = test::contact(0, world_body, {0, 0, 0}, {0, 1, 0}, 0.0, 0.0, 0.3);
    Trace trace;
    TraceRecorder recorder(trace);
    ContactMemory memory;
    resolve_contacts(bodies, std::span(&contact, 1), settings_of("pgs"), recorder, {.frame = 0, .memory = &memory});
    const VelocityIteration& last = trace.frames.at(0).velocity.iterations.back();
    CHECK((last.accumulated->clamp == ImpulseClamp::friction || last.accumulated->clamp == ImpulseClamp::both));
    CHECK(last.resolution->impulse_terms.impulse_model == ImpulseModel::sliding_friction);
    const Vec3 total = last.accumulated->after;
    CHECK(total.x() > 0.0);
    CHECK(std::hypot(total.y(), total.z()) == doctest::Approx(0.3 * total.x()).epsilon(1e-12));
    CHECK(bodies[0].velocity.x() < 5.0);
    CHECK(bodies[0].velocity.x() > 4.9);
}

TEST_CASE("the split impulse removes penetration without adding kinetic energy") {
    // A sphere 5 cm into the ground, falling at g h. The pushes move it up by beta (d - slop) =
    // 0.8 x 0.045 = 0.036 m and leave its velocity exactly as a solve with no position correction does;
    // Baumgarte's bias (0.2) instead makes it rise, with energy that came from nowhere.
    const auto run = [](std::vector<std::string> settings) {
        std::vector<RigidBody> bodies{test::sphere(1.0, 0.5, {0, 0.45, 0}, {0, -g * h, 0})};
        const Contact contact = test::contact(0, world_body, {0, -0.05, 0}, {0, 1, 0}, 0.05);
        Scene scene;
        for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
        ContactMemory memory;
        Recorder nobody;
        resolve_contacts(bodies, std::span(&contact, 1), scene.settings, nobody, {.frame = 0, .memory = &memory});
        return bodies[0];
    };
    const RigidBody split = run({"preset=pgs_split"});
    const RigidBody unbiased = run({"preset=pgs", "position_bias.factor=0"});
    const RigidBody baumgarte = run({"preset=pgs"});
    CHECK(split.position.y() == doctest::Approx(0.45 + 0.8 * 0.045).epsilon(1e-12));
    CHECK(unbiased.position.y() == 0.45);
    CHECK(split.velocity == unbiased.velocity);
    CHECK(split.angular_velocity == unbiased.angular_velocity);
    CHECK(kinetic_energy(split) == kinetic_energy(unbiased));
    CHECK(kinetic_energy(baumgarte) > kinetic_energy(split));
}

TEST_CASE("recorded and unrecorded runs of each method are bit-identical") {
    // Every row of the method table, with the book's velocities or positions around it, every preset, and the
    // step-5 and friction options: every method runs one loop and reports its visits only when the recorder keeps
    // the frame, and the recorder builds its records apart (record/visit_records.hpp), so a run watched and one
    // not must end in the same bits.
    std::vector<std::vector<std::string>> runs = method_runs;
    for (const auto& row : velocity_methods) runs.push_back({"velocity_method=" + std::string(row.name)});
    for (const auto& row : position_methods) {
        runs.push_back({"position_method=" + std::string(row.name)});
        runs.push_back({"preset=pgs", "position_method=" + std::string(row.name)});
    }
    for (const std::string_view name : preset_names()) runs.push_back({"preset=" + std::string(name)});
    runs.push_back({"sliding_friction=against_slip"});
    runs.push_back({"preset=sweep", "sliding_friction=against_slip"});
    for (const std::vector<std::string>& settings : runs) {
        CAPTURE(settings.front());
        CAPTURE(settings.back());
        const Scene scene = scene_with("stack_3", settings);
        World quiet(scene), traced(scene);
        Trace trace;
        trace.scene = scene;
        TraceRecorder recorder(trace);
        for (int frame = 0; frame < 20; ++frame) {
            quiet.step();
            traced.step(recorder);
        }
        CHECK(quiet.bodies() == traced.bodies());
        CHECK(trace.frames.back().bodies_after.front() == state_of(quiet.bodies().front()));
    }
    // And a box sliding on its corners, where the cone clamps.
    for (const std::vector<std::string>& settings : runs) {
        CAPTURE(settings.front());
        CAPTURE(settings.back());
        Scene scene = test::sliding_box("book");
        for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
        World quiet(scene), traced(scene);
        Trace trace;
        trace.scene = scene;
        TraceRecorder recorder(trace);
        for (int frame = 0; frame < 10; ++frame) {
            quiet.step();
            traced.step(recorder);
        }
        CHECK(quiet.bodies() == traced.bodies());
    }
}

TEST_CASE("a traced run of each preset and method round-trips through trace JSON and validates") {
    // Two frames of a box resting on the ground (four contacts): the second frame is warm started.
    std::vector<std::vector<std::string>> runs{{"preset=pgs", "warm_start=false"},
                                               {"position_method=none", "baumgarte=true"},
                                               {"preset=sweep", "position_method=none", "baumgarte=true"}};
    for (const std::string_view name : preset_names()) runs.push_back({"preset=" + std::string(name)});
    for (const std::vector<std::string>& settings : runs) {
        CAPTURE(settings.front());
        CAPTURE(settings.back());
        Trace trace;
        trace.scene = scene_with("box_resting", settings);
        World world(trace.scene);
        TraceRecorder recorder(trace);
        for (int frame = 0; frame < 2; ++frame) world.step(recorder);
        if (trace.scene.settings.velocity_method == VelocityMethod::projected_gauss_seidel &&
            trace.scene.settings.warm_start)
            CHECK(trace.frames.at(1).velocity.iterations.at(0).sweep->stage == SolverStage::warm_start);
        const std::string text = formats::format_json(formats::trace_json(trace));
        const Trace again = formats::read_trace_text(text);  // also checks the schema
        CHECK(again == trace);
        CHECK(formats::format_json(formats::trace_json(again)) == text);
    }
}
