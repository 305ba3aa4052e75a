// Scene files: what a minimal case means (its defaults), and a table of malformed cases, each rejected with
// one line naming the JSON path, exit code 2, and no output file written.

#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "math/rotation.hpp"
#include "support/approx.hpp"
#include "support/temp_dir.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace impulse;
using namespace impulse::test;

TEST_CASE("a minimal case fills every default") {
    const Scene c = formats::read_scene_text(R"({
        "bodies": [{"inertia": [[1, 0, 0], [0, 2, 0], [0, 0, 4]]}],
        "contacts": [{"bodies": [0, null], "point": [0, 0, 0], "normal": [0, 2, 0]}]})");
    REQUIRE(c.bodies.size() == 1);
    CHECK(c.body_names[0] == "body0");
    const RigidBody& b = c.bodies[0];
    CHECK(b.position == Vec3::Zero());
    CHECK(b.orientation.coeffs() == Quat::Identity().coeffs());
    CHECK(b.velocity == Vec3::Zero());
    CHECK(b.angular_velocity == Vec3::Zero());
    CHECK(b.last_frame_acceleration == Vec3::Zero());
    CHECK(b.inverse_mass == 1.0);
    CHECK_CLOSE(b.inverse_inertia_body, Vec3(1, 0.5, 0.25).asDiagonal().toDenseMatrix());
    const Contact& contact = c.contacts[0];
    CHECK(contact.normal == Vec3(0, 1, 0));  // normalised on load
    CHECK(contact.penetration == 0.0);
    CHECK(contact.restitution == 0.0);
    CHECK(contact.friction == 0.0);
    CHECK(c.settings == *preset("book"));
}

TEST_CASE("shapes give the exact solid inertia: 2/5 m r^2 for a sphere, m (b^2 + c^2) / 3 for a box") {
    const Scene c = formats::read_scene_text(R"({
        "bodies": [{"mass": 2, "shape": {"type": "sphere", "radius": 0.5}},
                   {"mass": 3, "shape": {"type": "box", "half_size": [1, 0.5, 0.25]}},
                   {"name": "ground", "inverse_mass": 0}],
        "contacts": []})");
    // sphere: I = 0.4 * 2 * 0.25 = 0.2;  box: I = 3 (0.25 + 0.0625)/3, 3 (1 + 0.0625)/3, 3 (1 + 0.25)/3
    CHECK_CLOSE(c.bodies[0].inverse_inertia_body, (Mat3::Identity() / 0.2).eval());
    CHECK_CLOSE(c.bodies[1].inverse_inertia_body, Vec3(1 / 0.3125, 1 / 1.0625, 1 / 1.25).asDiagonal().toDenseMatrix());
    CHECK(is_immovable(c.bodies[2]));
}

TEST_CASE("orientation is [w, x, y, z] and orientation_deg turns about X, then Y, then Z") {
    const Scene c = formats::read_scene_text(R"({
        "bodies": [{"inverse_mass": 0, "orientation": [0.7071067811865476, 0, 0, 0.7071067811865476]},
                   {"inverse_mass": 0, "orientation_deg": [0, 0, 90]},
                   {"inverse_mass": 0, "orientation_deg": [90, 90, 0]}],
        "contacts": []})");
    CHECK_CLOSE(Vec3(c.bodies[0].orientation * Vec3::UnitX()), Vec3(0, 1, 0));
    CHECK_CLOSE(Vec3(c.bodies[1].orientation * Vec3::UnitX()), Vec3(0, 1, 0));
    // X first: y -> z; then Y: z -> x. So body y ends along world x.
    CHECK_CLOSE(Vec3(c.bodies[2].orientation * Vec3::UnitY()), Vec3(1, 0, 0));
}

TEST_CASE("a case written out in full reads back to the same bodies, contacts and settings") {
    const Scene c = formats::read_scene_text(R"({
        "bodies": [{"name": "a", "mass": 2, "orientation_deg": [10, 20, 30], "velocity": [1, 2, 3],
                    "shape": {"type": "box", "half_size": [1, 0.5, 0.25]}},
                   {"name": "b", "mass": 1, "shape": {"type": "sphere", "radius": 0.3}}],
        "contacts": [{"bodies": [null, "a"], "point": [0, 0.1, 0], "normal": [0.3, -1, 0.2], "penetration": 0.01}],
        "settings": {"preset": "chapter", "angular_limit": {"policy": "angle"}, "position_iterations": 7}})");
    const Scene again = formats::read_scene(formats::scene_json(c, true));
    CHECK(again == c);
    CHECK(again.settings.angular_limit.factor == 45.0);
    CHECK(again.settings.position_iterations == 7);
}

TEST_CASE("a scene needs only shapes and positions: every other value is a documented default") {
    const Scene s = formats::read_scene_text(
        R"({"ground": {}, "bodies": [{"shape": {"type": "box", "half_size": [1, 0.5, 0.5]}}]})");
    CHECK(s.world.gravity == Vec3(0, -9.81, 0));
    CHECK(s.world.frames == 600);
    CHECK(s.world.linear_damping == 1.0);
    REQUIRE(s.ground.has_value());
    CHECK(s.ground->plane == HalfSpace{Vec3::UnitY(), 0.0});
    CHECK(s.ground->material == "default");
    CHECK(s.materials.at("default") == Material{0.0, 0.5});
    CHECK(s.body_materials[0] == "default");
    CHECK(std::get<Box>(*s.shapes[0]).half_size == Vec3(1, 0.5, 0.5));
    CHECK(s.bodies[0].inverse_mass == 1.0);
    CHECK_CLOSE(s.bodies[0].inverse_inertia_body, box_inverse_inertia(1.0, Vec3(1, 0.5, 0.5)));
    CHECK(s.contacts.empty());
    CHECK(s.settings.duration == 1.0 / 60.0);
}

TEST_CASE("given inertia overrides the inertia a shape would give, and the shape still collides") {
    const Scene s = formats::read_scene_text(
        R"({"bodies": [{"shape": {"type": "sphere", "radius": 1}, "inertia": [[2, 0, 0], [0, 2, 0], [0, 0, 2]]}]})");
    CHECK(s.shapes[0].has_value());
    CHECK_CLOSE(s.bodies[0].inverse_inertia_body, (Mat3::Identity() * 0.5).eval());
}

TEST_CASE("materials combine by the larger restitution and the geometric mean of friction") {
    const Material m = combine({0.2, 0.9}, {0.6, 0.4});
    CHECK(m.restitution == 0.6);
    CHECK_CLOSE(m.friction, 0.6);  // sqrt(0.9 * 0.4)
    CHECK(combine({0.0, 0.0}, {0.5, 1.0}).friction == 0.0);
}

TEST_CASE("every shipped scene reads, and writes out to a scene that reads back equal") {
    for (const auto& entry : std::filesystem::directory_iterator(IMPULSE_SOURCE_DIR "/scenes")) {
        if (entry.path().extension() != ".json") continue;
        CAPTURE(entry.path().string());
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        const Scene s = formats::read_scene_text(text.str());
        CHECK(formats::read_scene(formats::scene_json(s, true)) == s);
    }
}

TEST_CASE("a scene naming the old position method baumgarte is refused with what replaced it") {
    // Baumgarte's bias became a term of step 5: position_method none with baumgarte true.
    const std::string scene =
        R"({"bodies": [{"shape": {"type": "sphere", "radius": 0.5}}], "settings": {"position_method": "baumgarte"}})";
    try {
        formats::read_scene_text(scene);
        FAIL("read");
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "settings.position_method");
        CHECK(std::string(e.problem()) ==
              "\"baumgarte\" is no longer a position method: Baumgarte's bias is now a term of step 5 (did you "
              "mean \"position_method\": \"none\" with \"baumgarte\": true?)");
    }
    Scene fixed = formats::read_scene_text(
        R"({"bodies": [{"shape": {"type": "sphere", "radius": 0.5}}],
            "settings": {"position_method": "none", "baumgarte": true}})");
    CHECK(fixed.settings.position_method == PositionMethod::none);
    CHECK(fixed.settings.baumgarte);
}

TEST_CASE("a misspelt settings value is told the value it is closest to, a wrong one only the choices") {
    const auto problem = [](const std::string& value) {
        try {
            formats::read_scene_text(
                R"({"bodies": [{"shape": {"type": "sphere", "radius": 0.5}}], "settings": {"sliding_friction": ")" +
                value + R"("}})");
        } catch (const formats::InputError& e) {
            return std::string(e.problem());
        }
        return std::string("read");
    };
    CHECK(problem("agianst_slip") ==
          "must be one of \"reference\", \"against_slip\"; got \"agianst_slip\" (did you mean \"against_slip\"?)");
    CHECK(problem("x") == "must be one of \"reference\", \"against_slip\"; got \"x\"");
}

TEST_CASE("settings added after trace format 1 are written only when they differ from what it implied") {
    // A trace of the book's defaults must stay the bytes older versions wrote (and could read).
    ResolverSettings s = *preset("book");
    const formats::json plain = formats::settings_json(s, WorldSettings{});
    CHECK_FALSE(plain.contains("baumgarte"));
    CHECK_FALSE(plain.contains("sliding_friction"));
    s.baumgarte = true;
    s.sliding_friction = SlidingFriction::against_slip;
    const formats::json changed = formats::settings_json(s, WorldSettings{});
    CHECK(changed["baumgarte"] == true);
    CHECK(changed["sliding_friction"] == "against_slip");
    CHECK(formats::settings_json(*preset("pgs"), WorldSettings{})["baumgarte"] == true);
}

TEST_CASE("a setting added after trace format 1 reads back as written under every preset, on or off") {
    // The reader starts from the preset, so a value the preset sets otherwise must be written even when it is the
    // default: pgs without its Baumgarte term, soft_step_recycled without recycling or its margin.
    for (const std::string_view name : preset_names()) {
        CAPTURE(name);
        const ResolverSettings named = *preset(name);
        std::vector<ResolverSettings> variants(6, named);
        variants[0].baumgarte = !named.baumgarte;
        variants[1].sliding_friction = named.sliding_friction == SlidingFriction::reference
                                           ? SlidingFriction::against_slip
                                           : SlidingFriction::reference;
        variants[2].soft_step.order =
            named.soft_step.order == SolveOrder::contacts ? SolveOrder::colours : SolveOrder::contacts;
        variants[3].recycling =
            named.recycling == RecyclingSettings{} ? RecyclingSettings{0.05, 0.1} : RecyclingSettings{};
        variants[4].speculative_margin = named.speculative_margin == 0.0 ? 0.02 : 0.0;
        for (std::size_t v = 0; v < variants.size(); ++v) {
            CAPTURE(v);
            const formats::json written = formats::settings_json(variants[v], WorldSettings{});
            Scene read_back;
            formats::read_settings(read_back, &written, "settings");
            CHECK(read_back.settings == variants[v]);
        }
    }
}
