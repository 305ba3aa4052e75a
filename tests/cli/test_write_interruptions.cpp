// The program's policy for interruptions while files are written (cli/deferred_signals.hpp), through the
// formats layer's writer: a signal waits until the files are in place, and a FIFO's reader that goes away is an
// error, not SIGPIPE.

#include "cli/deferred_signals.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <csignal>
#include <filesystem>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <fcntl.h>

using namespace impulse;
using namespace impulse::test;

namespace {

namespace fs = std::filesystem;

int wait_for(pid_t child) {
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

namespace {

volatile std::sig_atomic_t terminate_seen = 0;
extern "C" void see_terminate(int) {
    terminate_seen = 1;
}

}  // namespace

TEST_CASE("a signal that arrives while files are being written is delivered only once they are in place") {
    cli::install_deferred_signals();
    impulse::test::TempDir dir;
    struct sigaction action {
    }, previous{};
    action.sa_handler = see_terminate;
    sigemptyset(&action.sa_mask);
    sigaction(SIGTERM, &action, &previous);
    terminate_seen = 0;
    {
        const impulse::formats::HeldInterruptions held;
        impulse::formats::StagedFile staged(dir.file("out.txt"), "whole", "--out");
        std::raise(SIGTERM);  // held back: it would otherwise cut the write short
        CHECK(terminate_seen == 0);
        staged.commit();
    }
    CHECK(terminate_seen == 1);
    CHECK(dir.entries() == 1);  // the file, no temporary
    sigaction(SIGTERM, &previous, nullptr);
}

TEST_CASE("a FIFO whose reader goes away gives an error, not a SIGPIPE, and stays a FIFO") {
    cli::install_deferred_signals();
    TempDir dir;
    const fs::path fifo = dir.file("early.fifo");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    const pid_t child = ::fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const int fd = ::open(fifo.c_str(), O_RDONLY);  // opens, reads a little, leaves
        char buffer[16];
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        ::_exit(n > 0 ? 0 : 1);
    }
    const std::string text(1 << 20, 'x');  // far more than the pipe holds
    CHECK_THROWS_WITH_AS(formats::write_file_atomically(fifo, text, "--trace"), doctest::Contains("Broken pipe"),
                         formats::InputError);
    CHECK(wait_for(child) == 0);
    CHECK(fs::is_fifo(fifo));
}
