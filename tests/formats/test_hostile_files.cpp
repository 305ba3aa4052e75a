// Files written to break the readers (issue 29): each case is named after what went wrong before it was held.
// A reader must load what it is given, or refuse it as bad input with the place and the reason, within memory
// and time bounded by the input's limit.

#include "formats/csv.hpp"
#include "formats/input_error.hpp"
#include "formats/input_files.hpp"
#include "formats/input_limits.hpp"
#include "formats/json_text.hpp"
#include "formats/printable_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <fcntl.h>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace impulse;

namespace {

std::string repeated(std::string_view piece, std::size_t times) {
    std::string text;
    text.reserve(piece.size() * times);
    for (std::size_t i = 0; i < times; ++i) text += piece;
    return text;
}

// The shipped ruler case's trace (one contact, one iteration per phase), as a document to break.
formats::json ruler_trace() {
    Trace trace;
    trace.scene = test::shipped("cases/ruler");
    std::vector<RigidBody> bodies = trace.scene.bodies;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, trace.scene.contacts, trace.scene.settings, recorder);
    return formats::trace_json(trace);
}

std::string refusal(const formats::json& document) {
    try {
        formats::read_trace(document);
    } catch (const formats::InputError& e) {
        return e.what();
    }
    return "accepted";
}

}  // namespace

TEST_CASE("megabytes of JSON numbers are refused at the reader's memory cap, not by running out of memory") {
    // 200 MB of "1," aborted the program (SIGABRT at 4 GB): each is a 16-byte value in a vector that doubles.
    // The same document, at a cap 1/1000 of the real one, is refused at the element where the cap is passed.
    const std::string numbers = "[" + repeated("1,", 200'000) + "1]";
    const std::size_t cap = formats::max_json_memory_bytes / 1000;
    CHECK_THROWS_WITH_AS(formats::parse_json_text(numbers, cap), doctest::Contains("of memory"), formats::InputError);
    try {
        formats::parse_json_text(numbers, cap);
    } catch (const formats::InputError& e) {
        CHECK(e.where().starts_with("["));  // the element where it stopped
    }
    CHECK_NOTHROW(formats::parse_json_text(numbers, 32 * 200'001 + 64));  // what it takes, charged as estimated
}

TEST_CASE("a document refused part-way is let go of, nested arrays and objects and all, at any depth") {
    // The part read is emptied deepest first (json_reader.cpp's release) so that no destructor asks for memory;
    // whatever the depth at which the cap is passed, the refusal comes out whole (and the sanitize build finds no
    // leak or bad access).
    std::string nested = "[";
    for (int i = 0; i < 2000; ++i)
        nested += R"({"a": [1, 2, {"b": [[3], {}, []]}], "c": {"d": [4, {"e": "a string longer than fifteen"}]}},)";
    nested += "0]";
    for (const std::size_t cap : {std::size_t{100}, std::size_t{5000}, std::size_t{123457}, std::size_t{900000}}) {
        CAPTURE(cap);
        CHECK_THROWS_WITH_AS(formats::parse_json_text(nested, cap), doctest::Contains("of memory"),
                             formats::InputError);
    }
    CHECK(formats::parse_json_text(nested).size() == 2001);
}

TEST_CASE("empty objects, empty arrays, empty strings and many keys are charged for what they take") {
    const std::size_t cap = 1u << 20;
    for (const std::string piece : {"{},", "[],", "\"\","}) {
        CAPTURE(piece);
        CHECK_THROWS_AS(formats::parse_json_text("[" + repeated(piece, 100'000) + "0]", cap), formats::InputError);
    }
    std::string keys = "{";
    for (int i = 0; i < 100'000; ++i) keys += "\"k" + std::to_string(i) + "\":0,";
    keys += "\"end\":0}";
    CHECK_THROWS_AS(formats::parse_json_text(keys, cap), formats::InputError);
    CHECK_NOTHROW(formats::parse_json_text(keys));
}

TEST_CASE("a key repeated in a large object is found, at its path") {
    std::string keys = "{\"a\": {";
    for (int i = 0; i < 1000; ++i) keys += "\"k" + std::to_string(i) + "\":0,";
    keys += "\"k500\":1}}";
    CHECK_THROWS_WITH_AS(formats::parse_json_text(keys), "a.k500: key given twice in the same object",
                         formats::InputError);
}

TEST_CASE("a number too large for a double is named at its path, inside arrays and objects") {
    CHECK_THROWS_WITH_AS(formats::parse_json_text(R"({"bodies": [{"position": [0, -1e400, 0]}]})"),
                         doctest::Contains("bodies[0].position[1]: invalid JSON: number overflow parsing '-1e400'"),
                         formats::InputError);
}

TEST_CASE("a CSV row of a million commas is refused at the field cap, not held as a million strings") {
    // 200 MB of commas exited 70 (out of memory): every field was a string in one row.
    const std::string text = "kind,path,value\n" + std::string(1'000'000, ',') + "\n";
    CHECK_THROWS_WITH_AS(formats::parse_csv(text), doctest::Contains("line 2: more than 1000 fields in one row"),
                         formats::InputError);
}

TEST_CASE("a CSV cell a spreadsheet would run as a formula is written as text") {
    // =cmd|' /C calc'!A0 went verbatim into cells.csv.
    CHECK(formats::csv_field("=cmd|' /C calc'!A0") == "\"'=cmd|' /C calc'!A0\"");
    CHECK(formats::csv_field("+1+cmd") == "\"'+1+cmd\"");
    CHECK(formats::csv_field("-2+3") == "\"'-2+3\"");
    CHECK(formats::csv_field("@SUM(A1)") == "\"'@SUM(A1)\"");
    CHECK(formats::csv_field("\t=1") == "\"'\t=1\"");
    CHECK(formats::csv_field("\r=1") == "\"'\r=1\"");
    // Numbers stay numbers.
    CHECK(formats::csv_field("-0.5") == "-0.5");
    CHECK(formats::csv_field("-1.5e-07") == "-1.5e-07");
    CHECK(formats::csv_field("+3") == "+3");
    CHECK(formats::csv_field("−(1 + c)·v_s") == "−(1 + c)·v_s");  // U+2212, not a formula
}

TEST_CASE("control characters from a file are escaped before they reach a terminal or split an error line") {
    CHECK(formats::one_line("a\nb") == "a\\nb");
    CHECK(formats::one_line("\x1b[2J\x1b]0;title\x07") == "\\x1b[2J\\x1b]0;title\\x07");
    CHECK(formats::one_line("tab\there\r") == "tab\\there\\r");
    CHECK(formats::one_line("\xc2\x9b"
                            "31m") == "\\u009b31m");  // C1 CSI
    CHECK(formats::one_line("abc\xe2\x80\xaeRTL") == "abc\\u202eRTL");
    CHECK(formats::one_line("\x98") == "\\x98");  // not UTF-8
    CHECK(formats::one_line("Δv = −3 m/s, θ̇") == "Δv = −3 m/s, θ̇");
    CHECK(formats::printable("two\nlines\tand \x1b[31mred") == "two\nlines\tand \\x1b[31mred");
    CHECK(formats::incomplete_tail("ab\xc2") == 1);
    CHECK(formats::incomplete_tail("ab\xe2\x80") == 2);
    CHECK(formats::incomplete_tail("ab\xc2\x9b") == 0);
    CHECK(formats::incomplete_tail("abc") == 0);
}

TEST_CASE("a trace whose iteration numbers do not count 0, 1, 2 is refused by the reader (worksheet crashed on it)") {
    // validate accepted iteration 2147483647 (worksheet then segfaulted) and iteration 1 (exit 70).
    for (const int number : {2147483647, 1, 5}) {
        formats::json t = ruler_trace();
        t["frames"][0]["phases"][0]["iterations"][0]["iteration"] = number;
        CHECK(refusal(t) ==
              "frames[0].phases[0].iterations[0].iteration: must be 0 (iterations are numbered in order "
              "from 0), got " +
                  std::to_string(number));
    }
}

TEST_CASE("a trace whose counts contradict its records is refused") {
    formats::json t = ruler_trace();
    t["frames"][0]["phases"][1]["iterations_used"] = 7;
    CHECK(refusal(t) == "frames[0].phases[1].iterations_used: is 7, but the phase lists 1 iteration");
    // No method lists fewer iterations than it used (AVBD's body visits and dual updates are listed too).
    t = ruler_trace();
    t["frames"][0]["phases"][1]["iterations"] = formats::json::array();
    CHECK(refusal(t) == "frames[0].phases[1].iterations_used: is 1, but the phase lists 0 iterations");

    t = ruler_trace();
    t["frames"][0]["phases"][0]["iteration_limit"] = 0;
    CHECK(refusal(t).starts_with("frames[0].phases[0].iterations_used: is "));

    t = ruler_trace();
    t["frames"][0]["contact_count"] = 3;
    CHECK(refusal(t) ==
          "frames[0].contacts: lists 1 contact, but contact_count is 3 and the recording keeps every "
          "contact");
}

TEST_CASE("a trace with a duplicated or out-of-order frame, or an inverted recording range, is refused") {
    formats::json t = ruler_trace();
    t["frames"].push_back(t["frames"][0]);
    CHECK(refusal(t) ==
          "frames[1].frame: frame 0 comes after frame 0: frames are listed in increasing order, each "
          "once");

    t = ruler_trace();
    t["recording"]["first_frame"] = 3;
    t["recording"]["last_frame"] = 1;
    CHECK(refusal(t) ==
          "recording.last_frame: must be >= first_frame (3), or first_frame - 1 for a recording of no frames, got 1");
    t["frames"] = formats::json::array();
    t["recording"]["last_frame"] = 2;  // the empty range a run stopped before its first recorded frame writes
    CHECK(refusal(t) == "accepted");

    t = ruler_trace();
    t["recording"]["first_frame"] = 1;
    CHECK(refusal(t) == "frames[0].frame: frame 0 is outside the recording's frames 1..");
}

TEST_CASE("a trace whose update names another body than its contact's slot holds is refused") {
    formats::json t = ruler_trace();
    formats::json* update = nullptr;
    for (formats::json& phase : t["frames"][0]["phases"])
        for (formats::json& it : phase["iterations"])
            if (!update && it.contains("updates") && !it["updates"].empty()) update = &it["updates"][0];
    REQUIRE(update != nullptr);
    (*update)["slot"] = 1;  // the ruler's one contact has the world in slot 1
    CHECK(refusal(t).find("but contact 0 has the world in slot 1") != std::string::npos);
}

namespace {

std::string scene_refusal(const std::string& text) {
    try {
        formats::read_scene_text(text);
    } catch (const formats::InputError& e) {
        return e.what();
    }
    return "accepted";
}

std::string sphere_scene(const std::string& body_fields, const std::string& rest = "") {
    return R"({"bodies": [{"name": "ball", "shape": {"type": "sphere", "radius": 0.5}, )" + body_fields + "}]" + rest +
           "}";
}

}  // namespace

TEST_CASE("masses, sizes, normals and lengths whose products overflow or vanish are refused with their range") {
    // A 1e-320 kg mass (m⁻¹ = inf), a 1e-200 m radius (r² = 0) and a [1e308, 1e308, 0] normal (its length inf)
    // were accepted, and the runs then wrote traces validate refuses or lost a contact.
    CHECK(scene_refusal(sphere_scene(R"("mass": 1e-320)")) ==
          "bodies[0].mass: must be from 1e-30 to 1e+30 (the engine multiplies sizes and masses together; outside this "
          "range the products overflow or vanish), got 1e-320");
    CHECK(scene_refusal(R"({"bodies": [{"shape": {"type": "sphere", "radius": 1e-200}}]})")
              .starts_with("bodies[0].shape.radius: must be from 1e-30 to 1e+30"));
    CHECK(scene_refusal(R"({"bodies": [{"shape": {"type": "box", "half_size": [1, 1e31, 1]}}]})")
              .starts_with("bodies[0].shape.half_size[1]: must be from 1e-30 to 1e+30"));
    CHECK(scene_refusal(sphere_scene(R"("inverse_mass": 1e-40)")).starts_with("bodies[0].inverse_mass: must be 0 or "));
    CHECK(scene_refusal(sphere_scene(R"("inverse_mass": 0)")) == "accepted");
    CHECK(scene_refusal(sphere_scene(R"("position": [0, 1e200, 0])"))
              .starts_with("bodies[0].position[1]: must be from "));
    CHECK(scene_refusal(R"({"bodies": [{"inertia": [[1e-100, 0, 0], [0, 1, 0], [0, 0, 1]]}]})")
              .starts_with("bodies[0].inertia[0][0]: must be 0 or from 1e-90 to 1e+90 in size"));
    CHECK(scene_refusal(sphere_scene(R"("mass": 1)", R"(, "contacts": [{"bodies": ["ball", null], "point": [0, 0, 0],
        "normal": [1e308, 1e308, 0]}])"))
              .starts_with("contacts[0].normal[0]: must be from -1e+30 to 1e+30"));
}

TEST_CASE("a frame duration --dt refuses is refused in a file and by --set too") {
    // 5e-324 s was accepted in a file although --dt takes 1e-6 to 10.
    CHECK(scene_refusal(sphere_scene(R"("mass": 1)", R"(, "settings": {"duration": 5e-324})")) ==
          "settings.duration: must be >= 1e-06, got 5e-324");
    Scene scene = formats::read_scene_text(sphere_scene(R"("mass": 1)"));
    CHECK_THROWS_WITH_AS(formats::apply_setting(scene, "duration=5e-324", "--set"),
                         "--set duration: must be >= 1e-06, got 5e-324", formats::InputError);
}

TEST_CASE("a FIFO nobody writes to is refused after its silence limit, not waited on for ever") {
    // `validate`, the lesson list and every `lesson` command hung on a FIFO nobody wrote to.
    test::TempDir dir;
    const std::string fifo = dir.file("silent.fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const auto start = std::chrono::steady_clock::now();
    CHECK_THROWS_AS(formats::read_input_file(fifo, formats::max_input_bytes, std::chrono::milliseconds(300)),
                    formats::FileError);
    try {
        formats::read_input_file(fifo, formats::max_input_bytes, std::chrono::milliseconds(300));
    } catch (const formats::FileError& e) {
        CHECK(e.problem ==
              "nothing arrived within 300 ms: a FIFO or device nobody writes to (start its writer first, "
              "or give a file)");
    }
    CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(5));
}

TEST_CASE("a FIFO is read whole once its writer is done, and a device that never ends at the limit") {
    test::TempDir dir;
    const std::string fifo = dir.file("speaks.fifo").string();
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const pid_t writer = ::fork();
    REQUIRE(writer >= 0);
    if (writer == 0) {
        const int fd = ::open(fifo.c_str(), O_WRONLY);
        const std::string text = "{\"bodies\": []}";
        const timespec pause{0, 200'000'000};  // after the reader has begun to wait
        ::nanosleep(&pause, nullptr);
        const bool whole = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
        ::_exit(whole ? 0 : 1);
    }
    CHECK(formats::read_input_file(fifo, formats::max_input_bytes, std::chrono::milliseconds(5000)) ==
          "{\"bodies\": []}");
    int status = 0;
    ::waitpid(writer, &status, 0);
    CHECK(WEXITSTATUS(status) == 0);
    try {
        formats::read_input_file("/dev/zero", 1 << 20);
        FAIL("/dev/zero was read");
    } catch (const formats::FileError& e) {
        CHECK(e.problem == "goes on past the limit of 1 MiB (1048576 bytes)");
    }
    CHECK(formats::read_input_file("/dev/null").empty());
}
