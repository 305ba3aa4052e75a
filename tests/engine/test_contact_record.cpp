// A contact is prepared once, with only the values the methods resolve with (preparation/prepared_contact.hpp);
// its record, every intermediate of steps 1-5, is derived apart, only when a recorder keeps the frame
// (record/contact_record.hpp), by the same functions. Every shipped scene, part way through its motion, under
// every preset with and without Baumgarte's term: the record holds the prepared values, to the bit. (grid_1000 is
// grid_100's boxes ten times over, and would take most of the test's time under the sanitizers: it is left out.)

#include "preparation/bookkeeping.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/contact_record.hpp"
#include "settings/settings.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <memory_resource>
#include <string>

using namespace impulse;

namespace {

// The prepared contact's values as the record keeps them.
void check_same(const PreparedContact& p, const ContactPreparation& d, const ResolverSettings& settings) {
    CHECK(p.contact == d.contact);
    CHECK(p.bodies == d.bodies);
    CHECK(p.swapped == d.swapped);
    CHECK(p.origin == d.origin);
    CHECK(p.inert == d.inert);
    CHECK(p.penetration == d.penetration);
    CHECK(p.restitution == d.restitution);
    CHECK(p.friction == d.friction);
    CHECK(p.basis == d.basis);
    for (int i = 0; i < 2; ++i) CHECK(p.relative_position[i] == d.relative_position[i].value_or(Vec3::Zero()));
    CHECK(p.delta_velocity_per_unit_impulse == d.unit_impulse_chain.delta_velocity_per_unit_impulse);
    CHECK(p.contact_velocity == d.velocity_terms.contact_velocity);
    CHECK(p.desired_delta_velocity == d.desired_terms.desired_delta_velocity);
    CHECK(desired_again(p, velocity_refinements(settings)) == d.desired_terms);
    // PGS's slip offset: step 4's tangential acceleration terms, body 0's minus body 1's, from 0.
    std::array<double, 2> tangential{0.0, 0.0};
    for (int i = 0; i < 2; ++i) {
        const Vec3 term = d.velocity_terms.tangential_acceleration_velocity[i].value_or(Vec3::Zero());
        tangential[0] += body_sign(i) * term.y();
        tangential[1] += body_sign(i) * term.z();
    }
    CHECK(p.tangential_acceleration_velocity == tangential);
}

}  // namespace

TEST_CASE("a contact's record of steps 1-5 holds the values it was prepared with, to the bit, in every scene") {
    int compared = 0;
    for (const auto& entry : std::filesystem::directory_iterator(IMPULSE_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        if (name == "grid_1000") continue;
        CAPTURE(name);
        const Scene scene = test::shipped(name);
        World world(scene);
        for (int frame = 0; frame < 25; ++frame) world.step();  // moving, touching, with last frame's acceleration
        const Detection detection = detect_contacts(scene, world.bodies());
        const std::vector<MassProperties> mass = mass_properties(world.bodies());
        for (const std::string_view preset_name : preset_names()) {
            CAPTURE(preset_name);
            ResolverSettings settings = *preset(preset_name);
            for (const bool baumgarte : {false, true}) {
                settings.baumgarte = baumgarte;
                std::pmr::vector<PreparedContact> prepared;
                prepare_contacts(detection.contacts, world.bodies(), mass, settings, prepared);
                REQUIRE(prepared.size() == detection.contacts.size());
                for (std::size_t k = 0; k < prepared.size(); ++k) {
                    check_same(
                        prepared[k],
                        contact_preparation(static_cast<int>(k), detection.contacts[k], world.bodies(), mass, settings),
                        settings);
                    ++compared;
                }
            }
        }
    }
    CHECK(compared > 10000);  // the scenes do touch
}

TEST_CASE("prepared for soft step, a contact keeps steps 1 to 4 to the bit and leaves step 5 unset") {
    // Soft step reads steps 1-3 and step 4's v_s (the normal velocity it bounces from): those are the whole
    // preparation's, to the bit; step 4's tangential refinement and step 5 are left out (NaN, or no Baumgarte term).
    int compared = 0;
    for (const std::string name : {"sphere_drop", "pyramid_20", "box_on_slope", "mass_ratio_1000"}) {
        CAPTURE(name);
        const Scene scene = test::shipped(name);
        World world(scene);
        for (int frame = 0; frame < 25; ++frame) world.step();
        const Detection detection = detect_contacts(scene, world.bodies());
        const std::vector<MassProperties> mass = mass_properties(world.bodies());
        ResolverSettings settings = *preset("soft_step");
        settings.baumgarte = true;
        std::pmr::vector<PreparedContact> whole, soft;
        prepare_contacts(detection.contacts, world.bodies(), mass, settings, whole);
        prepare_contacts(detection.contacts, world.bodies(), mass, settings, soft, Preparation::steps_1_to_4);
        REQUIRE(soft.size() == whole.size());
        for (std::size_t k = 0; k < soft.size(); ++k) {
            const PreparedContact &p = soft[k], &w = whole[k];
            CHECK(p.contact == w.contact);
            CHECK(p.bodies == w.bodies);
            CHECK(p.swapped == w.swapped);
            CHECK(p.origin == w.origin);
            CHECK(p.inert == w.inert);
            CHECK(p.penetration == w.penetration);
            CHECK(p.restitution == w.restitution);
            CHECK(p.friction == w.friction);
            CHECK(p.basis == w.basis);
            CHECK(p.relative_position == w.relative_position);
            CHECK(p.delta_velocity_per_unit_impulse == w.delta_velocity_per_unit_impulse);
            CHECK(p.contact_velocity.x() == w.contact_velocity.x());
            CHECK(std::isnan(p.desired_delta_velocity));
            CHECK(std::isnan(p.velocity_from_acceleration));
            CHECK(std::isnan(p.tangential_acceleration_velocity[0]));
            CHECK_FALSE(p.position_bias.has_value());
            CHECK(w.position_bias.has_value());
            ++compared;
        }
    }
    CHECK(compared > 100);
}
