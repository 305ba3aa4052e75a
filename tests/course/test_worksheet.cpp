// Worksheets: which derivation step computes which trace key (the one table, checked against every key the
// shipped cases write under every method), the inputs and cells of a step, the places --steps names, the
// files `impulse-lab worksheet` writes, and the paths and CSV they are written in.

#include "course/course_schemas.hpp"
#include "course/json_path.hpp"
#include "course/step_keys.hpp"
#include "course/worksheet.hpp"
#include "formats/csv.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_json.hpp"
#include "model/navigator.hpp"

#include "support/opened.hpp"
#include "support/read_text.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

using namespace impulse;
using namespace impulse::course;
using impulse::test::opened;
using impulse::test::opened_session;
using impulse::test::read_text;

namespace {

using impulse::test::cases;

// Every key of an item object in StepKey's form: nested keys joined by '.', "[]" after an array of objects.
void collect_keys(const formats::json& object, const std::string& prefix, std::set<std::string>& keys) {
    for (auto it = object.begin(); it != object.end(); ++it) {
        const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
        const formats::json& value = it.value();
        if (value.is_object()) {
            collect_keys(value, key, keys);
        } else if (value.is_array() && !value.empty() && value[0].is_object()) {
            for (const formats::json& element : value) collect_keys(element, key + "[]", keys);
        } else {
            keys.insert(key);
        }
    }
}

// The shipped cases under every position method and both presets, and three frames of a scene: between
// them every optional key (rewind, pass, angular_limit, friction_solve, sliding_direction, updates) appears.
std::vector<Trace> every_kind_of_trace() {
    std::vector<Trace> traces;
    for (const char* name :
         {"ruler", "sphere_ground", "three_objects", "two_body_oblique", "sliding_box", "deep_corner"})
        for (const char* method : {"nonlinear_projection", "linear_projection", "velocity_based", "relaxation"}) {
            model::OpenOptions options;
            options.settings = {std::string("position_method=") + method};
            traces.push_back(opened(std::string("cases/") + name, options));
            options.preset = "chapter";
            traces.push_back(opened(std::string("cases/") + name, options));
        }
    model::OpenOptions scene;
    scene.frames = 3;
    traces.push_back(opened("box_tipping", scene));
    // The sweeping methods' words: sweeps, accumulated totals, the split impulse's push, Baumgarte's bias.
    for (const char* preset : {"sweep", "pgs", "pgs_split", "soft_step"}) {
        model::OpenOptions options;
        options.preset = preset;
        traces.push_back(opened("cases/tilted_box", options));
        options.settings = {"baumgarte=true"};
        traces.push_back(opened("cases/tilted_box", options));
    }
    // A recycled contact between two boxes: each body touched at its own anchor (body1_point).
    model::OpenOptions recycled;
    recycled.preset = "soft_step_recycled";
    recycled.frames = 3;
    traces.push_back(opened("stack_3", recycled));
    // AVBD's body visits and dual updates.
    model::OpenOptions avbd;
    avbd.preset = "avbd";
    traces.push_back(opened("cases/tilted_box", avbd));
    return traces;
}

std::vector<std::string> quantities(const std::vector<WorksheetEntry>& entries) {
    std::vector<std::string> names;
    for (const WorksheetEntry& e : entries) names.push_back(e.quantity);
    return names;
}

bool has(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

TEST_CASE("every key a trace writes into a contact or an iteration belongs to a derivation step") {
    std::set<std::string> seen[3];
    for (const Trace& trace : every_kind_of_trace()) {
        const formats::json document = formats::trace_json(trace);
        for (const formats::json& frame : document["frames"]) {
            for (const formats::json& contact : frame["contacts"]) collect_keys(contact, "", seen[0]);
            for (const formats::json& phase : frame["phases"])
                for (const formats::json& iteration : phase["iterations"])
                    collect_keys(iteration, "", seen[phase["phase"] == "position" ? 1 : 2]);
        }
    }
    const ItemKind kinds[3] = {ItemKind::contact, ItemKind::position_iteration, ItemKind::velocity_iteration};
    for (int k = 0; k < 3; ++k) {
        CHECK(seen[k].size() > 10);
        for (const std::string& key : seen[k]) {
            CAPTURE(k);
            CAPTURE(key);
            if (key == "updates") continue;  // an empty list (a sweep that keeps no updates) holds no keys
            CHECK(find_step_key(kinds[k], key) != nullptr);
        }
    }
    // And the table names nothing a trace never writes: each of its keys was seen.
    for (const StepKey& key : step_keys()) {
        CAPTURE(key.key);
        CHECK(seen[static_cast<int>(key.item)].count(std::string(key.key)) == 1);
    }
}

TEST_CASE("every step of the inspector's tables has its cells in the table, and every key says what it means") {
    std::set<std::string> steps[3];
    for (const Trace& trace : every_kind_of_trace())
        for (std::optional<model::Cursor> c = model::first_cursor(trace); c; c = model::next_step(trace, *c)) {
            const auto tables = model::step_tables(trace, *c);
            const int kind = c->stage == model::Stage::preparation ? 0 : c->stage == model::Stage::position ? 1 : 2;
            steps[kind].insert(tables[static_cast<std::size_t>(c->step)].step);
        }
    for (const StepKey& key : step_keys()) {
        CAPTURE(key.key);
        if (key.role == Role::computed || key.role == Role::setting)
            CHECK(steps[static_cast<int>(key.item)].count(std::string(key.step)) == 1);
        if (key.role == Role::computed || key.role == Role::given || key.role == Role::setting)
            CHECK_FALSE(describe_key(key).meaning.empty());
    }
    for (int k = 0; k < 3; ++k)
        for (const std::string& step : steps[k]) {
            // The velocity phase's choice only names the contact and its epsilon, both given. AVBD's constraint is
            // given (read at the positions the visit starts from); its block, the solve and the stiffness update
            // are shown, not put on worksheets (docs/coursework.md): a worksheet does not give the bodies' mass
            // blocks nor the other gathered contacts' rows they are made from.
            if (k == 2 && (step == "choice" || step == "constraint" || step == "block_matrix" ||
                           step == "block_force" || step == "position_change"))
                continue;
            const bool computed = std::any_of(step_keys().begin(), step_keys().end(), [&](const StepKey& key) {
                return static_cast<int>(key.item) == k && key.role == Role::computed && key.step == step;
            });
            CAPTURE(step);
            CHECK(computed);
        }
    for (const OutsideKey& key : outside_keys()) CHECK_FALSE(describe_outside(key).meaning.empty());
}

TEST_CASE("a worksheet step's cells are the values it computes and its inputs what it starts from") {
    const model::Session session = opened_session("cases/ruler");
    const std::vector<model::Cursor> places =
        places_from_specs(session.trace(), {"phase=velocity,iteration=0,step=impulse"}, "--steps");
    REQUIRE(places.size() == 1);
    const Worksheet sheet = make_worksheet(session, places);
    REQUIRE(sheet.steps.size() == 1);
    const WorksheetStep& step = sheet.steps[0];
    CHECK(step.at == "frame=0,phase=velocity,iteration=0,step=impulse");
    CHECK(step.place == "frame 0 · velocity phase · iteration 0 · contact 0 · impulse");
    CHECK(quantities(step.cells) == std::vector<std::string>{"impulse_model", "impulse", "impulse_world"});
    const WorksheetEntry& g = step.cells[1];
    CHECK(g.path == "frames[0].phases[1].iterations[0].impulse");
    CHECK(g.step == "impulse");
    CHECK(g.unit == "N·s");
    CHECK(g.equation == "(14.3)");
    CHECK(g.value.size() == 3);
    // What g = Δv / d needs: the desired Δv this iteration computed, and d from the contact's preparation.
    const std::vector<std::string> given = quantities(step.inputs);
    for (const char* name : {"iteration", "contact", "epsilon", "desired_delta_velocity", "contact_velocity",
                             "contacts[0].delta_velocity_per_unit_impulse", "contacts[0].basis",
                             "contacts[0].relative_position[0]", "scene.bodies[0].inverse_mass"})
        CHECK_MESSAGE(has(given, name), name);
    const auto d = std::find_if(step.inputs.begin(), step.inputs.end(), [](const WorksheetEntry& e) {
        return e.quantity == "contacts[0].delta_velocity_per_unit_impulse";
    });
    REQUIRE(d != step.inputs.end());
    CHECK(d->path == "frames[0].contacts[0].delta_velocity_per_unit_impulse");
    CHECK(d->value.get<double>() == doctest::Approx(31.97459493082857));
    // Nothing the step computes, and nothing of later steps, is given.
    for (const char* name : {"impulse_world", "velocity_change[0]", "updates[0].after"}) CHECK_FALSE(has(given, name));
}

TEST_CASE("a value asked for on the worksheet is not given away as another step's input") {
    const model::Session session = opened_session("cases/ruler");
    const Worksheet sheet = make_worksheet(session, default_places(session.trace()));
    std::set<std::string> cells;
    for (const WorksheetStep& s : sheet.steps)
        for (const WorksheetEntry& e : s.cells) CHECK(cells.insert(e.path).second);
    for (const WorksheetStep& s : sheet.steps)
        for (const WorksheetEntry& e : s.inputs) CHECK_MESSAGE(cells.count(e.path) == 0, e.path);
    // The velocity iteration's impulse is on the sheet with the preparation's d, so d is a cell, not an input.
    CHECK(cells.count("frames[0].contacts[0].delta_velocity_per_unit_impulse") == 1);
}

TEST_CASE("the default worksheet has every step with something to fill in of the first frame, in trace order") {
    const Trace trace = opened("cases/ruler");
    const std::vector<model::Cursor> places = default_places(trace);
    std::vector<std::string> names;
    for (const model::Cursor& c : places)
        names.push_back(model::step_tables(trace, c)[static_cast<std::size_t>(c.step)].step);
    // The ruler: one contact, one position iteration, one velocity iteration (whose choice is all given).
    CHECK(names == std::vector<std::string>{"basis", "relative_position", "delta_velocity_per_unit_impulse",
                                            "contact_velocity", "desired_delta_velocity", "choice",
                                            "penetration_inertia", "move_split", "position_change", "updates",
                                            "contact_velocity", "desired_delta_velocity", "impulse", "velocity_change",
                                            "updates"});
    CHECK(std::is_sorted(places.begin(), places.end(),
                         [](const model::Cursor& a, const model::Cursor& b) { return a.frame < b.frame; }));
}

TEST_CASE("a --steps place without step= takes every step of its item that computes something") {
    const Trace trace = opened("cases/sliding_box");
    const auto all = places_from_specs(trace, {"phase=preparation,contact=2"}, "--steps");
    CHECK(all.size() == 5);
    for (const model::Cursor& c : all) CHECK(model::contact_at(trace, c) == 2);
    const auto one = places_from_specs(trace, {"phase=velocity,iteration=1,step=impulse_world"}, "--steps");
    REQUIRE(one.size() == 1);
    CHECK(model::step_tables(trace, one[0])[static_cast<std::size_t>(one[0].step)].step == "impulse");
}

TEST_CASE("a step that computes nothing cannot be put on a worksheet") {
    const Trace trace = opened("cases/ruler");
    try {
        places_from_specs(trace, {"phase=velocity,iteration=0,step=choice"}, "--steps");
        FAIL("expected an error");
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "--steps");
        CHECK(e.problem() ==
              "\"phase=velocity,iteration=0,step=choice\": step choice computes nothing to fill in "
              "(steps that do here: contact_velocity, desired_delta_velocity, impulse, "
              "velocity_change, updates)");
    }
    CHECK_THROWS_AS(places_from_specs(trace, {"phase=velocity,iteration=7"}, "--steps"), formats::InputError);
}

TEST_CASE("worksheet writes JSON that its schema accepts, with every cell blank") {
    test::TempDir dir;
    const std::string out = dir.file("sheet.json").string();
    const test::CliResult r = test::run_cli({"worksheet", cases + "ruler.json", "--out", out});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
    // A JSON sheet lists each step's inputs with the step: 189 entries over the 15 steps.
    CHECK(r.out == "worksheet written to " + out +
                       ": 15 steps, 47 cells (89 numbers to fill in), 189 inputs given over its steps\n");
    const formats::json sheet = formats::parse_json_text(read_text(out));
    CHECK_NOTHROW(course::validate_worksheet_document(sheet));
    CHECK(sheet["format"] == "impulse-lab-worksheet");
    CHECK(sheet["settings"]["preset"] == "book");
    CHECK(sheet["reference"]["run"]["mode"] == "resolve");
    for (const formats::json& step : sheet["steps"])
        for (const formats::json& cell : step["cells"])
            for_each_scalar(cell["value"], "", [](const std::string&, const formats::json& v) { CHECK(v.is_null()); });
    // A vector cell keeps its shape.
    CHECK(sheet["steps"][1]["cells"][0]["value"] == formats::json::array({nullptr, nullptr, nullptr}));
}

TEST_CASE("worksheet writes CSV with one row per number, each input once") {
    test::TempDir dir;
    const std::string out = dir.file("sheet.csv").string();
    const test::CliResult r = test::run_cli({"worksheet", cases + "ruler.json", "--out", out, "--steps",
                                             "phase=velocity,iteration=0,step=impulse", "--steps",
                                             "phase=velocity,iteration=0,step=velocity_change"});
    CHECK(r.code == 0);
    const std::vector<formats::CsvRow> rows = formats::parse_csv(read_text(out));
    REQUIRE(rows.size() > 1);
    CHECK(formats::csv_row(rows[0].fields) == std::string(worksheet_csv_header) + "\n");
    std::size_t cells = 0;
    std::set<std::string> paths;
    for (auto row = rows.begin() + 1; row != rows.end(); ++row) {
        REQUIRE(row->fields.size() == 9);
        CHECK(paths.insert(row->fields[1]).second);
        if (row->fields[0] == "cell") {
            ++cells;
            CHECK(row->fields[4].empty());
        } else {
            CHECK(row->fields[0] == "input");
            CHECK_FALSE(row->fields[4].empty());
        }
    }
    // impulse_model, impulse (3), impulse_world (3); then torque, velocity and rotation change of body 0.
    CHECK(cells == 1 + 3 + 3 + 3 * 3);
    CHECK(paths.count("frames[0].phases[1].iterations[0].impulse_world[1]") == 1);
    CHECK(paths.count("frames[0].contacts[0].delta_velocity_per_unit_impulse") == 1);
}

TEST_CASE("a worksheet's reference re-runs to the trace it was made from") {
    for (const char* name : {"cases/ruler", "cases/sliding_box", "box_tipping"}) {
        model::OpenOptions options;
        if (std::string(name) == "box_tipping") {
            // Three frames simulated, the second recorded: the run's length is what must be kept.
            options.frames = 3;
            options.record = {"frames=1..1"};
        }
        const model::Session session = opened_session(name, options);
        const Worksheet sheet = make_worksheet(session, default_places(session.trace()));
        CAPTURE(name);
        CHECK(rerun_reference(worksheet_json(sheet)) == session.trace());
    }
}

TEST_CASE("worksheet refuses a bad --out or --steps in one line, exit code 2 and no file") {
    test::TempDir dir;
    const std::string ruler = cases + "ruler.json";
    const std::vector<std::pair<std::vector<std::string>, std::string>> table{
        {{"worksheet", ruler, "--out", dir.file("sheet.txt").string()},
         "impulse-lab: --out: must end in .json or .csv (or be - for standard output), got \"" +
             dir.file("sheet.txt").string() + "\""},
        {{"worksheet", ruler, "--out", dir.file("no/dir/s.csv").string()},
         "impulse-lab: --out: cannot write '" + dir.file("no/dir/s.csv").string() + "': No such file or directory"},
        {{"worksheet", ruler, "--out", dir.file("s.csv").string(), "--steps", "phase=sideways"},
         "impulse-lab: --steps: phase must be preparation, position or velocity, got \"sideways\""},
        {{"worksheet", ruler, "--out", dir.file("s.csv").string(), "--steps", "frame=3"},
         "impulse-lab: --steps: frame 3 is not in the trace (recorded frames: 0..0)"},
        {{"worksheet", dir.file("missing.json").string(), "--out", dir.file("s.csv").string()},
         "impulse-lab: " + dir.file("missing.json").string() + ": cannot read: No such file or directory"},
        {{"worksheet", ruler}, "impulse-lab: --out is required"},
    };
    for (const auto& [args, starts] : table) {
        const auto& expected = starts;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(expected);
        const test::CliResult r = test::run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err.rfind(starts, 0) == 0);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(r.out.empty());
    }
    CHECK(dir.entries() == 0);
}

TEST_CASE("a path reads back as json_path_child and json_path_index wrote it") {
    using formats::json_path_child, formats::json_path_index;
    const std::string path = json_path_index(
        json_path_child(
            json_path_index(json_path_child(json_path_index(json_path_child(json_path_index("frames", 0), "phases"), 1),
                                            "iterations"),
                            12),
            "impulse_world"),
        1);
    CHECK(path == "frames[0].phases[1].iterations[12].impulse_world[1]");
    const auto tokens = parse_json_path(path, "here");
    REQUIRE(tokens.size() == 8);
    CHECK(std::get<std::string>(tokens[0]) == "frames");
    CHECK(std::get<std::size_t>(tokens[5]) == 12);
    CHECK(std::get<std::size_t>(tokens[7]) == 1);
    for (const char* bad : {"", "frames[", "frames[x]", ".frames", "frames..x", "frames[0]x", "frames.", "a b"}) {
        CAPTURE(bad);
        CHECK_THROWS_AS(parse_json_path(bad, "here"), formats::InputError);
    }
    const formats::json document = formats::json::parse(R"({"a": {"b": [1, [2, 3]]}, "c": 4})");
    CHECK(*value_at(document, parse_json_path("a.b[1][0]", "")) == 2);
    CHECK(value_at(document, parse_json_path("a.b[2]", "")) == nullptr);
    CHECK(value_at(document, parse_json_path("c.d", "")) == nullptr);
    // Trace order: c after a, however the paths spell it.
    CHECK(document_position(document, parse_json_path("a.b[1][1]", "")) <
          document_position(document, parse_json_path("c", "")));
}

TEST_CASE("CSV fields round trip through quoting, CRLF line ends and a byte-order mark") {
    const std::vector<std::string> fields{"plain", "a, b", "say \"hi\"", "two\nlines", ""};
    const std::string text = "\xEF\xBB\xBF" + formats::csv_row(fields) + "x,y\r\n\r\nz\n";
    const std::vector<formats::CsvRow> rows = formats::parse_csv(text);
    REQUIRE(rows.size() == 3);
    CHECK(rows[0].fields == fields);
    CHECK(rows[1].line == 3);
    CHECK(rows[1].fields == std::vector<std::string>{"x", "y"});
    CHECK(rows[2].line == 5);
    CHECK_THROWS_AS(formats::parse_csv("a,\"open\n"), formats::InputError);
    CHECK_THROWS_AS(formats::parse_csv("\"closed\"x\n"), formats::InputError);
}

TEST_CASE("velocity_from_acceleration is given what it needs: the frame's duration and each body's last acceleration") {
    const model::Session session = opened_session("cases/desired_velocity");
    const Worksheet sheet = make_worksheet(
        session,
        places_from_specs(session.trace(), {"phase=preparation,contact=2,step=desired_delta_velocity"}, "--steps"));
    REQUIRE(sheet.steps.size() == 1);
    const auto input = [&](const std::string& path) {
        for (const WorksheetEntry& e : sheet.steps[0].inputs)
            if (e.path == path) return e.value;
        FAIL("no input " << path);
        return formats::json();
    };
    // 'landing' (body 2) was accelerated by (0, −9.81, 0) m/s² for one frame of 1/60 s against the ground
    // (body 1, the world): (a₀ − a₁)·n·Δt = −9.81 · 1 / 60 = −0.1635 m/s, which the trace records.
    const double duration = input("settings.duration").get<double>();
    const formats::json a = input("scene.bodies[2].last_frame_acceleration");
    CHECK(duration == doctest::Approx(1.0 / 60));
    CHECK(a == formats::json::array({0.0, -9.81, 0.0}));
    CHECK(a[1].get<double>() * duration == doctest::Approx(-0.1635));
    CHECK(input("frames[0].contacts[2].contact_velocity") == formats::json::array({-3.0, 0.0, 0.0}));
}

TEST_CASE("a simulated frame gives gravity as the last acceleration of every body that can move") {
    model::OpenOptions options;
    options.frames = 4;
    options.record = {"frames=3..3"};
    const model::Session session = opened_session("stack_3", options);
    const Worksheet sheet = make_worksheet(
        session, places_from_specs(session.trace(), {"phase=preparation,contact=0,step=contact_velocity"}, "--steps"));
    const std::vector<std::string> given = quantities(sheet.steps.at(0).inputs);
    CHECK(has(given, "scene.gravity"));
    CHECK(has(given, "settings.duration"));
    CHECK(has(given, "settings.tangential_acceleration_velocity"));
    CHECK_FALSE(has(given, "scene.bodies[0].last_frame_acceleration"));  // the file's start, not this frame's
}

TEST_CASE("an update starts from the value before it, which is not given when the sheet asks for it elsewhere") {
    const model::Session session = opened_session("cases/ruler");
    const Trace& trace = session.trace();
    // The velocity iteration's updates alone: the contact's velocity before the impulse is the iteration's own
    // contact_velocity, given at that path (and no longer as a copy under updates[0].before).
    const Worksheet alone =
        make_worksheet(session, places_from_specs(trace, {"phase=velocity,iteration=0,step=updates"}, "--steps"));
    const std::vector<std::string> given = quantities(alone.steps.at(0).inputs);
    CHECK(has(given, "contact_velocity"));
    CHECK(has(given, "desired_delta_velocity"));
    CHECK_FALSE(has(given, "updates[0].before"));
    CHECK_FALSE(has(given, "updates[0].desired_delta_velocity_before"));
    // With the iteration's contact_velocity step on the sheet too, the student starts from their own answer.
    const Worksheet both = make_worksheet(
        session,
        places_from_specs(
            trace, {"phase=velocity,iteration=0,step=contact_velocity", "phase=velocity,iteration=0,step=updates"},
            "--steps"));
    for (const WorksheetEntry& e : both.steps.at(1).inputs)
        CHECK(e.path != "frames[0].phases[1].iterations[0].contact_velocity");
}
