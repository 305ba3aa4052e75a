#pragma once
// The one exception type for bad input (a case, trace or settings file, or a command-line flag).
// It carries where the problem is (a JSON path such as `bodies[1].inverse_mass`, or a flag such as
// `--preset`) and what is wrong, so the command line can print it as one line and exit with code 2.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace impulse::formats {

class InputError : public std::runtime_error {
public:
    // `where` may be empty when the problem concerns the whole document (e.g. it is not JSON at all).
    InputError(std::string where, std::string problem);

    const std::string& where() const noexcept { return where_; }
    const std::string& problem() const noexcept { return problem_; }

private:
    std::string where_;
    std::string problem_;
};

// JSON paths as the error messages print them: `bodies[2].mass`, `settings.angular_limit.factor`.
// The document root is the empty path.
std::string json_path_child(std::string_view parent, std::string_view key);
std::string json_path_index(std::string_view parent, std::size_t index);

// A number as a message shows it: the shortest text that reads back to the same double, without a
// trailing ".0" (2, 0.25, -1e-07).
std::string number_text(double value);

}  // namespace impulse::formats
