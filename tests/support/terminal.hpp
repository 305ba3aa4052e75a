#pragma once
// A program run on a pseudo-terminal, as a student runs it in a terminal: its standard input, output and
// error are the terminal, so it may ask and wait. The test reads what it writes until an expected text
// appears and types lines into it.

#include <doctest/doctest.h>

#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::test {

class Terminal {
public:
    // Runs `argv` (argv[0] a path) with the environment changed by `env` (a value of none: unset), on a terminal
    // `columns` wide.
    Terminal(const std::vector<std::string>& argv, const std::map<std::string, std::optional<std::string>>& env,
             unsigned short columns = 110) {
        winsize size{};
        size.ws_row = 50;
        size.ws_col = columns;
        pid_ = ::forkpty(&master_, nullptr, nullptr, &size);
        REQUIRE_MESSAGE(pid_ >= 0, "forkpty failed");
        if (pid_ == 0) {
            for (const auto& [name, value] : env)
                if (value)
                    ::setenv(name.c_str(), value->c_str(), 1);
                else
                    ::unsetenv(name.c_str());
            std::vector<char*> args;
            for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
            args.push_back(nullptr);
            ::execv(args[0], args.data());
            ::_exit(127);
        }
    }
    ~Terminal() {
        if (pid_ > 0 && !exited_) {
            ::kill(pid_, SIGKILL);
            ::waitpid(pid_, nullptr, 0);
        }
        if (master_ >= 0) ::close(master_);
    }
    Terminal(const Terminal&) = delete;
    Terminal& operator=(const Terminal&) = delete;

    // Everything written since the last expect, up to and including `text`; fails after `seconds` without it.
    std::string expect(std::string_view text, double seconds = 30.0) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        while (true) {
            if (const std::size_t at = pending_.find(text); at != std::string::npos) {
                std::string seen = pending_.substr(0, at + text.size());
                pending_.erase(0, at + text.size());
                all_ += seen;
                return seen;
            }
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
            if (left.count() <= 0 || !read_some(static_cast<int>(left.count()))) {
                FAIL("no \"" << std::string(text) << "\" within " << seconds << " s; the terminal shows:\n"
                             << pending_);
                return {};
            }
        }
    }
    // Types a line and Enter.
    void send(std::string_view line) {
        const std::string typed = std::string(line) + "\n";
        REQUIRE(::write(master_, typed.data(), typed.size()) == static_cast<ssize_t>(typed.size()));
    }
    // Waits for the program to end (reading what it still writes) and returns its exit code.
    int wait(double seconds = 30.0) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        int status = 0;
        while (::waitpid(pid_, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() > deadline) {
                FAIL("the program did not end within " << seconds << " s; it shows:\n" << pending_);
                return -1;
            }
            read_some(50);
        }
        exited_ = true;
        while (read_some(0)) {
        }
        all_ += pending_;
        pending_.clear();
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    // All it wrote so far.
    const std::string& all() const { return all_; }

private:
    bool read_some(int milliseconds) {
        pollfd p{master_, POLLIN, 0};
        if (::poll(&p, 1, milliseconds) <= 0) return false;
        char buffer[4096];
        const ssize_t n = ::read(master_, buffer, sizeof buffer);
        if (n <= 0) return false;  // the program ended: the terminal reports EIO
        pending_.append(buffer, static_cast<std::size_t>(n));
        return true;
    }

    int master_ = -1;
    pid_t pid_ = -1;
    bool exited_ = false;
    std::string pending_, all_;
};

}  // namespace impulse::test
