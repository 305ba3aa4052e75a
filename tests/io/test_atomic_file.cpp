// Output files are replaced whole or not at all.

#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

using namespace impulse;
using namespace impulse::test;

namespace {

std::string contents(std::istream& in) {
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace

TEST_CASE("a reader of the old file keeps seeing all of it while the new one replaces it") {
    // The new text goes to a temporary file that is renamed over the old one, so a reader that opened the
    // old file reads the old text to the end; writing in place would truncate it under the reader.
    TempDir dir;
    const auto path = dir.write("trace.json", "old contents");
    std::ifstream reader(path);
    io::write_file_atomically(path, "new contents, longer than the old", "--trace");
    CHECK(contents(reader) == "old contents");
    std::ifstream fresh(path);
    CHECK(contents(fresh) == "new contents, longer than the old");
    CHECK(dir.entries() == 1);  // no temporary left beside it
}

TEST_CASE("a write that fails leaves the target as it was and no temporary behind") {
    // The target is a directory, so the final rename fails after the text was written.
    TempDir dir;
    std::filesystem::create_directory(dir.file("taken"));
    CHECK_THROWS_WITH_AS(io::write_file_atomically(dir.file("taken"), "text", "--trace"),
                         doctest::Contains("--trace: cannot write '"), io::InputError);
    CHECK(std::filesystem::is_directory(dir.file("taken")));
    CHECK(dir.entries() == 1);
}

TEST_CASE("a new file gets the permissions a normally created file would have, not the temporary's 0600") {
    TempDir dir;
    const mode_t previous = ::umask(022);
    io::write_file_atomically(dir.file("out.json"), "{}", "--trace");
    ::umask(previous);
    namespace fs = std::filesystem;
    CHECK(fs::status(dir.file("out.json")).permissions() ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read));
}

namespace {

volatile std::sig_atomic_t terminate_seen = 0;
extern "C" void see_terminate(int) { terminate_seen = 1; }

}  // namespace

TEST_CASE("a signal that arrives while files are being written is delivered only once they are in place") {
    impulse::test::TempDir dir;
    struct sigaction action {}, previous {};
    action.sa_handler = see_terminate;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, &previous);
    terminate_seen = 0;
    {
        const impulse::io::DeferredSignals held;
        impulse::io::StagedFile staged(dir.file("out.txt"), "whole", "--out");
        std::raise(SIGTERM);  // held back: it would otherwise cut the write short
        CHECK(terminate_seen == 0);
        staged.commit();
    }
    CHECK(terminate_seen == 1);
    CHECK(dir.entries() == 1);  // the file, no temporary
    sigaction(SIGTERM, &previous, nullptr);
}
