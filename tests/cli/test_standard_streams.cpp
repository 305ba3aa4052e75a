// "-" as a file argument: standard input for a file read, standard output for one written. When standard output
// carries a file nothing else goes there, and at most one argument of a command is "-" in each direction.

#include "formats/json_text.hpp"
#include "support/read_text.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/standard_input.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

using namespace impulse::test;

namespace {

std::size_t lines(const std::string& text) {
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST_CASE("resolve - --trace - reads the case from standard input and prints only the trace") {
    TempDir dir;
    const std::string trace = dir.file("ruler.trace.json").string();
    REQUIRE(run_cli({"resolve", cases + "ruler.json", "--trace", trace}).code == 0);

    const StandardInputFrom input(cases + "ruler.json");
    const CliResult r = run_cli({"resolve", "-", "--trace", "-"});
    CHECK(r.code == 0);
    CHECK(r.out == read_text(trace));  // the same trace, and nothing else on standard output
    CHECK(r.err.find("velocity phase: nothing left above") != std::string::npos);  // the summary moved here
    CHECK(r.err.find("trace written to") == std::string::npos);
    CHECK(dir.entries() == 1);  // no file named "-"
}

TEST_CASE("run - --states - reads the scene from standard input and writes the states to standard output") {
    TempDir dir;
    const StandardInputFrom input(shipped_scenes + "stack_3.json");
    const CliResult r = run_cli({"run", "-", "--frames", "4", "--states", "-", "--trace", dir.file("t.json").string()});
    CHECK(r.code == 0);
    CHECK(r.out.rfind("frame,time,body,name,", 0) == 0);
    CHECK(lines(r.out) == 1 + 3 * (4 + 1));  // header, then 3 bodies at frame -1 and frames 0..3
    CHECK(r.err.rfind("<stdin>: 3 bodies, ground, 4 frames", 0) == 0);  // the summary, naming standard input
    CHECK(r.err.find("trace written to " + dir.file("t.json").string()) != std::string::npos);
    CHECK(run_cli({"validate", dir.file("t.json").string()}).code == 0);
}

TEST_CASE("a JSON error in a file read from standard input names <stdin>") {
    TempDir dir;
    const StandardInputFrom input(dir.write("bad.json", R"({"bodies": [], "contacts": []})"));
    const CliResult r = run_cli({"resolve", "-"});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: <stdin>: bodies: must have at least 1 item, got 0\n");
}

TEST_CASE("validate - checks the file on standard input") {
    const StandardInputFrom input(cases + "ruler.json");
    const CliResult r = run_cli({"validate", "-"});
    CHECK(r.code == 0);
    CHECK(r.out == "<stdin>: valid case (1 body, 1 contact)\n");
}

TEST_CASE("standard input is read with the same size limit as a file") {
    // An inspect script is text a person writes: 4 MiB at most, and /dev/zero never ends.
    TempDir dir;
    const StandardInputFrom input("/dev/zero");
    const CliResult r = run_cli({"inspect", cases + "ruler.json", "--headless", "--script", "-", "--screenshot",
                                 dir.file("shot.png").string()});
    CHECK(r.code == 2);
    CHECK(r.err == "impulse-lab: <stdin>: goes on past the limit of 4 MiB (4194304 bytes)\n");
    CHECK(dir.entries() == 0);
}

TEST_CASE("worksheet --out - writes the worksheet as JSON to standard output and its summary to standard error") {
    const CliResult r = run_cli({"worksheet", cases + "ruler.json", "--out", "-"});
    CHECK(r.code == 0);
    const auto sheet = impulse::formats::parse_json_text(r.out);
    CHECK(sheet["format"] == "impulse-lab-worksheet");
    CHECK(r.err.rfind("worksheet written to standard output: ", 0) == 0);
}

TEST_CASE("diff --out - prints the report once") {
    TempDir dir;
    const std::string trace = dir.file("ruler.trace.json").string();
    REQUIRE(run_cli({"resolve", cases + "ruler.json", "--trace", trace}).code == 0);
    const CliResult to_file = run_cli({"diff", cases + "ruler.json", trace});
    const CliResult r = run_cli({"diff", cases + "ruler.json", trace, "--out", "-"});
    CHECK(r.code == 0);
    CHECK(r.out == to_file.out);
    CHECK(dir.entries() == 1);
}

TEST_CASE("two arguments given as - in one direction, or a folder given as -, are one line and exit code 2") {
    TempDir dir;
    const std::string ruler = cases + "ruler.json";
    const std::vector<std::pair<std::vector<std::string>, std::string>> table{
        {{"run", shipped_scenes + "stack_3.json", "--trace", "-", "--states", "-"},
         "impulse-lab: --states: standard output (\"-\") already carries --trace; only one output can go there\n"},
        {{"diff", "-", "-"},
         "impulse-lab: OTHER: standard input (\"-\") is already read for REFERENCE; only one file can come from it\n"},
        {{"validate", "-", "-"},
         "impulse-lab: FILE: standard input (\"-\") is already read for FILE; only one file can come from it\n"},
        {{"inspect", "-", "--headless", "--script", "-"},
         "impulse-lab: --script: standard input (\"-\") is already read for FILE; only one file can come from it\n"},
        {{"lesson", "1", "--out", "-"},
         "impulse-lab: --out: is a folder, so it cannot be standard input or output (\"-\")\n"},
        {{"bench", "--scene-dir", "-"},
         "impulse-lab: --scene-dir: is a folder, so it cannot be standard input or output (\"-\")\n"},
    };
    for (const auto& [args, message] : table) {
        const auto& expected = message;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(expected);
        const CliResult r = run_cli(args);
        CHECK(r.code == 2);
        CHECK(r.err == message);
        CHECK(r.out.empty());
    }
    CHECK(dir.entries() == 0);
}

TEST_CASE("only one of inspect's outputs may go to standard output") {
    // (That a script's export table - and --screenshot - go there: impulse_gui_tests, which may render.)
    TempDir dir;
    const auto twice = dir.write("twice.txt", "export table -\nexport trace -\n");
    const CliResult two = run_cli({"inspect", cases + "ruler.json", "--headless", "--script", twice.string()});
    CHECK(two.code == 2);
    CHECK(two.err == "impulse-lab: " + twice.string() + ": line 2: standard output (\"-\") already carries " +
                         twice.string() + ": line 1; only one output can go there\n");
    CHECK(two.out.empty());
    const auto once = dir.write("once.txt", "export table -\n");
    const CliResult both =
        run_cli({"inspect", cases + "ruler.json", "--headless", "--script", once.string(), "--screenshot", "-"});
    CHECK(both.code == 2);
    CHECK(both.err.rfind(
              "impulse-lab: --screenshot: standard output (\"-\") already carries " + once.string() + ": line 1", 0) ==
          0);
}
