#include "cli/cli.hpp"
#include "cli/terminal_guard.hpp"

#include <exception>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace {

// Standard output or error, when it is a terminal, behind a TerminalGuard while main runs.
class Guarded {
public:
    Guarded(std::ostream& stream, int fd) : stream_(stream) {
        if (::isatty(fd) != 1) return;
        guard_.emplace(stream.rdbuf());
        stream.rdbuf(&*guard_);
    }
    ~Guarded() {
        if (!guard_) return;
        stream_.flush();
        stream_.rdbuf(guard_->terminal());
    }
    Guarded(const Guarded&) = delete;
    Guarded& operator=(const Guarded&) = delete;

private:
    std::ostream& stream_;
    std::optional<impulse::cli::TerminalGuard> guard_;
};

}  // namespace

int main(int argc, char** argv) {
    const Guarded out(std::cout, STDOUT_FILENO), err(std::cerr, STDERR_FILENO);
    // cli::run answers every error itself; anything that still escapes is a bug: exit 70, as any internal error.
    try {
        return impulse::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr,
                                 ::isatty(STDERR_FILENO) == 1, ::isatty(STDIN_FILENO) == 1 ? &std::cin : nullptr);
    } catch (const std::exception& e) {
        std::cerr << "impulse-lab: internal error: " << e.what() << '\n';
    } catch (...) {
        std::cerr << "impulse-lab: internal error: an unknown exception\n";
    }
    return impulse::cli::exit_internal_error;
}
