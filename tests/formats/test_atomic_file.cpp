// Output files are replaced whole or not at all.

#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

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
    formats::write_file_atomically(path, "new contents, longer than the old", "--trace");
    CHECK(contents(reader) == "old contents");
    std::ifstream fresh(path);
    CHECK(contents(fresh) == "new contents, longer than the old");
    CHECK(dir.entries() == 1);  // no temporary left beside it
}

TEST_CASE("a write that fails leaves the target as it was and no temporary behind") {
    // The target is a directory, so the final rename fails after the text was written.
    TempDir dir;
    std::filesystem::create_directory(dir.file("taken"));
    CHECK_THROWS_WITH_AS(formats::write_file_atomically(dir.file("taken"), "text", "--trace"),
                         doctest::Contains("--trace: cannot write '"), formats::InputError);
    CHECK(std::filesystem::is_directory(dir.file("taken")));
    CHECK(dir.entries() == 1);
}

TEST_CASE("a new file gets the permissions a normally created file would have, not the temporary's 0600") {
    TempDir dir;
    const mode_t previous = ::umask(022);
    formats::write_file_atomically(dir.file("out.json"), "{}", "--trace");
    ::umask(previous);
    namespace fs = std::filesystem;
    CHECK(fs::status(dir.file("out.json")).permissions() ==
          (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read));
}

// What a path stands for stays what it was: only files are replaced.

namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return contents(in);
}

bool is_link(const fs::path& path) {
    return fs::is_symlink(fs::symlink_status(path));
}

// A child process that reads the FIFO to its end and copies what it read into `copy`, as `cat fifo > copy`
// would. Only async-signal-safe calls after fork.
pid_t start_reader(const fs::path& fifo, const fs::path& copy) {
    const std::string from = fifo.string(), to = copy.string();
    const pid_t child = ::fork();
    if (child != 0) return child;
    const int in = ::open(from.c_str(), O_RDONLY);
    const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (in < 0 || out < 0) ::_exit(1);
    char buffer[4096];
    ssize_t n = 0;
    while ((n = ::read(in, buffer, sizeof buffer)) > 0)
        if (::write(out, buffer, static_cast<std::size_t>(n)) != n) ::_exit(1);
    ::_exit(n == 0 ? 0 : 1);
}

int wait_for(pid_t child) {
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("a missing file is created whole, and a regular one replaced, both through a temporary") {
    TempDir dir;
    CHECK(formats::output_target(dir.file("new.json"), "--trace").kind == formats::OutputKind::replaced);
    formats::write_file_atomically(dir.file("new.json"), "first", "--trace");
    CHECK(read_all(dir.file("new.json")) == "first");
    CHECK(formats::output_target(dir.file("new.json"), "--trace").kind == formats::OutputKind::replaced);
    formats::write_file_atomically(dir.file("new.json"), "second", "--trace");
    CHECK(read_all(dir.file("new.json")) == "second");
    CHECK(dir.entries() == 1);
}

TEST_CASE("a symlink given as an output stays a link and its target, in another folder, gets the text") {
    // out.json -> chain.json -> ../elsewhere/trace.json: the whole chain is followed, and the temporary lives in
    // the target's folder (a rename across folders could cross file systems), never beside the link.
    TempDir dir;
    fs::create_directory(dir.file("here"));
    fs::create_directory(dir.file("elsewhere"));
    std::ofstream(dir.file("elsewhere/trace.json")) << "old";
    fs::create_symlink("../elsewhere/trace.json", dir.file("here/chain.json"));
    fs::create_symlink("chain.json", dir.file("here/out.json"));
    const formats::OutputTarget target = formats::output_target(dir.file("here/out.json"), "--trace");
    CHECK(target.kind == formats::OutputKind::replaced);
    CHECK(fs::equivalent(target.path.parent_path(), dir.file("elsewhere")));

    formats::write_file_atomically(dir.file("here/out.json"), "new trace", "--trace");
    CHECK(is_link(dir.file("here/out.json")));
    CHECK(is_link(dir.file("here/chain.json")));
    CHECK(fs::read_symlink(dir.file("here/out.json")) == "chain.json");
    CHECK(read_all(dir.file("elsewhere/trace.json")) == "new trace");
    CHECK(std::distance(fs::directory_iterator(dir.file("here")), fs::directory_iterator()) == 2);
    CHECK(std::distance(fs::directory_iterator(dir.file("elsewhere")), fs::directory_iterator()) == 1);
}

TEST_CASE("a dangling symlink into an existing folder creates its target and stays a link") {
    TempDir dir;
    fs::create_directory(dir.file("results"));
    fs::create_symlink(dir.file("results/trace.json"), dir.file("latest.json"));
    CHECK_NOTHROW(formats::check_writable(dir.file("latest.json"), "--trace"));
    formats::write_file_atomically(dir.file("latest.json"), "made", "--trace");
    CHECK(is_link(dir.file("latest.json")));
    CHECK(read_all(dir.file("results/trace.json")) == "made");
}

TEST_CASE("a dangling symlink into a missing folder and a loop of links are refused before anything is written") {
    TempDir dir;
    fs::create_symlink(dir.file("gone/trace.json"), dir.file("dangling.json"));
    CHECK_THROWS_WITH_AS(formats::check_writable(dir.file("dangling.json"), "--trace"),
                         doctest::Contains("': No such file or directory"), formats::InputError);
    fs::create_symlink("b.json", dir.file("a.json"));
    fs::create_symlink("a.json", dir.file("b.json"));
    CHECK_THROWS_WITH_AS(formats::check_writable(dir.file("a.json"), "--trace"),
                         doctest::Contains("Too many levels of symbolic links"), formats::InputError);
    CHECK_THROWS_AS(formats::write_file_atomically(dir.file("a.json"), "x", "--trace"), formats::InputError);
    CHECK(is_link(dir.file("a.json")));
    CHECK(dir.entries() == 3);
}

TEST_CASE("a FIFO given as an output stays a FIFO and its reader receives the whole text") {
    // Today's bug: the temporary was renamed over the FIFO, so the reader waited forever and the FIFO became a
    // regular file. Larger than a pipe's buffer (64 KiB), so the writer must wait for the reader too.
    TempDir dir;
    const fs::path fifo = dir.file("trace.fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    REQUIRE(formats::output_target(fifo, "--trace").kind == formats::OutputKind::in_place);
    CHECK_NOTHROW(formats::check_writable(fifo, "--trace"));
    std::string text;
    for (int i = 0; text.size() < 300'000; ++i) text += "line " + std::to_string(i) + "\n";
    const pid_t reader = start_reader(fifo, dir.file("received"));
    REQUIRE(reader > 0);
    formats::write_file_atomically(fifo, text, "--trace");
    CHECK(wait_for(reader) == 0);
    CHECK(fs::is_fifo(fifo));
    CHECK(read_all(dir.file("received")) == text);
    CHECK(dir.entries() == 2);  // the FIFO and the reader's copy: no temporary
}

TEST_CASE("a FIFO staged with a file is written when the set commits, and the file beside it is replaced") {
    TempDir dir;
    const fs::path fifo = dir.file("states.fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const pid_t reader = start_reader(fifo, dir.file("received"));
    REQUIRE(reader > 0);
    {
        const formats::HeldInterruptions held;  // a set of files: committed together
        std::vector<formats::StagedFile> files;
        files.emplace_back(dir.file("trace.json"), "trace", "--trace");
        files.emplace_back(fifo, "states", "--states");
        for (formats::StagedFile& f : files) f.commit();
    }
    CHECK(wait_for(reader) == 0);
    CHECK(read_all(dir.file("received")) == "states");
    CHECK(read_all(dir.file("trace.json")) == "trace");
    CHECK(fs::is_fifo(fifo));
}

TEST_CASE("/dev/null is written in place and stays the null device") {
    // Checked to be written in place before anything is written: were it replaced, as root, /dev/null would
    // become a regular file for the whole machine.
    const formats::OutputTarget target = formats::output_target("/dev/null", "--trace");
    REQUIRE(target.kind == formats::OutputKind::in_place);
    formats::write_file_atomically("/dev/null", "discarded", "--trace");
    CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("a terminal is written in place") {
    // A pseudo-terminal: what the program writes to its slave side the master side reads back.
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        MESSAGE("skipped: no pseudo-terminal here (" << std::strerror(errno) << ")");
        return;
    }
    const std::string terminal = ::ptsname(master);
    REQUIRE(formats::output_target(terminal, "--trace").kind == formats::OutputKind::in_place);
    formats::write_file_atomically(terminal, "on screen", "--trace");
    char buffer[64] = {};
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    CHECK(std::string(buffer, static_cast<std::size_t>(std::max<ssize_t>(n, 0))) == "on screen");
    CHECK(fs::is_character_file(terminal));
    ::close(master);
}

TEST_CASE("a directory as an output is one clear error before anything is written") {
    TempDir dir;
    fs::create_directory(dir.file("results"));
    const std::string expected = "--trace: cannot write '" + dir.file("results").string() + "': Is a directory";
    CHECK_THROWS_WITH_AS(formats::check_writable(dir.file("results"), "--trace"), expected.c_str(),
                         formats::InputError);
    fs::create_symlink("results", dir.file("link"));
    CHECK_THROWS_WITH_AS(formats::check_writable(dir.file("link"), "--trace"), doctest::Contains("Is a directory"),
                         formats::InputError);
    CHECK_THROWS_AS(formats::StagedFile(dir.file("results"), "x", "--trace"), formats::InputError);
    CHECK(dir.entries() == 2);
}

TEST_CASE("an output in a folder the user cannot write is refused before anything runs") {
    if (::geteuid() == 0) {
        MESSAGE("skipped: run as root, which may write in any folder, so there is no unwritable folder to test");
        return;
    }
    TempDir dir;
    fs::create_directory(dir.file("locked"));
    fs::permissions(dir.file("locked"), fs::perms::owner_read | fs::perms::owner_exec);
    CHECK_THROWS_WITH_AS(formats::check_writable(dir.file("locked/trace.json"), "--trace"),
                         doctest::Contains("': Permission denied"), formats::InputError);
    CHECK_THROWS_AS(formats::write_file_atomically(dir.file("locked/trace.json"), "x", "--trace"), formats::InputError);
    fs::permissions(dir.file("locked"), fs::perms::owner_all);
    CHECK(fs::is_empty(dir.file("locked")));
}

TEST_CASE("a replaced file keeps its permissions") {
    TempDir dir;
    const auto path = dir.write("shared.json", "old");
    fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    formats::write_file_atomically(path, "new", "--trace");
    CHECK(fs::status(path).permissions() == (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
}
