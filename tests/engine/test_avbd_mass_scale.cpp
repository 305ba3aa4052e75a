// AVBD's penalty parameters per kilogram (derivation/avbd/mass_scaled_penalty.hpp): the step's values worked by hand,
// a cube of 10^6 kg held as a 1 kg one is (the recurrence of docs/methods.md's worked example, mass-free), and scenes
// whose every mass is multiplied by 10^6 moving as they did at their own masses.

#include "derivation/avbd/mass_scaled_penalty.hpp"
#include "formats/settings_json.hpp"
#include "support/bodies.hpp"
#include "support/gravity_and_frame.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace impulse;

namespace {

using impulse::test::g;
using impulse::test::h;

// `scene` with every body's mass and inertia multiplied by `factor`; gravity, shapes and materials as they were.
Scene heavier(Scene scene, double factor) {
    for (RigidBody& b : scene.bodies) {
        b.inverse_mass /= factor;
        b.inverse_inertia_body /= factor;
    }
    return scene;
}

// The largest distance between the same body's centres in two runs (m).
double largest_gap(const std::vector<RigidBody>& a, const std::vector<RigidBody>& b) {
    double gap = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) gap = std::max(gap, (a[i].position - b[i].position).norm());
    return gap;
}

}  // namespace

TEST_CASE("a contact's beta, k_min and k_max are the settings' per kg times the lighter translating body's mass") {
    AvbdSettings s;  // 1e6, 1e4, 1e9 per kg
    // A 5 kg box on a 2 kg one: 2 kg, 2e6 N/m^2, 2e4 and 2e9 N/m, whichever body is body 0.
    PenaltyParameters p = mass_scaled_penalty(s, {2.0, 5.0});
    CHECK(p.mass == 2.0);
    CHECK(p.beta == 2.0e6);
    CHECK(p.stiffness_min == 2.0e4);
    CHECK(p.stiffness_max == 2.0e9);
    CHECK(mass_scaled_penalty(s, {5.0, 2.0}) == p);
    // On the world (or a static body, inverse mass 0, given as 0 kg): the body's own mass, not 0.
    p = mass_scaled_penalty(s, {3.0e6, 0.0});
    CHECK(p.mass == 3.0e6);
    CHECK(p.beta == 3.0e12);
    CHECK(p.stiffness_min == 3.0e10);
    CHECK(p.stiffness_max == 3.0e15);
    // Lighter than a kilogram scales down: 0.25 kg on the world, and under a 4 kg box.
    s.beta = 200.0;
    s.stiffness_min = 8.0;
    s.stiffness_max = 4.0e3;
    CHECK(mass_scaled_penalty(s, {0.0, 0.25}) == PenaltyParameters{0.25, 50.0, 2.0, 1.0e3});
    CHECK(mass_scaled_penalty(s, {0.25, 4.0}) == PenaltyParameters{0.25, 50.0, 2.0, 1.0e3});
    // A 1 kg body on the world, and a contact between two bodies that cannot translate: the settings' own numbers,
    // to the bit.
    for (const std::array<double, 2> mass : {std::array<double, 2>{1.0, 0.0}, std::array<double, 2>{0.0, 0.0}}) {
        CAPTURE(mass[0]);
        CHECK(mass_scaled_penalty(s, mass) == PenaltyParameters{1.0, s.beta, s.stiffness_min, s.stiffness_max});
    }
}

TEST_CASE("a cube of 10^6 kg resting on the ground carries m g after a cold frame as a 1 kg cube does") {
    // docs/methods.md's worked example: four corners exactly the slop into the ground, new contacts at lambda = 0 and
    // k = m k_min (k_min per kg). With M = m/h^2, K = 4k and e = Lambda - m g, iteration n does e <- e M/(M + K) and
    // k <- k + m beta |e/(M + K)|: every term is m times the 1 kg cube's, so e/m, k/m and the move e/(M + K) are the
    // 1 kg cube's. At 4 iterations the force is m g to 4.4e-5 (the first factor 3600/43600 = 0.083, then smaller).
    Scene one;
    formats::apply_setting(one, "preset=avbd", "--set");
    formats::apply_setting(one, "avbd.iterations=4", "--set");
    one.materials[default_material] = Material{0.0, 0.5};
    one.ground = Ground{};
    RigidBody cube;
    cube.inverse_mass = 1.0;
    cube.inverse_inertia_body = box_inverse_inertia(1.0, {0.5, 0.5, 0.5});
    cube.position = {0.0, 0.499, 0.0};
    one.bodies = {cube};
    one.body_names = {"cube"};
    one.shapes = {Shape{Box{{0.5, 0.5, 0.5}}}};
    one.body_materials = {default_material};
    const double m = 1.0e6;
    const AvbdSettings& s = one.settings.avbd;
    double k = m * s.stiffness_min, e = -m * g, last_dy = 0.0;
    const double M = m / (h * h);
    for (int n = 0; n < 4; ++n) {
        last_dy = e / (M + 4.0 * k);
        e *= M / (M + 4.0 * k);
        k = std::min(k + m * s.beta * std::abs(last_dy), m * s.stiffness_max);
    }
    World light(one), heavy(heavier(one, m));
    light.step();
    heavy.step();
    double total = 0.0;
    for (std::ptrdiff_t slot = 0; slot < 4; ++slot) {
        CHECK((*heavy.contact_memory().stiffness_at(slot))[0] == doctest::Approx(k).epsilon(1e-12));
        CHECK((*heavy.contact_memory().stiffness_at(slot))[0] ==
              doctest::Approx(m * (*light.contact_memory().stiffness_at(slot))[0]).epsilon(1e-12));
        total += heavy.contact_memory().impulse_at(slot).y();
    }
    CHECK(total == doctest::Approx(m * g + e).epsilon(1e-9));
    CHECK(std::abs(total - m * g) / (m * g) < 1e-4);
    CHECK(heavy.bodies()[0].velocity.y() == doctest::Approx(last_dy / h).epsilon(1e-9));
    CHECK(heavy.bodies()[0].position.y() == doctest::Approx(light.bodies()[0].position.y()).epsilon(1e-12));
}

TEST_CASE("under AVBD a scene with every mass times 10^6 moves as it did at its own masses") {
    // Multiplying every mass and inertia by s (gravity the same) multiplies every force, lambda, k, H and f by s when
    // beta, k_min and k_max are per kilogram, and leaves each block's move H^-1 f as it was: the same motion, to
    // rounding. With them in N/m, as before, the heavy scene's contacts start 10^6 times too soft and its boxes fall
    // through each other and the ground: measured with 9962abf's program, the largest gap between the two runs'
    // centres over 2 s was 4.67 m (mass_ratio_100), 1.17 m (box_on_slope), 1.52 m (stack_3) and 0.072 m (two_spheres,
    // an impact of 1 kg and 3 kg spheres); with them per kilogram, 0, 1e-18, 0 and 1.1e-16 m.
    for (const char* name : {"mass_ratio_100", "box_on_slope", "stack_3", "two_spheres"}) {
        CAPTURE(name);
        Scene scene = test::shipped(name);
        formats::apply_setting(scene, "preset=avbd", "--set");
        World own(scene), heavy(heavier(scene, 1.0e6));
        double gap = 0.0;
        for (int frame = 0; frame < 120; ++frame) {
            own.step();
            heavy.step();
            gap = std::max(gap, largest_gap(own.bodies(), heavy.bodies()));
        }
        CHECK(gap < 1e-12);
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            CHECK((heavy.bodies()[i].velocity - own.bodies()[i].velocity).norm() < 1e-12);
    }
}
