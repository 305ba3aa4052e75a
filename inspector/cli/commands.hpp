#pragma once
// The commands behind the CLI, each taking its parsed options. They throw io::InputError for bad input;
// `where` is then prefixed with the file it concerns by the caller (cli.cpp).

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace impulse::cli {

struct ResolveOptions {
    std::string case_file;
    std::optional<std::string> preset;
    std::vector<std::string> settings;  // --set name=value, in order
    std::optional<std::string> trace_file;
    std::vector<std::string> record;  // --record frames=A..B / contacts=I,J
    bool explain = false;
};

int resolve_command(const ResolveOptions& options, std::ostream& out);

struct RunOptions {
    std::string scene_file;
    std::optional<int> frames;
    std::optional<double> dt;
    std::optional<std::string> preset;
    std::vector<std::string> settings;  // --set name=value, in order
    std::optional<std::string> trace_file;
    std::vector<std::string> record;
    std::optional<std::string> states_file;
};

// `progress` is where a progress bar may go (a terminal), or null for none.
int run_command(const RunOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress);

struct InspectOptions {
    std::string file;  // a case, scene or trace
    bool headless = false;
    std::optional<std::string> size;  // "WxH"
    std::optional<std::string> go_to;
    std::optional<std::string> script;
    std::optional<std::string> screenshot;
    std::optional<int> bench_frames;
    std::optional<std::string> preset;
    std::vector<std::string> settings;
    std::vector<std::string> record;
    std::optional<int> frames;
};

// Opens the inspector: a window, or with --headless the same frames rendered offscreen.
int inspect_command(const InspectOptions& options, std::ostream& out, std::ostream& err);

// Prints one line per file; returns exit_bad_input if any file is invalid (all files are checked).
int validate_command(const std::vector<std::string>& files, std::ostream& out, std::ostream& err);

}  // namespace impulse::cli
