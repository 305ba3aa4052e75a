#pragma once
// The impulse-lab command line. Runnable in-process so tests can check exit codes, messages and files
// without spawning the program.

#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace impulse::cli {

inline constexpr int exit_ok = 0;
inline constexpr int exit_failure = 1;    // something went wrong inside the program
inline constexpr int exit_bad_input = 2;  // a file or flag the user gave is wrong
inline constexpr int exit_interrupted = 130;  // `run` stopped by Ctrl-C (SIGTERM: 143, 128 + the signal)
inline constexpr int exit_non_finite = 3; // `run`: a body's state became NaN or infinite; the frames before it
                                          // are written

// `args` excludes the program name. `err_is_terminal` allows a progress bar on `err` for long runs;
// `terminal_in` is standard input when it is a terminal a lesson may ask questions on (null: never wait).
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal = false,
        std::istream* terminal_in = nullptr);

}  // namespace impulse::cli
