#pragma once
// The commands behind the CLI, each taking its parsed options. They throw formats::InputError for bad input;
// `where` is then prefixed with the file it concerns by the caller (cli.cpp).

#include "formats/input_files.hpp"
#include "model/script.hpp"
#include "model/session.hpp"

#include <istream>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace impulse::cli {

// The one line an error is printed as: "impulse-lab: FILE: PATH: PROBLEM\n", each part with its control
// characters and line breaks escaped (formats::one_line), so a file's name or a JSON key holding a line break or
// an escape sequence cannot split the line or reach the terminal as a command.
std::string error_line(const formats::FileError& e);
std::string error_line(std::string_view file, std::string_view what);  // file "" for none

struct ResolveOptions {
    std::string case_file;
    std::optional<std::string> preset;
    std::vector<std::string> settings;  // --set name=value, in order
    std::optional<std::string> trace_file;
    std::vector<std::string> record;     // --record frames=A..B / contacts=I,J
    std::optional<double> max_trace_mb;  // default formats::default_max_trace_mb
    bool explain = false;
};

int resolve_command(const ResolveOptions& options, std::ostream& out, std::ostream& err);

struct RunOptions {
    std::string scene_file;
    std::optional<int> frames;
    std::optional<double> dt;
    std::optional<std::string> preset;
    std::vector<std::string> settings;  // --set name=value, in order
    std::optional<std::string> trace_file;
    std::vector<std::string> record;
    std::optional<double> max_trace_mb;  // default formats::default_max_trace_mb
    std::optional<std::string> states_file;
    std::optional<double> max_states_mb;  // default cli::default_max_states_mb
    bool keep_partial = false;            // Ctrl-C or SIGTERM: write the trace and states of the frames done
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
    model::OpenOptions open;  // --preset, --set, --record, --frames for a case or scene
};

// Opens the inspector: a window, or with --headless the same frames rendered offscreen.
int inspect_command(const InspectOptions& options, std::ostream& out, std::ostream& err);

struct LessonOptions {
    std::optional<int> number;  // none: list the lessons
    bool headless = false;
    bool text = false;                 // in the terminal: interactive when `terminal` is given, else annotated
    std::istream* terminal = nullptr;  // standard input when it is a terminal (the lesson may then ask and wait)
    std::optional<std::string> out;    // folder for the headless lesson's trace and screenshots
    std::optional<std::string> lessons_folder;  // default: the data folder's lessons/ (cli/data_folder.hpp)
    std::optional<std::string> size;
    std::optional<std::string> script;      // as inspect's: actions, e.g. "lesson step 3", then the window stays
    std::optional<std::string> screenshot;  // as inspect's: a PNG at the end, then the window closes
    std::vector<std::string> settings;      // --set name=value: the lesson run with these too (answers included)
};

// Lists the lessons with the student's progress, or opens one: in a window; interactively in the terminal
// (--text, or no display) when standard input is one; else as annotated text (with its PNGs unless --text).
int lesson_command(const LessonOptions& options, std::ostream& out, std::ostream& err);

// A --script file's actions; throws FileError naming the file and line.
std::vector<model::Action> read_script_file(const std::string& path);

// "WxH" for --size: throws formats::InputError("--size", ...).
std::pair<int, int> parse_window_size(const std::string& text);

// Prints one line per file (all files are checked); returns exit_bad_input if a file cannot be read, else
// exit_verdict if any is invalid.
int validate_command(const std::vector<std::string>& files, std::ostream& out, std::ostream& err);

// `worksheet` and `diff` (docs/coursework.md).
struct WorksheetOptions {
    std::string file;                // a lesson, case, scene or trace
    std::vector<std::string> steps;  // --steps: places in the --goto syntax; empty = the first recorded frame
    std::string out;                 // .json or .csv
    model::OpenOptions open;         // --preset, --set, --record, --frames for a case or scene
};
int worksheet_command(const WorksheetOptions& options, std::ostream& out, std::ostream& err);

struct DiffOptions {
    std::string reference;            // a trace, or a case or scene run as inspect runs it
    std::vector<std::string> others;  // traces, filled worksheets (.json, .csv), folders of them
    double rtol = 1e-9;
    double atol = 1e-12;
    std::string format = "text";  // text, json or csv
    std::optional<std::string> out;
    model::OpenOptions open;  // --preset, --set, --record, --frames for a case or scene
};
// Returns exit_ok when everything matches, exit_verdict for a mismatch, a blank cell or (of several files) one
// that could not be read; throws for a bad reference, flag or single file.
int diff_command(const DiffOptions& options, std::ostream& out, std::ostream& err);

// `bench` (docs/bench.md): scenes x methods x iteration counts, timed and judged; five files into `out`.
struct BenchOptions {
    std::optional<std::string> scenes;      // comma-separated bench scene names or files; default: the suite's
    std::optional<std::string> suite;       // "default" (the default) or "large"
    std::optional<std::string> methods;     // comma-separated preset names; default: book, sweep, pgs, pgs_split,
                                            // soft_step
    std::optional<std::string> iterations;  // comma-separated counts; default 1,2,4,8,16,32
    int repeats = 3;                        // timed windows per configuration
    std::string out = "bench-results";
    std::optional<int> frames;             // overrides every scene's simulated frames
    std::optional<std::string> scene_dir;  // default: the data folder's scenes/ (cli/data_folder.hpp)
    bool scaling = false;                  // instead: time per resolved contact on grid_10..grid_1000
    std::optional<std::string> shard;      // "K/N": run every N-th configuration from the K-th
    std::vector<std::string> merge;        // instead: join these shard folders' results into --out
};
// `progress` is where a progress bar may go (a terminal), or null for none.
int bench_command(const BenchOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress);

}  // namespace impulse::cli
