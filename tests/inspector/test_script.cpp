// The inspector's session and its scripted actions: what a case, scene or trace file opens as, re-running
// with a changed setting while keeping the cursor's place, and --script lines parsed, performed and exported
// exactly as the window's keys and buttons do them.

#include "formats/input_error.hpp"
#include "formats/input_files.hpp"
#include "formats/json_text.hpp"
#include "formats/trace_json.hpp"
#include "model/derivation_view.hpp"
#include "model/navigator.hpp"
#include "model/script.hpp"
#include "model/session.hpp"
#include "support/temp_dir.hpp"

#include "support/opened.hpp"
#include "support/read_text.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace impulse;
using namespace impulse::model;

using impulse::test::read_text;

namespace {

using test::opened_session;
using test::ruler;

formats::InputError open_error(const std::string& path, const OpenOptions& options) {
    try {
        Session::open(path, options);
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL(path << " opened");
    return formats::InputError("", "");
}

formats::FileError file_error(const std::string& path) {
    try {
        Session::open(path, {});
    } catch (const formats::FileError& e) {
        return e;
    }
    FAIL(path << " opened");
    return {};
}

formats::InputError script_error(const std::string& text) {
    try {
        parse_script(text);
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("the script parsed:\n" << text);
    return formats::InputError("", "");
}

formats::InputError perform_error(Session& session, const std::string& action, ActionHost* host = nullptr) {
    try {
        perform(session, parse_action(action, 0), "test action", host);
    } catch (const formats::InputError& e) {
        return e;
    }
    FAIL("\"" << action << "\" was performed");
    return formats::InputError("", "");
}

void act(Session& session, const std::string& action, ActionHost* host = nullptr) {
    perform(session, parse_action(action, 0), "test action", host);
}

std::string step_name(const Session& session) {
    return step_tables(session.trace(), *session.cursor())[static_cast<std::size_t>(session.cursor()->step)].step;
}

// Records what the window would have done.
struct RecordingHost : ActionHost {
    std::vector<std::string> screenshots;
    std::vector<std::string> views;
    std::vector<int> lesson_steps;
    std::vector<std::string> keys, typed;
    int quits = 0;
    void screenshot(const std::string& path) override { screenshots.push_back(path); }
    void key(const std::string& chord) override { keys.push_back(chord); }
    void type(const std::string& text) override { typed.push_back(text); }
    void view(const std::string& plane) override { views.push_back(plane); }
    void lesson_step(int step) override { lesson_steps.push_back(step); }
    void quit() override { ++quits; }
};

using impulse::test::contains;

}  // namespace

TEST_CASE("a case file opens as a case, resolved once, with the cursor at its first place") {
    const Session s = opened_session("cases/ruler");
    CHECK(s.kind() == SourceKind::case_file);
    CHECK(s.path() == ruler);
    REQUIRE(s.trace().frames.size() == 1);
    CHECK(s.trace().frames[0].contact_count == 1);
    CHECK(s.cursor() == Cursor{0, Stage::preparation, 0, 0});
    CHECK(s.settings().preset == "book");
}

TEST_CASE("a scene file opens as a scene, simulated for the first second or the frames asked for") {
    // stack_3 runs 600 frames; the inspector opens at most default_inspect_frames of them.
    const Session whole = opened_session("stack_3");
    CHECK(whole.kind() == SourceKind::scene_file);
    CHECK(whole.trace().frames.size() == static_cast<std::size_t>(default_inspect_frames));
    CHECK(whole.trace().scene.world.frames == default_inspect_frames);
    OpenOptions three;
    three.frames = 3;
    const Session short_run = opened_session("stack_3", three);
    CHECK(short_run.kind() == SourceKind::scene_file);
    REQUIRE(short_run.trace().frames.size() == 3);
    CHECK(short_run.trace().frames[2].frame == 2);
    // The first frames of the longer run are the same frames.
    CHECK(short_run.trace().frames[2] == whole.trace().frames[2]);
    // --record frames=A..B keeps only those frames; the cursor starts in the first of them.
    OpenOptions recorded;
    recorded.frames = 3;
    recorded.record = {"frames=1..2"};
    const Session some = opened_session("stack_3", recorded);
    REQUIRE(some.trace().frames.size() == 2);
    CHECK(some.trace().frames[0].frame == 1);
    CHECK(some.cursor() == Cursor{0, Stage::preparation, 0, 0});
}

TEST_CASE("a case is resolved once: --frames is refused") {
    OpenOptions options;
    options.frames = 3;
    const formats::InputError e = open_error(ruler, options);
    CHECK(e.where() == "--frames");
}

TEST_CASE("a trace file opens as the trace it holds, equal value for value") {
    test::TempDir dir;
    const Trace recorded = opened_session("cases/sliding_box").trace();
    const std::string path =
        dir.write("sliding_box.trace.json", formats::format_json(formats::trace_json(recorded))).string();
    const Session s = Session::open(path, {});
    CHECK(s.kind() == SourceKind::trace_file);
    CHECK(s.trace() == recorded);
    CHECK(s.cursor() == first_cursor(recorded));
}

TEST_CASE("a trace is shown as recorded: --set, --preset, --frames and --record are refused naming the flag") {
    test::TempDir dir;
    const std::string path =
        dir.write("ruler.trace.json", formats::format_json(formats::trace_json(opened_session("cases/ruler").trace())))
            .string();
    OpenOptions set;
    set.settings = {"velocity_epsilon=0.5"};
    CHECK(open_error(path, set).where() == "--set");
    OpenOptions preset;
    preset.preset = "chapter";
    CHECK(open_error(path, preset).where() == "--preset");
    OpenOptions frames;
    frames.frames = 2;
    CHECK(open_error(path, frames).where() == "--frames");
    OpenOptions record;
    record.record = {"contacts=0"};
    CHECK(open_error(path, record).where() == "--record");
}

TEST_CASE("a bad file is a file error naming the file and the JSON path of the problem") {
    test::TempDir dir;
    const std::string bad = dir.write("bad.json", R"({
        "bodies": [{"mass": -1}],
        "contacts": [{"bodies": [0, null], "point": [0, 0, 0], "normal": [0, 1, 0]}]})")
                                .string();
    const formats::FileError e = file_error(bad);
    CHECK(e.file == bad);
    CHECK(e.where == "bodies[0].mass");
    CHECK_FALSE(e.problem.empty());
    // Not JSON at all: the whole document.
    const std::string text = dir.write("text.json", "not json").string();
    CHECK(file_error(text).file == text);
    // Missing.
    const std::string missing = dir.file("missing.json").string();
    CHECK(contains(file_error(missing).problem, "cannot read"));
}

TEST_CASE("a bad --set or --record on a case is an input error naming the flag") {
    OpenOptions set;
    set.settings = {"velocity_epsilon"};
    CHECK(open_error(ruler, set).where() == "--set");
    OpenOptions record;
    record.record = {"contacts=4"};  // the ruler has one contact
    CHECK(open_error(ruler, record).where() == "--record");
}

TEST_CASE("a changed setting re-runs the case and keeps the cursor on the same contact and step") {
    Session s = opened_session("cases/ruler");
    const Trace before = s.trace();
    s.move_to({0, Stage::velocity, 0, 3});  // the impulse
    s.set("position_method=linear_projection", "set");
    CHECK(s.settings().position_method == PositionMethod::linear_projection);
    CHECK(s.trace().scene.settings.position_method == PositionMethod::linear_projection);
    // Linear projection moves the ruler without turning it: a different position phase, the same contact.
    CHECK(s.trace() != before);
    CHECK(s.trace().frames[0].position != before.frames[0].position);
    REQUIRE(s.cursor().has_value());
    CHECK(s.cursor()->stage == Stage::velocity);
    CHECK(contact_at(s.trace(), *s.cursor()) == 0);
    CHECK(step_name(s) == "impulse");
}

// Regression: in a phase, a re-run kept the iteration number and ignored the contact, so the cursor could
// stand on another contact although an iteration of the same phase still resolved the old one.
TEST_CASE("a changed setting keeps a phase's cursor on the same contact when an iteration still chooses it") {
    OpenOptions options;
    options.frames = 3;
    Session s = opened_session("stack_3", options);
    s.move_to({1, Stage::velocity, 4, 3});  // frame 1, iteration 4 chose contact 8; its impulse
    REQUIRE(contact_at(s.trace(), *s.cursor()) == 8);
    // Fewer iterations per contact change frame 0's outcome, so frame 1's iterations pick in another order;
    // contact 8 is still chosen by some of them.
    s.set("iterations_per_contact=2", "set");
    const std::vector<VelocityIteration>& its = s.trace().frames[1].velocity.iterations;
    REQUIRE(std::any_of(its.begin(), its.end(), [](const VelocityIteration& it) { return it.contact == 8; }));
    REQUIRE(s.cursor().has_value());
    CHECK(s.cursor()->frame == 1);
    CHECK(s.cursor()->stage == Stage::velocity);
    CHECK(step_name(s) == "impulse");
    CHECK(contact_at(s.trace(), *s.cursor()) == 8);
}

TEST_CASE("a changed setting keeps a prepared contact's place by its contact number") {
    Session s = opened_session("cases/three_objects");
    s.move_to({0, Stage::preparation, 2, 3});  // contact 2's contact_velocity
    s.set("restitution_cutoff=0.5", "set");
    CHECK(s.settings().restitution_cutoff == 0.5);
    CHECK(s.cursor() == Cursor{0, Stage::preparation, 2, 3});
    CHECK(contact_at(s.trace(), *s.cursor()) == 2);
}

TEST_CASE("a bad setting changes nothing and names where it came from") {
    Session s = opened_session("cases/ruler");
    s.move_to({0, Stage::velocity, 0, 2});
    const Trace before = s.trace();
    try {
        s.set("no_such_setting=1", "line 4");
        FAIL("accepted");
    } catch (const formats::InputError& e) {
        // The source of the change, then the setting, as "--set velocity_epsilon" names a flag's part.
        CHECK(e.where() == "line 4 no_such_setting");
    }
    CHECK(s.trace() == before);
    CHECK(s.cursor() == Cursor{0, Stage::velocity, 0, 2});
}

TEST_CASE("a script's lines become actions, skipping blanks and comments and counting every line") {
    const std::vector<Action> actions = parse_script(
        "# look at the ruler\n"
        "\n"
        "next step 3\n"
        "   prev contact\r\n"
        "previous iteration 2\n"
        "next phase\n"
        "prev item 4\n"
        "view top\n"
        "goto frame=0,phase=velocity,step=impulse\n"
        "  # indented comment\n"
        "set velocity_epsilon 0.5\n"
        "screenshot shot.png\n"
        "export trace out.json\n"
        "export table table.csv\n"
        "first\n"
        "last\n"
        "quit");
    REQUIRE(actions.size() == 14);
    CHECK(actions[0].kind == ActionKind::next_step);
    CHECK(actions[0].count == 3);
    CHECK(actions[0].line == 3);
    CHECK(actions[1].kind == ActionKind::previous_contact);
    CHECK(actions[1].count == 1);
    CHECK(actions[1].line == 4);
    CHECK(actions[2].kind == ActionKind::previous_iteration);
    CHECK(actions[2].count == 2);
    CHECK(actions[3].kind == ActionKind::next_phase);
    CHECK(actions[4].kind == ActionKind::previous_item);
    CHECK(actions[4].count == 4);
    CHECK(actions[5].kind == ActionKind::view);
    CHECK(actions[5].argument == "top");
    CHECK(actions[6].kind == ActionKind::go_to);
    CHECK(actions[6].argument == "frame=0,phase=velocity,step=impulse");
    CHECK(actions[6].line == 9);
    CHECK(actions[7].kind == ActionKind::set);
    CHECK(actions[7].argument == "velocity_epsilon=0.5");
    CHECK(actions[7].line == 11);
    CHECK(actions[8].kind == ActionKind::screenshot);
    CHECK(actions[8].argument == "shot.png");
    CHECK(actions[9].kind == ActionKind::export_trace);
    CHECK(actions[9].argument == "out.json");
    CHECK(actions[10].kind == ActionKind::export_table);
    CHECK(actions[10].argument == "table.csv");
    CHECK(actions[11].kind == ActionKind::first);
    CHECK(actions[12].kind == ActionKind::last);
    CHECK(actions[13].kind == ActionKind::quit);
    CHECK(actions[13].line == 17);
    CHECK(parse_script("").empty());
    CHECK(parse_script("# only a comment\n\n").empty());
    // A comment after an action, as the README writes them.
    const std::vector<Action> commented = parse_script("next step 4    # to the desired Δv\ntype 7,5 m/s\t# typed\n");
    REQUIRE(commented.size() == 2);
    CHECK(commented[0].kind == ActionKind::next_step);
    CHECK(commented[0].count == 4);
    CHECK(commented[1].kind == ActionKind::type);
    CHECK(commented[1].argument == "7,5 m/s");
}

TEST_CASE("a line that is not an action is an input error at its line number") {
    const std::vector<std::pair<std::string, std::string>> bad{
        {"next step\njump\n", "line 2"},     // unknown action
        {"next step 0", "line 1"},           // a count from 1
        {"\n\nnext step x", "line 3"},       // not a number
        {"next step 3x", "line 1"},          // not a whole number
        {"next step 1000001", "line 1"},     // above the limit
        {"next sideways", "line 1"},         // nothing to move by
        {"next", "line 1"},                  // missing what to move by
        {"next step 2 3", "line 1"},         // too many words
        {"# fine\ngoto", "line 2"},          // missing spec
        {"goto phase=sideways", "line 1"},   // the spec is checked when parsed
        {"set velocity_epsilon", "line 1"},  // missing value
        {"screenshot", "line 1"},            // missing file
        {"export trace", "line 1"},          // missing file
        {"export picture p.png", "line 1"},  // neither trace nor table
        {"first 2", "line 1"},               // first takes no count
        {"quit now", "line 1"},              // nor does quit
        {"view sideways", "line 1"},         // not a view
        {"view", "line 1"},                  // missing plane
    };
    for (const auto& [text, where] : bad) {
        const auto& script = text;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(script);
        const formats::InputError e = script_error(text);
        CHECK(e.where() == where);
        CHECK_FALSE(e.problem().empty());
    }
    CHECK(contains(script_error("jump").problem(), "unknown action \"jump\""));
    CHECK(contains(script_error("next step 0").problem(), "repeat count"));
    // An action typed outside a script is named as such.
    try {
        parse_action("jump", 0);
        FAIL("accepted");
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "action");
    }
}

TEST_CASE("move actions move the cursor as the navigator does, a count repeating the move") {
    Session s = opened_session("cases/ruler");
    const Trace& t = s.trace();
    act(s, "next step 3");
    CHECK(s.cursor() == Cursor{0, Stage::preparation, 0, 3});
    act(s, "prev step 2");
    CHECK(s.cursor() == Cursor{0, Stage::preparation, 0, 1});
    act(s, "next iteration");
    CHECK(s.cursor() == next_iteration(t, {0, Stage::preparation, 0, 1}));
    CHECK(s.cursor() == Cursor{0, Stage::position, 0, 0});
    act(s, "next phase");
    CHECK(s.cursor() == Cursor{0, Stage::velocity, 0, 0});
    act(s, "next step 3");
    act(s, "prev item");  // from the velocity iteration's impulse to the position iteration, which has none
    CHECK(s.cursor() == Cursor{0, Stage::position, 0, 0});
    act(s, "next item");
    CHECK(s.cursor() == Cursor{0, Stage::velocity, 0, 0});
    act(s, "prev phase");
    CHECK(s.cursor() == Cursor{0, Stage::position, 0, 0});
    act(s, "last");
    CHECK(s.cursor() == last_cursor(t));
    act(s, "first");
    CHECK(s.cursor() == first_cursor(t));
    act(s, "goto phase=velocity,step=impulse");
    CHECK(s.cursor() == Cursor{0, Stage::velocity, 0, 3});
}

TEST_CASE("a move past the end of the trace is an error and leaves the cursor where it was") {
    Session s = opened_session("cases/ruler");
    // 16 tables in all (see the navigator's tests): 15 steps forward reach the last, 16 would leave the trace.
    act(s, "next step 4");
    const Cursor before = *s.cursor();
    const formats::InputError e = perform_error(s, "next step 12");
    CHECK(e.where() == "test action");
    CHECK(contains(e.problem(), "already at the end of the trace"));
    CHECK(s.cursor() == before);
    act(s, "next step 11");
    CHECK(s.cursor() == last_cursor(s.trace()));
    CHECK(perform_error(s, "next contact").where() == "test action");
    CHECK(s.cursor() == last_cursor(s.trace()));
    act(s, "first");
    CHECK(contains(perform_error(s, "prev step").problem(), "already at the start"));
    CHECK(s.cursor() == first_cursor(s.trace()));
}

TEST_CASE("a goto to a place the trace lacks is an error and leaves the cursor where it was") {
    Session s = opened_session("cases/ruler");
    act(s, "next step 2");
    const Cursor before = *s.cursor();
    CHECK(perform_error(s, "goto frame=9").where() == "test action");
    CHECK(s.cursor() == before);
}

TEST_CASE("a set action re-runs the scene with the setting") {
    Session s = opened_session("cases/ruler");
    act(s, "set position_method linear_projection");
    CHECK(s.settings().position_method == PositionMethod::linear_projection);
    CHECK(perform_error(s, "set velocity_epsilon fast").where() == "test action velocity_epsilon");
    CHECK(s.settings().position_method == PositionMethod::linear_projection);
}

TEST_CASE("export trace writes the session's trace, which reads back equal") {
    test::TempDir dir;
    Session s = opened_session("cases/sliding_box");
    const std::filesystem::path file = dir.file("out.trace.json");
    act(s, "export trace " + file.string());
    const std::string text = read_text(file);
    CHECK(text == exported_trace(s));
    CHECK(formats::read_trace_text(text) == s.trace());
    // After a re-run the export is the new trace.
    act(s, "set velocity_epsilon 0.5");
    act(s, "export trace " + file.string());
    CHECK(formats::read_trace_text(read_text(file)) == s.trace());
    CHECK(s.trace().scene.settings.velocity_epsilon == 0.5);
}

TEST_CASE("export table writes the CSV of the derivation table at the cursor") {
    test::TempDir dir;
    Session s = opened_session("cases/ruler");
    act(s, "goto phase=velocity,step=impulse");
    const std::filesystem::path file = dir.file("impulse.csv");
    act(s, "export table " + file.string());
    const std::string text = read_text(file);
    CHECK(text == exported_table(s));
    CHECK(text == derivation_csv(derivation_view(s.trace(), *s.cursor())));
    CHECK(text.rfind("step,quantity,value,exact,other_frame,formula,equation,meaning,changed\n", 0) == 0);
    CHECK(contains(text, "\nimpulse,impulse_world,"));
}

TEST_CASE("an export to a directory that does not exist is an input error and writes nothing") {
    test::TempDir dir;
    Session s = opened_session("cases/ruler");
    const std::string path = dir.file("missing").string() + "/out.csv";
    CHECK(perform_error(s, "export table " + path).where() == "test action");
    CHECK(perform_error(s, "export trace " + path).where() == "test action");
    CHECK(dir.entries() == 0);
}

TEST_CASE("a screenshot, view or quit without a window is an input error") {
    Session s = opened_session("cases/ruler");
    CHECK(perform_error(s, "screenshot shot.png").where() == "test action");
    CHECK(perform_error(s, "view front").where() == "test action");
    CHECK(perform_error(s, "quit").where() == "test action");
    CHECK(s.cursor() == first_cursor(s.trace()));
    // With a window they are passed on to it.
    RecordingHost host;
    act(s, "screenshot shot.png", &host);
    act(s, "view 3d", &host);
    act(s, "quit", &host);
    act(s, "key ctrl+s", &host);
    act(s, "type  7,5 m/s ", &host);
    CHECK(host.screenshots == std::vector<std::string>{"shot.png"});
    CHECK(host.views == std::vector<std::string>{"3d"});
    CHECK(host.quits == 1);
    // The keys go to the window's event queue as typed; a typed text keeps its inner spaces.
    CHECK(host.keys == std::vector<std::string>{"ctrl+s"});
    CHECK(host.typed == std::vector<std::string>{"7,5 m/s"});
    CHECK(perform_error(s, "key Right").problem().starts_with("only the inspector's window"));
}

TEST_CASE("moves and exports of a session with nothing recorded are input errors") {
    // A trace without frames, as a recording whose frame filter matched none of the run would be.
    Trace empty = opened_session("cases/ruler").trace();
    empty.frames.clear();
    Session s = Session::from_trace(empty, SourceKind::trace_file, "empty.json");
    CHECK_FALSE(s.cursor().has_value());
    CHECK(perform_error(s, "next step").where() == "test action");
    try {
        exported_table(s);
        FAIL("exported");
    } catch (const formats::InputError& e) {
        CHECK(e.where() == "export table");
    }
    // first and last have nowhere to go and stay without a cursor.
    act(s, "first");
    CHECK_FALSE(s.cursor().has_value());
}
