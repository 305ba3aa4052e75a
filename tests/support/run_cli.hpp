#pragma once
// Runs impulse-lab in-process and keeps what it printed.

#include "cli/cli.hpp"

#include <sstream>
#include <string>
#include <vector>

namespace impulse::test {

struct CliResult {
    int code;
    std::string out;
    std::string err;
};

inline CliResult run_cli(const std::vector<std::string>& args) {
    std::ostringstream out, err;
    const int code = cli::run(args, out, err);
    return {code, out.str(), err.str()};
}

}  // namespace impulse::test
