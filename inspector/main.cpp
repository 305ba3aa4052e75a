#include "cli/cli.hpp"

#include <iostream>
#include <unistd.h>

int main(int argc, char** argv) {
    return impulse::cli::run(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr,
                             ::isatty(STDERR_FILENO) == 1, ::isatty(STDIN_FILENO) == 1 ? &std::cin : nullptr);
}
