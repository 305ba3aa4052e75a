// Soft step (Box2D v3) against hand-derived values: its softness coefficients, a bounce, free fall over the
// sub-steps, a resting box, warm starting, and its recording (bit-identical to an unrecorded run, a trace that
// round-trips and passes its schema).

#include "formats/json_text.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "methods/soft_step.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/approx.hpp"
#include "support/bodies.hpp"
#include "support/shipped.hpp"
#include "support/simulate.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <set>

using namespace impulse;

namespace {

Scene soft_scene(const std::string& name, const std::vector<std::string>& settings = {}) {
    return test::shipped_under(name, "soft_step", settings);
}

using test::simulate;

}  // namespace

TEST_CASE("the softness coefficients match hand-derived values for 30 Hz, damping ratio 10 and h = 1/240") {
    // omega = 2 pi 30 = 60 pi rad/s, so h omega = 60 pi / 240 = pi / 4 exactly.
    //   a1 = 2 zeta + h omega = 20 + pi/4                 = 20.785398163397448
    //   a2 = h omega a1       = (pi/4)(20 + pi/4)          = 5 pi + pi^2/16 = 16.324813543017047
    //   bias_rate     = omega / a1 = 60 pi / (20 + pi/4)   = 9.068652798161134 1/s
    //   mass_scale    = a2 / (1 + a2)                      = 0.9422793210722281
    //   impulse_scale = 1 / (1 + a2)                       = 0.05772067892777182
    // They come from a spring k = m omega^2 and damper c = 2 m zeta omega on the effective mass m, stepped
    // with implicit Euler: m (v2 - v1) = -h (k (C + h v2) + c v2) gives
    //   m (v2 - v1) = -m [a2 / (1 + a2)] (v1 + [omega / a1] C),
    // since h c + h^2 k = m h omega (2 zeta + h omega) = m a2 and h k / (h c + h^2 k) = omega / a1. The two
    // scales add to 1, which makes -impulse_scale lambda the term that lets a visit converge to that impulse.
    const double pi = std::numbers::pi;
    const Softness s = soft_contact(30.0, 10.0, 1.0 / 240.0);
    const double a1 = 20.0 + pi / 4, a2 = (pi / 4) * a1;
    CHECK_CLOSE(s.bias_rate, 60 * pi / a1);
    CHECK_CLOSE(s.mass_scale, a2 / (1 + a2));
    CHECK_CLOSE(s.impulse_scale, 1 / (1 + a2));
    CHECK_CLOSE(s.bias_rate, 9.068652798161134);
    CHECK_CLOSE(s.mass_scale, 0.9422793210722281);
    CHECK_CLOSE(s.impulse_scale, 0.05772067892777182);
    CHECK_CLOSE(s.mass_scale + s.impulse_scale, 1.0);
    // The soft_step preset: 4 sub-steps of a 1/60 s frame are h = 1/240; 30 Hz is below the cap of a quarter
    // of the 240 Hz sub-step rate (60 Hz), so the preset uses exactly these coefficients.
    CHECK(soft_step_softness(*preset("soft_step")) == s);
    // With one sub-step the cap binds: 0.25 x 60 Hz = 15 Hz.
    ResolverSettings one = *preset("soft_step");
    one.soft_step.substeps = 1;
    CHECK(soft_step_softness(one) == soft_contact(15.0, 10.0, 1.0 / 60.0));
}

TEST_CASE("an isolated frictionless sphere hitting the ground at 2 m/s with restitution 0.5 leaves at 1 m/s") {
    // Relax leaves the normal velocity at 0 (a rigid solve with the impulse still pushing), and restitution
    // then asks for -c v_n(before) = -0.5 x (-2) = 1 m/s with an unclamped impulse: exactly 1 m/s, whatever
    // the soft contact did on the way. The closing speed 2 m/s is above the 0.25 m/s cut-off.
    std::vector<RigidBody> bodies{test::sphere(2.0, 0.5, {0, 0.5, 0}, {0, -2, 0})};
    const std::vector<Contact> contacts{test::contact(0, world_body, {0, 0, 0}, {0, 1, 0}, 0.0, 0.5)};
    const ResolverSettings settings = *preset("soft_step");
    Trace trace;
    TraceRecorder recorder(trace);
    const ResolutionSummary summary = resolve_contacts(bodies, contacts, settings, recorder);
    CHECK_CLOSE(bodies[0].velocity, Vec3(0, 1, 0));
    CHECK(bodies[0].angular_velocity == Vec3::Zero());
    CHECK(summary.position.iterations_used == 0);
    // One contact: 4 sub-steps of warm start, 1 solve and 1 relax sweep, then one restitution visit.
    CHECK(summary.velocity.iterations_used == 4 * 3 + 1);
    const VelocityIteration& last = trace.frames.at(0).velocity.iterations.back();
    CHECK(last.sweep->stage == SolverStage::restitution);
    CHECK(last.resolution->impulse_terms.impulse_model == ImpulseModel::frictionless);
    CHECK_CLOSE(last.resolution->contact_velocity.x() + last.resolution->desired_terms.desired_delta_velocity, 1.0);
}

TEST_CASE("a separated contact pushes nothing and only stops a closing faster than its gap allows") {
    // Regression: the speculative bias had its sign reversed, so a contact whose bodies had drawn apart during
    // the sub-steps pushed them further apart at gap / h_s, and pyramid_20 exploded.
    // A sphere 1 cm above the ground (penetration -0.01): at rest it stays at rest.
    const std::vector<Contact> gap{test::contact(0, world_body, {0, -0.01, 0}, {0, 1, 0}, -0.01)};
    const ResolverSettings settings = *preset("soft_step");
    std::vector<RigidBody> resting{test::sphere(1.0, 0.5, {0, 0.51, 0})};
    resolve_contacts(resting, gap, settings);
    CHECK(resting[0].velocity == Vec3::Zero());
    // Falling at 0.3 m/s it covers 0.3 / 240 = 1.25 mm per sub-step, 5 mm of the 10 mm gap in the frame: untouched.
    std::vector<RigidBody> falling{test::sphere(1.0, 0.5, {0, 0.51, 0}, {0, -0.3, 0})};
    resolve_contacts(falling, gap, settings);
    CHECK(falling[0].velocity == Vec3(0, -0.3, 0));
    CHECK_CLOSE(falling[0].position.y(), 0.51 - 0.3 / 60);
    // Falling at 3 m/s it would cover 12.5 mm in the first sub-step: it is slowed to close exactly the 10 mm.
    std::vector<RigidBody> fast{test::sphere(1.0, 0.5, {0, 0.51, 0}, {0, -3, 0})};
    resolve_contacts(fast, gap, settings);
    CHECK(fast[0].position.y() >= 0.5 - 1e-12);
    CHECK(fast[0].velocity.y() > -3.0);
}

TEST_CASE("a body touching nothing falls as semi-implicit Euler over the sub-steps") {
    // n sub-steps of h_s per frame: after N = 4 x 60 sub-steps v = g N h_s and y = y0 + g h_s^2 N (N + 1) / 2.
    Scene scene = soft_scene("sphere_drop");
    scene.ground.reset();
    const std::vector<RigidBody> bodies = simulate(scene, 60);
    const double g = -9.81, h = scene.settings.duration / 4, n = 240;
    CHECK_CLOSE(bodies[0].velocity, Vec3(0, g * n * h, 0), 1e-12);
    CHECK_CLOSE(bodies[0].position.y(), scene.bodies[0].position.y() + g * h * h * n * (n + 1) / 2, 1e-12);
}

TEST_CASE("a box resting on the ground under soft step stays within a millimetre over 300 frames") {
    // The soft contact holds the box where its spring carries the weight: a deflection of g / omega^2 =
    // 9.81 / (60 pi)^2 = 0.28 mm at 30 Hz. Nothing pushes it sideways.
    const Scene scene = soft_scene("box_resting");
    World world(scene);
    const std::vector<RigidBody>& bodies = world.bodies();
    double most_energy = 0.0, most_drift = 0.0;
    for (int frame = 0; frame < 300; ++frame) {
        const StepReport r = world.step();
        most_energy = std::max(most_energy, r.kinetic_energy);
        most_drift = std::max(most_drift, (bodies[0].position - scene.bodies[0].position).norm());
        CHECK(r.contacts == 4);
    }
    CHECK(most_drift < 1e-3);
    CHECK(std::abs(scene.bodies[0].position.y() - bodies[0].position.y() - 9.81 / std::pow(60 * std::numbers::pi, 2)) <
          1e-4);
    CHECK(most_energy < 1e-5);  // J: well below the 0.5 x 1 kg x (g h)^2 = 4.4e-4 J of one sub-step's gravity
}

TEST_CASE("warm starting reduces the first solve sweep's impulse change on the second frame") {
    const auto first_solve_change = [](bool warm) {
        Trace trace;
        simulate(soft_scene("box_resting", {std::string("warm_start=") + (warm ? "true" : "false")}), 2, &trace);
        double change = 0.0;
        for (const VelocityIteration& it : trace.frames.at(1).velocity.iterations)
            if (it.sweep->substep == 0 && it.sweep->pass == 0 && it.sweep->stage == SolverStage::solve)
                change += (it.accumulated->after - it.accumulated->before).norm();
        return change;
    };
    const double cold = first_solve_change(false), warm = first_solve_change(true);
    // Cold, the four contacts must build the box's weight over one sub-step, about m g h_s = 0.041 N s, again.
    CHECK(cold > 0.03);
    CHECK(warm < 0.1 * cold);
}

TEST_CASE("recorded and unrecorded soft-step runs are bit-identical") {
    const Scene scene = soft_scene("stack_3", {"soft_step.substeps=2", "sweeps=2"});
    Trace trace;
    CHECK(simulate(scene, 60) == simulate(scene, 60, &trace));
    CHECK(trace.frames.size() == 60);
}

TEST_CASE("a traced soft-step run round-trips through the trace file and passes the schema") {
    Trace trace;
    simulate(soft_scene("stack_3"), 3, &trace);
    // A bounce adds the restitution stage.
    Trace bounce;
    bounce.scene = test::shipped("cases/sphere_ground");
    formats::apply_setting(bounce.scene, "preset=soft_step", "--set");
    std::vector<RigidBody> bodies = bounce.scene.bodies;
    TraceRecorder recorder(bounce);
    resolve_contacts(bodies, bounce.scene.contacts, bounce.scene.settings, recorder);
    for (const Trace* t : {&trace, &bounce}) {
        const std::string text = formats::format_json(formats::trace_json(*t));
        const Trace again = formats::read_trace_text(text);  // checks the schema first
        CHECK(again == *t);
        CHECK(formats::format_json(formats::trace_json(again)) == text);
    }
    std::set<SolverStage> stages;
    for (const Trace* t : {&trace, &bounce})
        for (const FrameRecord& f : t->frames)
            for (const VelocityIteration& it : f.velocity.iterations) {
                REQUIRE(it.sweep);
                REQUIRE(it.accumulated);
                REQUIRE(it.resolution);
                stages.insert(it.sweep->stage);
            }
    CHECK(stages == std::set<SolverStage>{SolverStage::warm_start, SolverStage::solve, SolverStage::relax,
                                          SolverStage::restitution});
}
