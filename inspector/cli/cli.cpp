#include "cli/cli.hpp"

#include "cli/commands.hpp"
#include "cli/input_files.hpp"
#include "cli/interrupt.hpp"
#include "io/input_error.hpp"
#include "record/trace.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <sstream>

namespace impulse::cli {

namespace {

constexpr const char* version_text = "impulse-lab " IMPULSE_LAB_VERSION;

std::vector<std::string> preset_choices() {
    const auto names = preset_names();
    return {names.begin(), names.end()};
}

// CLI11's Range lets NaN through (every comparison with it is false) and calls "1x" out of range; these say
// what is wrong with the text itself. CLI11 prints the message after the flag's name.
CLI::Validator whole_number(long long lowest, long long highest) {
    const std::string range = std::to_string(lowest) + " to " + std::to_string(highest);
    return CLI::Validator(
        [lowest, highest, range](std::string& text) -> std::string {
            long long value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error == std::errc::invalid_argument || end != text.data() + text.size())
                return "expected a whole number from " + range + ", got \"" + text + "\"";
            if (error == std::errc::result_out_of_range || value < lowest || value > highest)
                return "must be from " + range + ", got " + text;
            return {};
        },
        "INT in " + range);
}

CLI::Validator finite_number(double lowest, double highest) {
    const std::string range = io::number_text(lowest) + " to " + io::number_text(highest);
    return CLI::Validator(
        [lowest, highest, range](std::string& text) -> std::string {
            char* end = nullptr;
            const double value = std::strtod(text.c_str(), &end);
            if (text.empty() || end != text.c_str() + text.size())
                return "expected a number from " + range + ", got \"" + text + "\"";
            if (!(value >= lowest && value <= highest)) return "must be from " + range + ", got " + text;
            return {};
        },
        "NUMBER in " + range);
}

// --max-trace-mb, for every command that records a trace.
void add_max_trace_mb(CLI::App& command, std::optional<double>& max_trace_mb) {
    std::ostringstream default_mb;
    default_mb << inspect::default_max_trace_mb;
    command
        .add_option("--max-trace-mb", max_trace_mb,
                    "Stop recording when the trace would pass this size in MB (estimated; default " + default_mb.str() +
                        "): it then ends with the last whole frame, and the run goes on")
        ->check(finite_number(1e-6, 1e9));
}

void add_resolve(CLI::App& app, ResolveOptions& o) {
    CLI::App* resolve = app.add_subcommand("resolve",
                                           "Resolve a case's contacts once and record every derivation step.\n"
                                           "Example: impulse-lab resolve scenes/cases/ruler.json --explain");
    resolve->add_option("CASE", o.case_file, "Scene file (JSON): bodies, explicit contacts, settings")->required();
    resolve->add_option("--preset", o.preset, "Settings preset the case's own settings apply on top of")
        ->check(CLI::IsMember(preset_choices()));
    resolve->add_option("--set", o.settings,
                        "Change one setting, e.g. --set position_method=linear_projection or "
                        "--set angular_limit.policy=angle (repeatable; applied after the case's settings)");
    resolve->add_option("--trace", o.trace_file, "Write the trace (JSON) to this file, atomically");
    resolve->add_option("--record", o.record,
                        "Record only part of the run: frames=A..B or contacts=I,J,... (repeatable)");
    add_max_trace_mb(*resolve, o.max_trace_mb);
    resolve->add_flag("--explain", o.explain,
                      "Print every derivation step as a table: quantity, value, formula, equation, meaning");
}

void add_run(CLI::App& app, RunOptions& o) {
    CLI::App* run = app.add_subcommand(
        "run",
        "Simulate a scene frame by frame (integrate, detect contacts, resolve them) and summarise it.\n"
        "Example: impulse-lab run scenes/stack_3.json --trace stack.json --record frames=0..9");
    run->add_option("SCENE", o.scene_file, "Scene file (JSON)")->required();
    run->add_option("--frames", o.frames, "Frames to simulate (default: the scene's settings.frames, 600)")
        ->check(whole_number(1, 10000000));
    run->add_option("--dt", o.dt, "Frame duration in seconds (default: the scene's settings.duration, 1/60)")
        ->check(finite_number(1e-6, 10.0));
    run->add_option("--preset", o.preset, "Settings preset the scene's own settings apply on top of")
        ->check(CLI::IsMember(preset_choices()));
    run->add_option("--set", o.settings, "Change one setting, e.g. --set position_epsilon=0.001 (repeatable)");
    run->add_option("--trace", o.trace_file, "Write the trace of the recorded frames (JSON), atomically");
    run->add_option("--record", o.record,
                    "Record only part of the run: frames=A..B or contacts=I,J,... (default: every frame)");
    add_max_trace_mb(*run, o.max_trace_mb);
    run->add_option("--states", o.states_file, "Write every body's state per frame as CSV, atomically");
}

// How a case or scene is run before it is looked at: the same four flags for inspect, worksheet and diff.
void add_open_options(CLI::App& command, inspect::OpenOptions& o, const std::string& what) {
    command.add_option("--preset", o.preset, "Settings preset for " + what)->check(CLI::IsMember(preset_choices()));
    command.add_option("--set", o.settings, "Change one setting of " + what + " (repeatable)");
    command.add_option("--record", o.record, "Record only frames=A..B or contacts=I,J,... of " + what);
    command.add_option("--frames", o.frames, "Frames to simulate for a scene (default: its own, at most 60)")
        ->check(whole_number(1, 100000));
    add_max_trace_mb(command, o.max_trace_mb);
}

void add_inspect(CLI::App& app, InspectOptions& o) {
    CLI::App* inspect = app.add_subcommand(
        "inspect",
        "Step through a case, scene or trace in a window (or headless, to PNG files).\n"
        "Keys: ←/→ step, ↑/↓ contact or iteration, PgUp/PgDn phase, Home/End first/last.\n"
        "Example: impulse-lab inspect scenes/cases/ruler.json --headless --goto phase=position,step=angular_change "
        "--screenshot ruler.png");
    inspect->add_option("FILE", o.file, "Case (resolved once), scene (simulated, then inspected) or trace (JSON)")
        ->required();
    inspect->add_flag("--headless", o.headless,
                      "Render offscreen, without a display: needs --screenshot, --script "
                      "or --bench-frames");
    inspect->add_option("--size", o.size, "Window or image size WxH in pixels (default 1280x800)");
    inspect->add_option("--goto", o.go_to,
                        "Start at frame=F,phase=preparation|position|velocity,iteration=I,contact=C,step=NAME "
                        "(any parts; step may name a step or a quantity)");
    inspect->add_option("--script", o.script,
                        "Run actions from a file, one per line: next/prev step|contact|iteration|item|phase [N], "
                        "first, last, goto SPEC, set NAME VALUE, view front|top|side|3d, screenshot FILE, "
                        "export trace FILE, export table FILE, quit");
    inspect->add_option("--screenshot", o.screenshot, "Save a PNG of the window at the end, then close");
    inspect
        ->add_option("--bench-frames", o.bench_frames,
                     "Render N frames stepping one derivation step per frame; print frame-time percentiles")
        ->check(whole_number(1, 1000000));
    add_open_options(*inspect, o.open, "a case or scene");
}

void add_lesson(CLI::App& app, LessonOptions& o) {
    CLI::App* lesson = app.add_subcommand(
        "lesson",
        "The course on chapter 14: without N, the lessons and your progress; with N, that lesson in the\n"
        "inspector (a window; with --headless or without a display, annotated text and PNGs in a folder).\n"
        "Example: impulse-lab lesson 1");
    lesson->add_option("N", o.number, "Lesson number")->check(whole_number(1, 99));
    lesson->add_flag("--headless", o.headless, "Print the lesson as text; write its trace and a PNG per step");
    lesson->add_option("--out", o.out, "Folder for the headless lesson's files (default lesson-NN)");
    lesson->add_option("--lessons", o.lessons_folder, "Folder of lesson files (default: the repository's lessons/)");
    lesson->add_option("--size", o.size, "Window or image size WxH in pixels (default 1280x800)");
    lesson->add_option("--script", o.script, "Window: run inspect's actions first (e.g. lesson step 3, next step)");
    lesson->add_option("--screenshot", o.screenshot, "Window: save a PNG after the script, then close");
}

void add_worksheet(CLI::App& app, WorksheetOptions& o) {
    CLI::App* worksheet = app.add_subcommand(
        "worksheet",
        "Make a worksheet: the inputs and blank cells of chosen derivation steps, for students to fill in.\n"
        "Example: impulse-lab worksheet scenes/cases/ruler.json --steps phase=velocity,iteration=0 --out ruler.csv");
    worksheet
        ->add_option("FILE", o.file,
                     "Lesson (lessons/NN-name.md: its run and its steps), case (resolved once), scene "
                     "(simulated) or trace (JSON)")
        ->required();
    worksheet->add_option("--steps", o.steps,
                          "A place as --goto takes it: frame=F,phase=preparation|position|velocity,iteration=I,"
                          "contact=C,step=NAME; without step=, every step of that contact or iteration "
                          "(repeatable; default: every step of the first recorded frame)");
    worksheet->add_option("--out", o.out, "The worksheet: .json or .csv (one row per number), written atomically")
        ->required();
    add_open_options(*worksheet, o.open, "a case or scene");
}

void add_diff(CLI::App& app, DiffOptions& o) {
    CLI::App* diff = app.add_subcommand(
        "diff",
        "Compare traces or filled worksheets with a reference, value by value; the first divergence is marked.\n"
        "Several files (or a folder) give a class summary; --out DIR writes the class report (summary.csv,\n"
        "cells.csv, a feedback page per student). Exit 0 all match, 1 mismatches or blanks, 2 bad input.\n"
        "Example: impulse-lab diff lessons/07-calculating-and-applying-the-impulse.md submissions/ --rtol 1e-4 "
        "--out report/");
    diff->add_option("REFERENCE", o.reference,
                     "Lesson (run as worksheet runs it); worksheet (re-run as it was made); case or scene (run as "
                     "inspect runs it); or a trace")
        ->required();
    diff->add_option("OTHER", o.others, "Traces or filled worksheets (.json, .csv), or folders of them")->required();
    diff->add_option("--rtol", o.rtol,
                     "Relative tolerance: numbers match when |b − a| ≤ atol + rtol·|a| (default 1e-9)");
    diff->add_option("--atol", o.atol, "Absolute tolerance (default 1e-12)");
    diff->add_option("--format", o.format, "Report as text (default), json or csv")
        ->check(CLI::IsMember({"text", "json", "csv"}));
    diff->add_option("--out", o.out,
                     "One file: also write the report to this file. A class: the folder of the class report. "
                     "Written atomically");
    add_open_options(*diff, o.open, "a case or scene reference");
}

void add_bench(CLI::App& app, BenchOptions& o) {
    CLI::App* bench = app.add_subcommand(
        "bench",
        "Time every scene x method x iteration count (recorder off) and judge its accuracy; write results.csv,\n"
        "results.json, speed_accuracy.png, stability.md and stability.png (docs/bench.md).\n"
        "Example: impulse-lab bench --scenes stack_10,box_resting --methods book,pgs --iterations 1,4,16");
    bench->add_option("--scenes", o.scenes,
                      "Bench scenes, comma-separated (default: all: stack_10, stack_20, pyramid_20, brick_wall, "
                      "mass_ratio_100, mass_ratio_1000, deep_plank, box_resting, spinning_box, grid_1000, "
                      "sphere_drop, two_spheres)");
    bench->add_option("--methods", o.methods,
                      "Presets, comma-separated (default: book, sweep, pgs, pgs_split, soft_step)");
    bench->add_option("--iterations", o.iterations,
                      "Iteration counts N, comma-separated (default 1,2,4,8,16,32): iterations_per_contact for "
                      "worst-first, sweeps for sweep/pgs/pgs_split, substeps for soft_step");
    bench
        ->add_option("--repeats", o.repeats,
                     "Timed windows per configuration; the median step time is kept (default 3)")
        ->check(whole_number(1, 1000));
    bench->add_option("--out", o.out, "Folder for the five result files (default bench-results/), written atomically");
    bench->add_option("--frames", o.frames, "Simulate this many frames of every scene instead of its own duration")
        ->check(whole_number(1, 100000));
    bench->add_option("--scene-dir", o.scene_dir, "Folder of the scene files (default: the repository's scenes/)");
    bench->add_flag("--scaling", o.scaling,
                    "Instead: time per resolved contact of the book preset on grid_10, grid_100, grid_1000 with "
                    "worst_first_search priority_queue and full_scan; prints it and writes scaling.csv");
}

void add_validate(CLI::App& app, std::vector<std::string>& files) {
    CLI::App* validate = app.add_subcommand("validate", "Check case, trace and lesson files");
    validate->add_option("FILE", files, "Scene, case or trace files (JSON), lesson files (lessons/NN-name.md)")
        ->required();
}

// CLI11 forms of a user's mistake as one line: "impulse-lab resolve: --preset: ..." with a pointer to help.
std::string one_line(const std::string& text) {
    std::string line = text;
    std::replace(line.begin(), line.end(), '\n', ' ');
    while (!line.empty() && line.back() == ' ') line.pop_back();
    return line;
}

}  // namespace

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal) {
    CLI::App app{"Impulse Lab: step through rigid-body collision resolution (Millington, ch. 14)", "impulse-lab"};
    app.set_version_flag("--version", version_text);
    app.require_subcommand(1);
    ResolveOptions resolve;
    RunOptions run_options;
    std::vector<std::string> validate_files;
    InspectOptions inspect;
    LessonOptions lesson;
    add_resolve(app, resolve);
    add_run(app, run_options);
    add_inspect(app, inspect);
    add_lesson(app, lesson);
    add_validate(app, validate_files);
    WorksheetOptions worksheet;
    DiffOptions diff;
    add_worksheet(app, worksheet);
    add_diff(app, diff);
    BenchOptions bench;
    add_bench(app, bench);

    // CLI11 would say only "A subcommand is required" for a misspelt command; name it instead.
    const auto is_command = [&app](const std::string& name) {
        return !app.get_subcommands([&name](const CLI::App* sub) { return sub->get_name() == name; }).empty();
    };
    if (!args.empty() && !args[0].empty() && args[0][0] != '-' && !is_command(args[0])) {
        err << "impulse-lab: unknown command \"" << args[0]
            << "\" (commands: resolve, run, inspect, lesson, validate, worksheet, diff, bench; see impulse-lab --help)\n";
        return exit_bad_input;
    }
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
        app.parse(reversed);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForVersion& e) {
        out << version_text << '\n';
        return exit_ok;
    } catch (const CLI::ParseError& e) {
        err << "impulse-lab: " << one_line(e.what()) << " (see impulse-lab --help)\n";
        return exit_bad_input;
    }

    try {
        if (app.got_subcommand("resolve")) return resolve_command(resolve, out, err);
        if (app.got_subcommand("run")) return run_command(run_options, out, err, err_is_terminal ? &err : nullptr);
        if (app.got_subcommand("inspect")) return inspect_command(inspect, out, err);
        if (app.got_subcommand("lesson")) return lesson_command(lesson, out, err);
        if (app.got_subcommand("worksheet")) return worksheet_command(worksheet, out, err);
        if (app.got_subcommand("diff")) return diff_command(diff, out, err);
        if (app.got_subcommand("bench"))
            return bench_command(bench, out, err, err_is_terminal ? &err : nullptr);
        return validate_command(validate_files, out, err);
    } catch (const Interrupted& e) {
        err << "impulse-lab: interrupted (" << (e.signal == SIGTERM ? "SIGTERM" : "SIGINT")
            << "): no file written, those already there are unchanged\n";
        return 128 + e.signal;
    } catch (const FileError& e) {
        err << "impulse-lab: " << e.file << ": " << (e.where.empty() ? "" : e.where + ": ") << e.problem << '\n';
        return exit_bad_input;
    } catch (const io::InputError& e) {
        err << "impulse-lab: " << e.what() << '\n';
        return exit_bad_input;
    } catch (const std::exception& e) {
        err << "impulse-lab: internal error: " << e.what() << '\n';
        return exit_failure;
    }
}

}  // namespace impulse::cli
