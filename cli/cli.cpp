#include "cli/cli.hpp"
#include "cli/deferred_signals.hpp"

#include "bench/adapters/engine_adapter.hpp"
#include "bench/bench_plan.hpp"
#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_files.hpp"
#include "cli/interrupt.hpp"
#include "cli/states_csv.hpp"
#include "formats/input_error.hpp"
#include "formats/printable_text.hpp"
#include "formats/suggest.hpp"
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

// --max-trace-mb, for every command that records a trace.
void add_max_trace_mb(CLI::App& command, std::optional<double>& max_trace_mb, FlagCatalog& c) {
    std::ostringstream default_mb;
    default_mb << formats::default_max_trace_mb;
    finite_number(
        command.add_option("--max-trace-mb", max_trace_mb,
                           "Stop recording when the trace would pass this size in MB (estimated; default " +
                               default_mb.str() + "): it then ends with the last whole frame, and the run goes on"),
        c, 1e-6, 1e9);
}

void add_resolve(CLI::App& app, ResolveOptions& o, FlagCatalog& c) {
    CLI::App* resolve = app.add_subcommand("resolve",
                                           "Resolve a case's contacts once and record every derivation step.\n"
                                           "Example: impulse-lab resolve scenes/cases/ruler.json --explain");
    input_file(resolve->add_option("CASE", o.case_file, "Scene file (JSON): bodies, explicit contacts, settings"), c)
        ->required();
    one_of(resolve->add_option("--preset", o.preset, "Settings preset the case's own settings apply on top of"), c,
           preset_choices(), "PRESET");
    resolve
        ->add_option("--set", o.settings,
                     "Change one setting, e.g. --set position_method=linear_projection or "
                     "--set angular_limit.policy=angle (repeatable; applied after the case's settings)")
        ->type_name("NAME=VALUE");
    output_file(resolve->add_option("--trace", o.trace_file, "Write the trace (JSON) to this file, atomically"), c);
    resolve
        ->add_option("--record", o.record, "Record only part of the run: frames=A..B or contacts=I,J,... (repeatable)")
        ->type_name("SPEC");
    add_max_trace_mb(*resolve, o.max_trace_mb, c);
    resolve->add_flag("--explain", o.explain,
                      "Print every derivation step as a table: quantity, value, formula, equation, meaning");
}

void add_run(CLI::App& app, RunOptions& o, FlagCatalog& c) {
    CLI::App* run = app.add_subcommand(
        "run",
        "Simulate a scene frame by frame (integrate, detect contacts, resolve them) and summarise it.\n"
        "Example: impulse-lab run scenes/stack_3.json --trace stack.json --record frames=0..9");
    input_file(run->add_option("SCENE", o.scene_file, "Scene file (JSON)"), c)->required();
    whole_number(
        run->add_option("--frames", o.frames, "Frames to simulate (default: the scene's settings.frames, 600)"), c, 1,
        10000000);
    finite_number(
        run->add_option("--dt", o.dt, "Frame duration in seconds (default: the scene's settings.duration, 1/60)"), c,
        1e-6, 10.0);
    one_of(run->add_option("--preset", o.preset, "Settings preset the scene's own settings apply on top of"), c,
           preset_choices(), "PRESET");
    run->add_option("--set", o.settings, "Change one setting, e.g. --set position_epsilon=0.001 (repeatable)")
        ->type_name("NAME=VALUE");
    output_file(run->add_option("--trace", o.trace_file, "Write the trace of the recorded frames (JSON), atomically"),
                c);
    run->add_option("--record", o.record,
                    "Record only part of the run: frames=A..B or contacts=I,J,... (default: every frame)")
        ->type_name("SPEC");
    add_max_trace_mb(*run, o.max_trace_mb, c);
    output_file(run->add_option("--states", o.states_file, "Write every body's state per frame as CSV, atomically"), c);
    std::ostringstream default_states_mb;
    default_states_mb << default_max_states_mb;
    finite_number(run->add_option("--max-states-mb", o.max_states_mb,
                                  "Stop writing --states when its CSV would pass this size in MB (default " +
                                      default_states_mb.str() +
                                      "): it then ends with the last whole frame, and the "
                                      "run goes on"),
                  c, 1e-6, 1e9);
    run->add_flag("--keep-partial", o.keep_partial,
                  "When Ctrl-C or SIGTERM stops the run, write the trace and states of the frames done (they are "
                  "valid files); without it nothing is written and the summary of those frames is printed");
}

// How a case or scene is run before it is looked at: the same four flags for inspect, worksheet and diff.
void add_open_options(CLI::App& command, model::OpenOptions& o, const std::string& what, FlagCatalog& c) {
    one_of(command.add_option("--preset", o.preset, "Settings preset for " + what), c, preset_choices(), "PRESET");
    command.add_option("--set", o.settings, "Change one setting of " + what + " (repeatable)")->type_name("NAME=VALUE");
    command.add_option("--record", o.record, "Record only frames=A..B or contacts=I,J,... of " + what)
        ->type_name("SPEC");
    whole_number(
        command.add_option("--frames", o.frames, "Frames to simulate for a scene (default: its own, at most 60)"), c, 1,
        100000);
    add_max_trace_mb(command, o.max_trace_mb, c);
}

void add_inspect(CLI::App& app, InspectOptions& o, FlagCatalog& c) {
    CLI::App* inspect = app.add_subcommand(
        "inspect",
        "Step through a case, scene or trace in a window (or headless, to PNG files).\n"
        "Keys: Left/Right step, Up/Down contact or iteration, PgUp/PgDn phase, Home/End first/last.\n"
        "Example: impulse-lab inspect scenes/cases/ruler.json --headless --goto phase=position,step=angular_change "
        "--screenshot ruler.png");
    input_file(
        inspect->add_option("FILE", o.file, "Case (resolved once), scene (simulated, then inspected) or trace (JSON)"),
        c)
        ->required();
    inspect->add_flag("--headless", o.headless,
                      "Render offscreen, without a display: needs --screenshot, --script "
                      "or --bench-frames");
    inspect
        ->add_option("--size", o.size,
                     "Window or image size WxH in pixels (default: a window 90 % of the display, an image 1280x800)")
        ->type_name("WxH");
    inspect
        ->add_option("--goto", o.go_to,
                     "Start at frame=F,phase=preparation|position|velocity,iteration=I,contact=C,step=NAME "
                     "(any parts; step may name a step or a quantity)")
        ->type_name("SPEC");
    input_file(inspect->add_option("--script", o.script,
                                   "Run actions from a file, one per line: next/prev step|contact|iteration|item|phase "
                                   "[N], first, last, goto SPEC, set NAME VALUE, view front|top|side|3d, key NAME (key "
                                   "ctrl+s), type what is typed (type 7,5 m/s), screenshot FILE, export trace FILE, "
                                   "export table FILE, quit"),
               c);
    CLI::Option* screenshot = output_file(
        inspect->add_option("--screenshot", o.screenshot, "Save a PNG of the window at the end, then close"), c);
    screenshot->description(screenshot->get_description() + " when that is not a terminal");
    whole_number(inspect->add_option("--bench-frames", o.bench_frames,
                                     "Render N frames stepping one derivation step per frame; print frame-time "
                                     "percentiles"),
                 c, 1, 1000000);
    add_open_options(*inspect, o.open, "a case or scene", c);
}

void add_lesson(CLI::App& app, LessonOptions& o, FlagCatalog& c) {
    CLI::App* lesson = app.add_subcommand(
        "lesson",
        "The course on chapter 14: without N, the lessons and your progress; with N, that lesson in the\n"
        "inspector's window; with --text, or without a display in a terminal, asked in the terminal; with\n"
        "--headless, or with neither, annotated text with the answers and PNGs in a folder.\n"
        "Example: impulse-lab lesson 1");
    whole_number(lesson->add_option("N", o.number, "Lesson number"), c, 1, 99);
    lesson->add_flag("--headless", o.headless,
                     "Print the lesson as text; write its trace and a PNG per step (with --script: take the lesson "
                     "offscreen, driven by the script's keys)");
    lesson->add_flag("--text", o.text,
                     "Take the lesson in this terminal: it asks each question and waits (without a terminal to read "
                     "from, it prints the lesson with the answers)");
    folder(lesson->add_option("--out", o.out, "Folder for the headless lesson's files (default lesson-NN)"), c);
    folder(lesson->add_option("--lessons", o.lessons_folder,
                              "Folder of lesson files (default: the installed course, share/impulse-lab/lessons)"),
           c);
    lesson
        ->add_option("--size", o.size,
                     "Window or image size WxH in pixels (default: a window 90 % of the display, an image 1280x800)")
        ->type_name("WxH");
    input_file(lesson->add_option("--script", o.script,
                                  "Window: run inspect's actions first (e.g. lesson step 3, key Right, type 7,5)"),
               c);
    output_file(lesson->add_option("--screenshot", o.screenshot, "Window: save a PNG after the script, then close"), c);
    lesson
        ->add_option("--set", o.settings,
                     "Run the lesson with one more setting, e.g. --set sliding_friction=reference (repeatable); its "
                     "questions are then graded against that run, and progress is not saved")
        ->type_name("NAME=VALUE");
}

void add_worksheet(CLI::App& app, WorksheetOptions& o, FlagCatalog& c) {
    CLI::App* worksheet = app.add_subcommand(
        "worksheet",
        "Make a worksheet: the inputs and blank cells of chosen derivation steps, for students to fill in.\n"
        "Example: impulse-lab worksheet scenes/cases/ruler.json --steps phase=velocity,iteration=0 --out ruler.csv");
    input_file(worksheet->add_option("FILE", o.file,
                                     "Lesson (lessons/NN-name.md: its run and its steps), case (resolved once), scene "
                                     "(simulated) or trace (JSON)"),
               c)
        ->required();
    worksheet
        ->add_option("--steps", o.steps,
                     "A place as --goto takes it: frame=F,phase=preparation|position|velocity,iteration=I,"
                     "contact=C,step=NAME; without step=, every step of that contact or iteration "
                     "(repeatable; default: every step of the first recorded frame)")
        ->type_name("SPEC");
    output_file(worksheet->add_option("--out", o.out,
                                      "The worksheet: .json or .csv (one row per number), written atomically "
                                      "(standard output gets JSON)"),
                c)
        ->required();
    add_open_options(*worksheet, o.open, "a case or scene", c);
}

void add_diff(CLI::App& app, DiffOptions& o, FlagCatalog& c) {
    CLI::App* diff = app.add_subcommand(
        "diff",
        "Compare traces or filled worksheets with a reference, value by value; the first divergence is marked.\n"
        "Several files (or a folder) give a class summary; --out DIR writes the class report (summary.csv,\n"
        "cells.csv, a feedback page per student). Exit 0 all match, 1 mismatches or blanks, 2 bad input.\n"
        "Example: impulse-lab diff lessons/07-calculating-and-applying-the-impulse.md submissions/ --rtol 1e-4 "
        "--out report/");
    input_file(diff->add_option("REFERENCE", o.reference,
                                "Lesson (run as worksheet runs it); worksheet (re-run as it was made); case or scene "
                                "(run as inspect runs it); or a trace"),
               c)
        ->required();
    input_file(diff->add_option("OTHER", o.others, "Traces or filled worksheets (.json, .csv), or folders of them"), c)
        ->required();
    diff->add_option("--rtol", o.rtol,
                     "Relative tolerance: numbers match when |b - a| <= atol + rtol * |a| (default 1e-9)")
        ->type_name("NUMBER");
    diff->add_option("--atol", o.atol, "Absolute tolerance (default 1e-12)")->type_name("NUMBER");
    one_of(diff->add_option("--format", o.format, "Report as text (default), json or csv"), c, {"text", "json", "csv"},
           "FORMAT");
    output_file(diff->add_option("--out", o.out,
                                 "One file: also write the report to this file (- is standard output). A class: the "
                                 "folder of the class report. Written atomically"),
                c);
    add_open_options(*diff, o.open, "a case or scene reference", c);
}

void add_bench(CLI::App& app, BenchOptions& o, FlagCatalog& c) {
    CLI::App* bench = app.add_subcommand(
        "bench",
        "Time every scene x method x iteration count (recorder off) and judge its accuracy; write results.csv,\n"
        "results.json, speed_accuracy.png, stability.md and stability.png (docs/bench.md).\n"
        "Example: impulse-lab bench --scenes stack_10,box_resting --methods book,pgs --iterations 1,4,16");
    std::string standard, large;  // each suite's scenes, for the help
    for (const bench::ShippedScene& s : bench::shipped_bench_scenes()) {
        std::string& list = s.suite == bench::Suite::large ? large : standard;
        list += (list.empty() ? "" : ", ") + std::string(s.name);
    }
    bench
        ->add_option("--scenes", o.scenes,
                     "Bench scenes or scene files, comma-separated: a name (the default suite: " + standard +
                         "; the large suite: " + large +
                         ") or a path (e.g. scenes/stack_3.json), judged by its \"bench\" block or by the general "
                         "measures")
        ->type_name("LIST");
    one_of(bench->add_option("--suite", o.suite,
                             "Without --scenes: the default suite (default) or the large suite (" + large +
                                 "), minutes a configuration"),
           c, {"default", "large"}, "SUITE");
    std::string engines, methods;
    for (const bench::EngineRow& e : bench::built_engines()) engines += std::string(", ") + std::string(e.name);
    for (const std::string& m : bench::default_methods()) methods += (methods.empty() ? "" : ", ") + m;
    bench
        ->add_option("--methods", o.methods,
                     "Presets or other engines, comma-separated (default: " + methods +
                         "; engines in this build: " + (engines.empty() ? "none" : engines.substr(2)) + ")")
        ->type_name("LIST");
    bench
        ->add_option("--iterations", o.iterations,
                     "Iteration counts N, comma-separated (default 1,2,4,8,16,32): iterations_per_contact for "
                     "worst-first, sweeps for sweep/pgs/pgs_split, substeps for soft_step, iterations for avbd")
        ->type_name("LIST");
    whole_number(bench->add_option("--repeats", o.repeats,
                                   "Timed windows per configuration; the median step time is kept (default 3)"),
                 c, 1, 1000);
    folder(bench->add_option("--out", o.out,
                             "Folder for the five result files (default bench-results/), written atomically"),
           c);
    whole_number(
        bench->add_option("--frames", o.frames, "Simulate this many frames of every scene instead of its own duration"),
        c, 1, 100000);
    folder(bench->add_option("--scene-dir", o.scene_dir,
                             "Folder of the scene files (default: the installed scenes, share/impulse-lab/scenes)"),
           c);
    formatted(bench->add_option("--shard", o.shard,
                                "Run only the K-th of N shares of the configurations (every N-th from the K-th, "
                                "scene-major, then method, then N) and write their results; join the shards with "
                                "--merge"),
              c, "K/N", "K/N: whole numbers, 1 <= K <= N <= 10000", [](const std::string& text) -> std::string {
                  try {
                      bench::parse_shard(text);
                  } catch (const formats::InputError& e) {
                      return e.problem();
                  }
                  return {};
              });
    folder(bench->add_option("--merge", o.merge,
                             "Instead of running: join the results.json of these shard folders (each from --shard "
                             "K/N, every K once) and write the same five files into --out"),
           c)
        ->expected(1, -1);
    bench->add_flag("--scaling", o.scaling,
                    "Instead: time per resolved contact of the book preset on grid_10, grid_100, grid_1000 with "
                    "worst_first_search priority_queue and full_scan; prints it and writes scaling.csv");
}

void add_validate(CLI::App& app, std::vector<std::string>& files, FlagCatalog& c) {
    CLI::App* validate = app.add_subcommand(
        "validate", "Check case, trace and lesson files. Exit 0 all valid, 1 some invalid, 2 a file cannot be read.");
    input_file(
        validate->add_option("FILE", files, "Scene, case or trace files (JSON), lesson files (lessons/NN-name.md)"), c)
        ->required();
}

// `impulse-lab help [COMMAND]` and `impulse-lab completion bash`: answered before the other commands are parsed.
void add_help_and_completion(CLI::App& app, FlagCatalog& c, const std::vector<std::string>& commands,
                             std::string& command, std::string& shell) {
    CLI::App* help = app.add_subcommand("help", "Print the help of impulse-lab, or of one command");
    one_of(help->add_option("COMMAND", command, "The command"), c, commands, "COMMAND");
    CLI::App* completion = app.add_subcommand("completion",
                                              "Print the bash completion script (source it, or install it as "
                                              "share/bash-completion/completions/impulse-lab)");
    one_of(completion->add_option("SHELL", shell, "The shell")->required(), c, {"bash"}, "SHELL");
}

// The exit codes: one table, for the help's footer, the manual page and the README.
const std::vector<std::pair<std::string, std::string>> exit_codes{
    {"0", "done"},
    {"1", "a verdict: diff found a mismatch or a blank cell, validate an invalid file"},
    {"2", "bad input or flags: one line names the file and JSON path, or the flag, and what is wrong"},
    {"3", "a run stopped because a body's state became NaN or infinite (the frames before it are written)"},
    {"70", "an internal error (EX_SOFTWARE)"},
    {"130, 143", "interrupted by Ctrl-C (SIGINT) or SIGTERM"},
};

std::string footer_text() {
    std::string text = "Exit codes:";
    for (const auto& [code, meaning] : exit_codes)
        text += " " + code + " " + meaning.substr(0, meaning.find(':')) + ";";
    text.back() = '.';
    return text +
           "\nA file argument may be - for standard input (a file read) or standard output (a file written).\n"
           "Run 'impulse-lab help COMMAND' for a command's flags.";
}

const char* const introduction =
    "A step-through debugger for rigid-body collision resolution, following chapter 14 (\"Collision "
    "Resolution\") of Ian Millington's Game Physics Engine Development and its reference engine. The engine "
    "resolves contacts the chapter's way (and by other methods) and records every intermediate value of every "
    "contact; impulse-lab prints each beside its formula and the chapter's equation, steps through them in a window, "
    "teaches them in a course of lessons, and writes and grades coursework. Start with: impulse-lab lesson 1.";

std::vector<HelpSection> manual_sections() {
    std::vector<HelpSection> sections;
    sections.push_back({"Standard streams",
                        {{"-",
                          "As a file argument: standard input for a file read (a scene, case, trace, worksheet or "
                          "script), standard output for a file written (a trace, states, worksheet, report, a "
                          "script's exported table or trace, or a screenshot). At most one argument of a command "
                          "reads standard input and one writes standard output; when standard output carries a "
                          "file, the command's report goes to standard error."},
                         {"/dev/stdout",
                          "The same as -. Any other output is written atomically (a temporary file renamed over "
                          "it); a symbolic link is followed and its target replaced; a FIFO, a terminal or a device "
                          "is written in place."}}});
    sections.push_back({"Exit status", exit_codes});
    sections.push_back({"Files",
                        {{"$XDG_CONFIG_HOME/impulse-lab/progress.json",
                          "The course's progress (answers and the step reached), per user; "
                          "~/.config/impulse-lab/progress.json when XDG_CONFIG_HOME is not set."}}});
    return sections;
}

}  // namespace

std::string error_line(std::string_view file, std::string_view what) {
    return "impulse-lab: " + (file.empty() ? std::string() : formats::one_line(file) + ": ") + formats::one_line(what) +
           "\n";
}

std::string error_line(const formats::FileError& e) {
    return error_line(e.file, e.where.empty() ? e.problem : e.where + ": " + e.problem);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal,
        std::istream* terminal_in) {
    install_deferred_signals();
    CLI::App app{"Impulse Lab: step through rigid-body collision resolution (Millington, ch. 14)", "impulse-lab"};
    app.set_version_flag("--version", version_text);
    app.footer(footer_text());
    // Words a user reads; the commands share the program's formatter.
    app.get_formatter()->label("REQUIRED", "(required)");
    app.get_formatter()->label("SUBCOMMAND", "COMMAND");
    app.require_subcommand(1);
    FlagCatalog catalog;
    ResolveOptions resolve;
    RunOptions run_options;
    std::vector<std::string> validate_files;
    InspectOptions inspect;
    LessonOptions lesson;
    add_resolve(app, resolve, catalog);
    add_run(app, run_options, catalog);
    add_inspect(app, inspect, catalog);
    add_lesson(app, lesson, catalog);
    add_validate(app, validate_files, catalog);
    WorksheetOptions worksheet;
    DiffOptions diff;
    add_worksheet(app, worksheet, catalog);
    add_diff(app, diff, catalog);
    BenchOptions bench;
    add_bench(app, bench, catalog);
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
        commands.push_back(sub->get_name());
    std::string help_command, completion_shell;
    add_help_and_completion(app, catalog, commands, help_command, completion_shell);
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) command->group("Commands");
    // Answered before parsing (below); a flag here so that the help and the completion list it.
    bool help_all = false;
    app.add_flag("--help-all", help_all, "Print the help of every command (the manual page is made from it)");
    commands.push_back("help");
    commands.push_back("completion");

    const auto command_named = [&app](const std::string& name) -> CLI::App* {
        const auto found = app.get_subcommands([&name](const CLI::App* sub) { return sub->get_name() == name; });
        return found.empty() ? nullptr : const_cast<CLI::App*>(found.front());
    };
    const auto unknown_command = [&](const std::string& name) {
        const auto meant = formats::closest_name(name, commands);
        err << "impulse-lab: unknown command \"" << name << "\""
            << (meant ? " (did you mean " + *meant + "?)" : std::string()) << "; commands: ";
        for (std::size_t i = 0; i < commands.size(); ++i) err << (i ? ", " : "") << commands[i];
        err << "; see impulse-lab help\n";
        return exit_bad_input;
    };
    if (args.empty()) {
        err << "impulse-lab: a command is required, e.g. impulse-lab lesson 1; see impulse-lab help\n";
        return exit_bad_input;
    }
    // CLI11 would say only "A subcommand is required" for a misspelt command; name it instead.
    if (!args[0].empty() && args[0][0] != '-' && !command_named(args[0])) return unknown_command(args[0]);
    if (args[0] == "--help-all") {
        out << help_all_text(app, introduction, manual_sections());
        return exit_ok;
    }
    if (args[0] == "help") {
        if (args.size() == 2 && (args[1] == "--help" || args[1] == "-h")) {
            out << command_named("help")->help("impulse-lab");
            return exit_ok;
        }
        if (args.size() > 2)
            err << "impulse-lab: help: takes one command, got " << args.size() - 1
                << " arguments; see impulse-lab help\n";
        else if (args.size() == 2 && !command_named(args[1]))
            return unknown_command(args[1]);
        else {
            out << (args.size() == 1 ? app.help() : command_named(args[1])->help("impulse-lab"));
            return exit_ok;
        }
        return exit_bad_input;
    }
    try {
        std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
        app.parse(reversed);
        for (const CLI::App* command : app.get_subcommands()) check_standard_streams(*command, catalog);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e, out, err);
    } catch (const CLI::CallForVersion& e) {
        out << version_text << '\n';
        return exit_ok;
    } catch (const CLI::ParseError& e) {
        err << error_line("", parse_error_line(app, catalog, args, e));
        return exit_bad_input;
    } catch (const formats::InputError& e) {
        err << error_line("", e.what());
        return exit_bad_input;
    }

    try {
        if (app.got_subcommand("resolve")) return resolve_command(resolve, out, err);
        if (app.got_subcommand("run")) return run_command(run_options, out, err, err_is_terminal ? &err : nullptr);
        if (app.got_subcommand("inspect")) return inspect_command(inspect, out, err);
        if (app.got_subcommand("lesson")) {
            lesson.terminal = terminal_in;
            return lesson_command(lesson, out, err);
        }
        if (app.got_subcommand("worksheet")) return worksheet_command(worksheet, out, err);
        if (app.got_subcommand("diff")) return diff_command(diff, out, err);
        if (app.got_subcommand("bench")) return bench_command(bench, out, err, err_is_terminal ? &err : nullptr);
        if (app.got_subcommand("completion")) {
            out << bash_completion(app, catalog);
            return exit_ok;
        }
        return validate_command(validate_files, out, err);
    } catch (const Interrupted& e) {
        err << "impulse-lab: interrupted (" << signal_name(e.signal)
            << "): no file written, those already there are unchanged\n";
        return 128 + e.signal;
    } catch (const formats::WaitInterrupted& e) {
        // The signal was held back while the files were written and delivered as the wait gave up: `run`'s
        // handler noted it; a command without one ended with it already.
        const int signal = interrupt_received().value_or(SIGINT);
        err << error_line("", "interrupted (" + std::string(signal_name(signal)) + ") while " + e.flag + " '" + e.path +
                                  "' waited for its reader: it got nothing");
        return 128 + signal;
    } catch (const formats::FileError& e) {
        err << error_line(e);
        return exit_bad_input;
    } catch (const formats::InputError& e) {
        err << error_line("", e.what());
        return exit_bad_input;
    } catch (const std::exception& e) {
        err << error_line("", std::string("internal error: ") + e.what());
        return exit_internal_error;
    } catch (...) {
        err << "impulse-lab: internal error: an unknown exception\n";
        return exit_internal_error;
    }
}

}  // namespace impulse::cli
