// A file at the input limit of each kind (formats/input_limits.hpp) is read, or refused as bad input, by the
// program itself within a memory cap: the memory a file can cost is bounded by the limits, not by the machine
// (issue 29: 200 MB of JSON numbers aborted at 4 GB). Each file is made as large as the limit lets it be and as
// costly per byte as its kind allows. Reading time against size is a benchmark (impulse-bench-read,
// docs/bench.md), not a check here; the time limit only keeps a run that does not stop from hanging the suite.

#include "formats/input_limits.hpp"
#include "support/capped_run.hpp"
#include "support/program.hpp"
#include "support/read_text.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>

using impulse::test::TempDir;

namespace {

using impulse::test::program;
// The limits' own memory (a document's estimate) and the text read whole, with room for the program itself.
constexpr std::size_t memory_cap =
    impulse::formats::max_json_memory_bytes + impulse::formats::max_input_bytes + (256u << 20);

// Writes `head`, then `piece` as many times as fit with `tail` under `limit` bytes, then `tail`.
std::filesystem::path fill(const std::filesystem::path& file, const std::string& head, const std::string& piece,
                           const std::string& tail, std::size_t limit) {
    std::ofstream out(file, std::ios::binary);
    out << head;
    const std::size_t times = (limit - head.size() - tail.size()) / piece.size();
    std::string block;
    for (int i = 0; i < 4096; ++i) block += piece;
    for (std::size_t done = 0; done < times; done += 4096)
        out.write(block.data(), static_cast<std::streamsize>(piece.size() * std::min<std::size_t>(4096, times - done)));
    out << tail;
    return file;
}

impulse::test::CappedResult run(const std::vector<std::string>& args) {
    std::vector<std::string> full{program};
    full.insert(full.end(), args.begin(), args.end());
    const impulse::test::CappedResult r = impulse::test::run_capped(full, memory_cap, 120);
    MESSAGE(args[0] << " " << std::filesystem::path(args.back()).filename().string() << ": exit " << r.code << ", peak "
                    << r.peak_kib / 1024 << " MiB, " << r.seconds << " s");
    return r;
}

}  // namespace

TEST_CASE("a file at the input limit of each kind is read or refused in words within the memory cap") {
    if (impulse::test::address_sanitized) {
        // AddressSanitizer's shadow memory and quarantine make neither a cap nor a peak the program's own.
        // The default preset runs it; the sanitize build runs the test below, which needs no cap.
        MESSAGE("skipped under AddressSanitizer: the default preset runs it");
        return;
    }
    TempDir dir;
    const std::size_t limit = impulse::formats::max_input_bytes;
    CAPTURE(memory_cap);

    // A scene of boxes written as grid_1000.json writes them, 2.5 million of them: refused where its document's
    // memory passes the cap, naming the body.
    const auto scene =
        fill(dir.file("boxes.json"),
             R"({"format": "impulse-lab-scene", "ground": {}, "bodies": [)"
             "\n",
             R"({"name": "b", "shape": {"type": "box", "half_size": [0.5, 0.5, 0.5]}, "position": [0, 0.5, 0]},)"
             "\n",
             R"({"name": "last", "shape": {"type": "sphere", "radius": 0.5}, "position": [0, 9, 0]}]})"
             "\n",
             limit);
    auto r = run({"validate", scene.string()});
    CHECK(r.code == 1);
    CHECK(r.err.find(": holds more than one document may: reading it would take over 1536 MiB of memory") !=
          std::string::npos);
    CHECK(r.err.find("boxes.json: bodies[") != std::string::npos);

    // The costliest JSON per byte, "1," (a 16-byte value in a vector that doubles), as a worksheet for diff.
    const auto reference = dir.file("reference.json");
    REQUIRE(run({"resolve", IMPULSE_SOURCE_DIR "/scenes/cases/ruler.json", "--trace", reference.string()}).code == 0);
    const auto numbers = fill(dir.file("numbers.json"), "[", "1,", "1]", limit);
    r = run({"diff", reference.string(), numbers.string()});
    CHECK(r.code == 2);
    CHECK(r.err.find("numbers.json: [") != std::string::npos);
    CHECK(r.err.find("reading it would take over 1536 MiB of memory") != std::string::npos);

    // A CSV worksheet of the shortest rows that are cells: refused at the cell cap.
    const auto cells = fill(dir.file("cells.csv"), "kind,path,step,quantity,value,unit,formula,equation,meaning\n",
                            "cell,x,,,1,,,,\n", "", limit);
    r = run({"diff", reference.string(), cells.string()});
    CHECK(r.code == 2);
    CHECK(r.err.find("cells.csv: line ") != std::string::npos);
    CHECK(r.err.find("more than any worksheet within the input limit holds") != std::string::npos);

    // The largest trace the program writes by default (--max-trace-mb 200), read back whole and valid.
    const auto trace = dir.file("stack.trace.json");
    REQUIRE(
        run({"run", IMPULSE_SOURCE_DIR "/scenes/stack_10.json", "--frames", "80", "--trace", trace.string()}).code ==
        0);
    CHECK(std::filesystem::file_size(trace) > 190'000'000);
    r = run({"validate", trace.string()});
    CHECK(r.code == 0);
    CHECK(r.err.empty());
}

// What needs no memory cap runs in every build, the sanitized one too (a lesson at its limit is cheap to read, and a
// file over the limit is refused before it is read); the sanitize build runs no other test of these limits.
TEST_CASE("a lesson at the text limit is valid, and a file one byte over the input limit is refused unread") {
    TempDir dir;
    const std::size_t limit = impulse::formats::max_input_bytes;
    CAPTURE(memory_cap);

    // Text a person writes has its own, smaller limit: a lesson of 4 MiB, its last step a long read, is valid.
    // It sits where the shipped lesson does, next to a copy of the scene it names ("../scenes/cases/...").
    const std::string lesson_text =
        impulse::test::read_text(impulse::test::shipped_lessons / "01-impulse-is-a-velocity-change.md");
    std::filesystem::create_directories(dir.file("lessons"));
    std::filesystem::create_directories(dir.file("scenes/cases"));
    std::filesystem::copy_file(impulse::test::cases + "sphere_ground.json",
                               dir.file("scenes/cases/sphere_ground.json"));
    const auto lesson = fill(dir.file("lessons/01-impulse-is-a-velocity-change.md"), lesson_text,
                             "The impulse changes the velocity by its size over the mass. ", "\n",
                             impulse::formats::max_text_input_bytes);
    auto r = run({"validate", lesson.string()});
    CHECK(r.code == 0);
    CHECK(r.err.empty());

    // One byte over the limit is refused before it is read.
    fill(dir.file("over.json"), "[", "1,", "1]", limit);
    std::ofstream(dir.file("over.json"), std::ios::app) << "  ";
    r = run({"validate", dir.file("over.json").string()});
    CHECK(r.code == 2);
    CHECK(r.err.find("over the limit of 256 MiB") != std::string::npos);
}
