// The two ways to a contact's row values (preparation/row_preparation.hpp): read off the full preparation, or
// computed alone when nothing records. Every shipped scene, part way through its motion, under every preset:
// the same values to the bit, with and without steps 4 and 5. (grid_1000 is grid_100's boxes ten times over,
// and would take most of the test's time under the sanitizers: it is left out.)

#include "preparation/row_preparation.hpp"
#include "settings/settings.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <memory_resource>
#include <string>

using namespace impulse;

TEST_CASE("the lean row preparation gives the full preparation's row values, to the bit, for every shipped scene") {
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
                const std::vector<PreparedContact> full =
                    prepare_contacts(detection.contacts, world.bodies(), mass, settings);
                std::pmr::vector<RowPreparation> lean, lean_without_velocity;
                prepare_rows(detection.contacts, world.bodies(), settings, true, lean);
                prepare_rows(detection.contacts, world.bodies(), settings, false, lean_without_velocity);
                REQUIRE(lean.size() == full.size());
                REQUIRE(lean_without_velocity.size() == full.size());
                for (std::size_t k = 0; k < full.size(); ++k) {
                    RowPreparation expected = row_preparation(full[k]);
                    CHECK(lean[k] == expected);
                    // Without steps 4 and 5, v_s is still the prepared one when a method asks for it.
                    CHECK(separating_velocity(lean_without_velocity[k], world.bodies(), settings) ==
                          expected.velocity->separating_velocity);
                    expected.velocity.reset();
                    CHECK(lean_without_velocity[k] == expected);
                    ++compared;
                }
            }
        }
    }
    CHECK(compared > 10000);  // the scenes do touch
}
