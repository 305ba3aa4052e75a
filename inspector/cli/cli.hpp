#pragma once
// The impulse-lab command line. Runnable in-process so tests can check exit codes, messages and files
// without spawning the program.

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace impulse::cli {

// The exit codes, one table in the README.
inline constexpr int exit_ok = 0;
inline constexpr int exit_verdict = 1;          // a verdict: diff found a mismatch or a blank, validate an invalid file
inline constexpr int exit_bad_input = 2;        // a file or flag the user gave is wrong
inline constexpr int exit_non_finite = 3;       // a run stopped: a body's state became NaN or infinite
inline constexpr int exit_internal_error = 70;  // something went wrong inside the program (EX_SOFTWARE, sysexits.h)
inline constexpr int exit_interrupted = 130;    // Ctrl-C (SIGTERM: 143; 128 + the signal)

// `args` excludes the program name. `err_is_terminal` allows a progress bar on `err` for long runs;
// `terminal_in` is standard input when it is a terminal a lesson may ask questions on (null: never wait).
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal = false,
        std::istream* terminal_in = nullptr);

}  // namespace impulse::cli
