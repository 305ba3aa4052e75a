#include "cli/cli.hpp"

#include <exception>
#include <iostream>
#include <unistd.h>

int main(int argc, char** argv) {
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
