// Malformed scene files through the program: each rejected with one line naming the JSON path, exit code 2,
// and no output file written.

#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::test;

namespace {

// A case with one valid body and contact, into which each malformed case below changes one thing.
std::string case_with(const std::string& bodies, const std::string& contacts, const std::string& rest = "") {
    return R"({"bodies": )" + bodies + R"(, "contacts": )" + contacts + rest + "}";
}

const std::string ruler_body =
    R"({"name": "ruler", "mass": 1, "shape": {"type": "box", "half_size": [0.5, 0.01, 0.02]}})";
const std::string ground_contact = R"({"bodies": ["ruler", null], "point": [0, 0, 0], "normal": [0, 1, 0]})";

struct Malformed {
    const char* what;
    std::string text;
    std::string message;  // after "impulse-lab: <file>: "
};

}  // namespace

TEST_CASE("malformed cases are rejected with one line naming the path, exit code 2 and no file written") {
    const std::vector<Malformed> table{
        {"negative inverse mass", case_with("[" + ruler_body + R"(, {"name": "b", "inverse_mass": -2}])", "[]"),
         "bodies[1].inverse_mass: must be >= 0, got -2"},
        {"zero mass", case_with(R"([{"mass": 0}])", "[]"), "bodies[0].mass: must be > 0, got 0"},
        {"misspelt field", case_with(R"([{"masss": 1}])", "[]"),
         "bodies[0].masss: unknown field (did you mean \"mass\"?)"},
        {"zero normal",
         case_with("[" + ruler_body + "]", R"([{"bodies": ["ruler", null], "point": [0, 0, 0], "normal": [0, 0, 0]}])"),
         "contacts[0].normal: must not be zero"},
        {"short normal",
         case_with("[" + ruler_body + "]", R"([{"bodies": ["ruler", null], "point": [0, 0, 0], "normal": [0, 1]}])"),
         "contacts[0].normal: must have exactly 3 items, got 2"},
        {"misspelt body name",
         case_with("[" + ruler_body + "]", R"([{"bodies": ["rular", null], "point": [0, 0, 0], "normal": [0, 1, 0]}])"),
         "contacts[0].bodies[0]: no body named \"rular\" (did you mean \"ruler\"?)"},
        {"body index out of range",
         case_with("[" + ruler_body + "]", R"([{"bodies": [0, 3], "point": [0, 0, 0], "normal": [0, 1, 0]}])"),
         "contacts[0].bodies[1]: no body with index 3 (the scene has 1 body, numbered from 0)"},
        {"world against world",
         case_with("[" + ruler_body + "]", R"([{"bodies": [null, null], "point": [0, 0, 0], "normal": [0, 1, 0]}])"),
         "contacts[0].bodies: at least one must be a body (both are the world)"},
        {"body against itself",
         case_with("[" + ruler_body + "]", R"([{"bodies": ["ruler", 0], "point": [0, 0, 0], "normal": [0, 1, 0]}])"),
         "contacts[0].bodies: a body cannot touch itself (both are \"ruler\")"},
        {"non-unit quaternion", case_with(R"([{"inverse_mass": 0, "orientation": [2, 0, 0, 0]}])", "[]"),
         "bodies[0].orientation: must be a unit quaternion [w, x, y, z] (length 1 within 1e-6), got length 2"},
        {"two orientations",
         case_with(R"([{"inverse_mass": 0, "orientation": [1, 0, 0, 0], "orientation_deg": [0, 0, 0]}])", "[]"),
         "bodies[0].orientation_deg: give orientation or orientation_deg, not both"},
        {"indefinite inertia", case_with(R"([{"inertia": [[1, 0, 0], [0, -1, 0], [0, 0, 1]]}])", "[]"),
         "bodies[0].inertia: must be positive definite, but its eigenvalues are -1, 1, 1"},
        {"asymmetric inertia", case_with(R"([{"inertia": [[1, 0.5, 0], [0, 1, 0], [0, 0, 1]]}])", "[]"),
         "bodies[0].inertia: must be symmetric (row i, column j equal to row j, column i)"},
        {"no rotational inertia", case_with(R"([{"name": "a"}])", "[]"),
         "bodies[0]: needs inertia, inverse_inertia or shape: a body with finite mass must resist rotation"},
        {"sphere without radius", case_with(R"([{"shape": {"type": "sphere"}}])", "[]"),
         "bodies[0].shape.radius: missing (a sphere needs a radius)"},
        {"duplicate body name", case_with("[" + ruler_body + ", " + ruler_body + "]", "[]"),
         "bodies[1].name: \"ruler\" is already the name of bodies[0]"},
        {"unknown limit policy",
         case_with("[" + ruler_body + "]", "[]", R"(, "settings": {"angular_limit": {"policy": "huge"}})"),
         "settings.angular_limit.policy: must be one of \"none\", \"fixed\", \"lever_arm\", \"angle\"; got \"huge\""},
        {"angle over 180 degrees",
         case_with("[" + ruler_body + "]", "[]",
                   R"(, "settings": {"angular_limit": {"policy": "angle", "factor": 200}})"),
         "settings.angular_limit.factor: the angle policy's factor is a turn in degrees and must be > 0 and < 180, got "
         "200"},
        {"restitution above 1",
         case_with("[" + ruler_body + "]",
                   R"([{"bodies": ["ruler", null], "point": [0, 0, 0], "normal": [0, 1, 0], "restitution": 1.5}])"),
         "contacts[0].restitution: must be <= 1, got 1.5"},
        {"unknown preset", case_with("[" + ruler_body + "]", "[]", R"(, "settings": {"preset": "fast"})"),
         "settings.preset: must be one of \"book\", \"chapter\", \"sweep\", \"pgs\", \"pgs_split\", \"soft_step\", "
         "\"soft_step_recycled\", \"soft_step_coloured\", \"soft_step_wide\", \"avbd\"; got "
         "\"fast\""},
        {"no bodies list", R"({"contacts": []})", "bodies: missing (required)"},
        {"no bodies", case_with("[]", "[]"), "bodies: must have at least 1 item, got 0"},
        {"a string for a number", case_with(R"([{"inverse_mass": 0, "position": [0, "x", 0]}])", "[]"),
         "bodies[0].position[1]: must be a number, got \"x\""},
        {"a key given twice", case_with(R"([{"inverse_mass": 0, "inverse_mass": 1}])", "[]"),
         "bodies[0].inverse_mass: key given twice in the same object"},
        {"not an object", "[]", "must be an object, got []"},
        {"an unknown material",
         case_with(R"([{"shape": {"type": "sphere", "radius": 1}, "material": "rubbr"}])", "[]",
                   R"(, "materials": {"rubber": {"restitution": 0.8}})"),
         "bodies[0].material: no material named \"rubbr\" (did you mean \"rubber\"?)"},
        {"a zero ground normal", case_with("[" + ruler_body + "]", "[]", R"(, "ground": {"normal": [0, 0, 0]})"),
         "ground.normal: must not be zero"},
        {"an unknown shape", case_with(R"([{"shape": {"type": "cone", "radius": 1}}])", "[]"),
         "bodies[0].shape.type: must be one of \"sphere\", \"box\"; got \"cone\""},
        {"a flat box", case_with(R"([{"shape": {"type": "box", "half_size": [1, 0, 1]}}])", "[]"),
         "bodies[0].shape.half_size[1]: must be from 1e-30 to 1e+30 (the engine multiplies sizes and masses together; "
         "outside this range the products overflow or vanish), got 0"},
        {"inertia given twice",
         case_with(
             R"([{"inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "inverse_inertia": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}])",
             "[]"),
         "bodies[0].inverse_inertia: give inertia or inverse_inertia, not both"},
        {"no frames", case_with("[" + ruler_body + "]", "[]", R"(, "settings": {"frames": 0})"),
         "settings.frames: must be >= 1, got 0"},
        {"friction on a material below zero",
         case_with("[" + ruler_body + "]", "[]", R"(, "materials": {"ice": {"friction": -0.1}})"),
         "materials.ice.friction: must be >= 0, got -0.1"},
        {"a number too large for a double", case_with(R"([{"inverse_mass": 1e999}])", "[]"),
         "bodies[0].inverse_mass: invalid JSON: number overflow parsing '1e999'"},
        {"a number too large for a double in a vector", case_with(R"([{"position": [0, -1e400, 0]}])", "[]"),
         "bodies[0].position[1]: invalid JSON: number overflow parsing '-1e400'"},
        {"broken JSON", "{\n  \"bodies\": [,]\n}",
         "invalid JSON at line 2, column 14: syntax error while parsing value - unexpected ','; expected '[', '{', or "
         "a literal"},
    };
    for (const Malformed& m : table) {
        const std::string what = m.what;
        CAPTURE(what);
        TempDir dir;
        const std::string file = dir.write("case.json", m.text).string();
        const std::string trace = dir.file("out.json").string();
        const CliResult r = run_cli({"resolve", file, "--trace", trace});
        CHECK(r.code == 2);
        CHECK(r.err == "impulse-lab: " + file + ": " + m.message + "\n");
        CHECK(r.out.empty());
        CHECK_FALSE(std::filesystem::exists(trace));
        CHECK(dir.entries() == 1);  // the case file only: no temporary left either
    }
}

TEST_CASE("a file that cannot be read is named in one line with the reason") {
    TempDir dir;
    const std::string missing = dir.file("missing.json").string();
    const CliResult r = run_cli({"resolve", missing});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: " + missing + ": cannot read: No such file or directory\n");
}
