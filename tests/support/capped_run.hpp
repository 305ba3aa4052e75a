#pragma once
// Runs a program as a child process under a memory cap (RLIMIT_AS) and a time limit, and keeps its exit, its
// standard error and its peak resident memory: the tests that a hostile input is refused within bounded memory
// (issue 29), which an in-process run cannot show.

#include <chrono>
#include <ctime>
#include <csignal>
#include <cstddef>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace impulse::test {

// AddressSanitizer reserves terabytes of address space for its shadow memory, so under it no address-space cap
// can be set and peak memory is not the program's own (freed blocks wait in its quarantine): the sanitize build
// runs these programs uncapped, and its tests check what they do, not what they take.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool address_sanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool address_sanitized = true;
#else
inline constexpr bool address_sanitized = false;
#endif
#else
inline constexpr bool address_sanitized = false;
#endif

struct CappedResult {
    int code = -1;         // the exit code, or 128 + the signal that ended it (SIGKILL at the time limit)
    std::string err;       // its standard error
    long peak_kib = 0;     // its peak resident memory (ru_maxrss), KiB
    double seconds = 0.0;  // wall time
};

// A signal sent to the child a while after it starts (Ctrl-C in the middle of something).
struct SignalAfter {
    int signal = 0;  // 0: none
    int milliseconds = 0;
};

// `args` starts with the program's path; `memory_bytes` caps its address space (not under AddressSanitizer); standard
// output goes to /dev/null, standard input is /dev/null.
inline CappedResult run_capped(const std::vector<std::string>& args, std::size_t memory_bytes, int time_limit_s,
                               SignalAfter signal = {}) {
    char err_name[] = "/tmp/impulse-lab-capped-XXXXXX";
    const int err_fd = ::mkstemp(err_name);
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = ::fork();
    if (child == 0) {
        if (!address_sanitized) {
            const rlimit cap{memory_bytes, memory_bytes};
            ::setrlimit(RLIMIT_AS, &cap);
        }
        const int null = ::open("/dev/null", O_RDWR);
        ::dup2(null, STDIN_FILENO);
        ::dup2(null, STDOUT_FILENO);
        ::dup2(err_fd, STDERR_FILENO);
        ::alarm(static_cast<unsigned>(time_limit_s));  // SIGALRM ends it: no test hangs on a run that does not stop
        std::vector<char*> argv;
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    if (signal.signal != 0) {
        const timespec pause{signal.milliseconds / 1000, (signal.milliseconds % 1000) * 1'000'000L};
        ::nanosleep(&pause, nullptr);
        ::kill(child, signal.signal);
    }
    CappedResult result;
    int status = 0;
    rusage usage{};
    ::wait4(child, &status, 0, &usage);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.peak_kib = usage.ru_maxrss;
    ::close(err_fd);
    std::ifstream in(err_name);
    std::stringstream text;
    text << in.rdbuf();
    result.err = text.str();
    ::unlink(err_name);
    return result;
}

}  // namespace impulse::test
