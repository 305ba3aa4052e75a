// Every input the fuzz targets found a bug with (tests/fuzz_regressions/<target>/, docs/fuzzing.md) goes
// through the same loader again: it must load or be rejected as bad input (formats::InputError), nothing else.
// Under the sanitize preset this also checks that none of them crashes, leaks or reads out of bounds again.

#include "fuzz_loaders.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace {

std::string file_text(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("every fuzz regression input loads or is rejected as bad input") {
    const std::filesystem::path root = std::filesystem::path(IMPULSE_SOURCE_DIR) / "tests" / "fuzz_regressions";
    int inputs = 0;
    for (const impulse::fuzz::Loader& loader : impulse::fuzz::loaders) {
        const std::filesystem::path folder = root / loader.target;
        if (!std::filesystem::is_directory(folder)) continue;
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const std::filesystem::path file = entry.path();
            CAPTURE(file.string());
            ++inputs;
            const std::string text = file_text(file);
            try {
                loader.load(text);
            } catch (const impulse::formats::InputError& e) {
                // Bad input, said in one line: where and what.
                CHECK(!e.problem().empty());
            } catch (const std::exception& e) {
                FAIL_CHECK("not an InputError: " << e.what());
            }
        }
    }
    CHECK(inputs > 0);
}

TEST_CASE("every fuzz target has a regression folder name that is one of the loaders") {
    const std::filesystem::path root = std::filesystem::path(IMPULSE_SOURCE_DIR) / "tests" / "fuzz_regressions";
    for (const auto& entry : std::filesystem::directory_iterator(root)) {
        CAPTURE(entry.path().string());
        bool known = false;
        for (const impulse::fuzz::Loader& loader : impulse::fuzz::loaders)
            known = known || entry.path().filename() == loader.target;
        CHECK(known);
    }
}

namespace {

// The InputError a kept input gives, as "where: problem"; empty when it loads.
std::string rejection(std::string_view target, const std::string& name) {
    const std::filesystem::path file =
        std::filesystem::path(IMPULSE_SOURCE_DIR) / "tests" / "fuzz_regressions" / target / name;
    for (const impulse::fuzz::Loader& loader : impulse::fuzz::loaders) {
        if (loader.target != target) continue;
        try {
            loader.load(file_text(file));
        } catch (const impulse::formats::InputError& e) {
            return e.where() + ": " + e.problem();
        }
    }
    return "";
}

}  // namespace

// Each of these numbers passed the schema as an "integer" (a double with no fraction is one) and was then cast
// to an int by nlohmann's get<int>(), which is undefined behaviour when it does not fit: UBSan stopped there.
TEST_CASE("a trace's frame number beyond int is rejected at its path, not cast") {
    CHECK(rejection("fuzz_trace_text", "frame-number-1e300.json") ==
          "frames[0].frame: must be <= 2147483647, got 1e+300");
    CHECK(rejection("fuzz_trace_text", "first-frame-1e300.json").starts_with("recording.first_frame: must be <="));
    CHECK(rejection("fuzz_trace_text", "contact-count-1e300.json").starts_with("frames[0].contact_count: must be <="));
}

TEST_CASE("a case's body index beyond long long is rejected at its path, not cast") {
    CHECK(rejection("fuzz_scene_text", "body-index-1e300.json").starts_with("contacts[0].bodies[0]: "));
    CHECK(rejection("fuzz_scene_text", "body-index-minus-1e300.json").starts_with("contacts[0].bodies[0]: "));
}

TEST_CASE("a worksheet reference's recording beyond int or two billion frames is rejected before it runs") {
    CHECK(rejection("fuzz_worksheet_reference", "first-frame-1e300.json")
              .starts_with("reference.recording.first_frame: must be <= 2147483647"));
    CHECK(rejection("fuzz_worksheet_reference", "two-billion-frames.json")
              .starts_with("reference.run.frames: must be <= 100000, got 2"));
}

TEST_CASE("a progress file's counts must be whole numbers that fit, named by their path") {
    CHECK(rejection("fuzz_progress_text", "tries-1e300.json") ==
          "lessons.01-x.answers.q.tries: must be a whole number from 0 to 2147483647, got 1e+300");
    CHECK(rejection("fuzz_progress_text", "last-step-text.json").starts_with("lessons.01-x.last_step: must be"));
}

TEST_CASE("a trace iteration with part of its derivation is rejected at the missing key, not read past it") {
    // libFuzzer (fuzz_trace_text, 194375 executions in): impulse_world dropped from a velocity iteration that keeps
    // impulse_model; the reader then indexed a key that was not there (a nlohmann assertion, undefined behaviour).
    CHECK(rejection("fuzz_trace_text", "velocity-derivation-without-impulse-world.json") ==
          "frames[0].phases[1].iterations[1].impulse_world: missing (given with impulse_model)");
}

TEST_CASE("a CSV worksheet that is not UTF-8 is rejected at its line, not written into a JSON report") {
    // libFuzzer (fuzz_diff, 18120 executions in): a byte 0x98 in a CSV cell reached diff's JSON report, where
    // nlohmann refused to write it (an exception no command caught: "internal error").
    CHECK(rejection("fuzz_diff", "csv-cell-not-utf8.bin") == "line 36: not UTF-8 text: byte 0x98 at column 117");
}
