// `impulse-lab inspect FILE`: open a case, scene or trace in the inspector, in a window or headless.

#include "formats/trace_format1.hpp"
#include "formats/trace_json.hpp"
#include "cli/commands.hpp"
#include "formats/input_files.hpp"
#include "cli/outputs.hpp"
#include "gui/display.hpp"
#include "gui/inspector_app.hpp"
#include "formats/input_error.hpp"
#include "model/script.hpp"

#include <chrono>
#include <charconv>

namespace impulse::cli {

std::vector<model::Action> read_script_file(const std::string& path) {
    try {
        return model::parse_script(formats::read_input_file(path, formats::max_text_input_bytes));
    } catch (const formats::InputError& e) {
        throw formats::FileError{formats::input_name(path), e.where(), e.problem()};
    }
}

std::pair<int, int> parse_window_size(const std::string& text) {
    const std::size_t x = text.find('x');
    int width = 0, height = 0;
    const auto read = [](std::string_view s, int& value) {
        const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), value);
        return error == std::errc() && end == s.data() + s.size();
    };
    if (x == std::string::npos || !read(std::string_view(text).substr(0, x), width) ||
        !read(std::string_view(text).substr(x + 1), height))
        throw formats::InputError("--size", "expected WIDTHxHEIGHT in pixels, e.g. 1280x800, got \"" + text + "\"");
    if (width < 320 || height < 240 || width > 8192 || height > 8192)
        throw formats::InputError("--size", "each side must be from 320x240 to 8192x8192 pixels, got " + text);
    return {width, height};
}

int inspect_command(const InspectOptions& options, std::ostream& out, std::ostream& err) {
    gui::InspectorRun run;
    run.headless = options.headless;
    if (options.size) std::tie(run.width, run.height) = parse_window_size(*options.size);
    // Without --size a window fits the display; frame times are measured at the size asked for.
    run.fit_to_screen = !options.size && !options.bench_frames;
    if (run.headless && !options.screenshot && !options.script && !options.bench_frames)
        throw formats::InputError("--headless", "nothing to render: give --screenshot, --script or --bench-frames");
    // Before any work: a window needs a display.
    if (!run.headless && !gui::display_available())
        throw formats::InputError("inspect",
                                  "there is no display to open a window on (DISPLAY is not set); add "
                                  "--headless with --screenshot or --script to render PNG files instead");
    if (options.script) {
        run.script_name = formats::input_name(*options.script);
        run.script = read_script_file(*options.script);
    }
    // No picture or export may replace the file inspected, the script, or another of them.
    DistinctFiles files;
    files.input("the inspected FILE", options.file);
    if (options.script) files.input("the script --script", *options.script);
    for (const model::Action& a : run.script)
        if (a.kind == model::ActionKind::screenshot || a.kind == model::ActionKind::export_trace ||
            a.kind == model::ActionKind::export_table)
            files.output(run.script_name + ": line " + std::to_string(a.line), a.argument);
    if (options.screenshot) files.output("--screenshot", *options.screenshot);
    // One output may go to standard output: --screenshot -, or a script's export or screenshot to "-". A picture
    // only where that is not a terminal. What the command says goes to stderr then.
    std::optional<std::string> standard_output_by;
    const auto claim = [&](const std::string& path, const std::string& by, bool picture) {
        if (!names_standard_output(path, out)) return;
        if (standard_output_by)
            throw formats::InputError(by, "standard output (\"-\") already carries " + *standard_output_by +
                                              "; only one output can go there");
        if (picture && is_terminal(out))
            throw formats::InputError(by, "standard output is a terminal; redirect it to a file or a pipe for a PNG");
        standard_output_by = by;
    };
    for (const model::Action& a : run.script)
        if (a.kind == model::ActionKind::screenshot || a.kind == model::ActionKind::export_trace ||
            a.kind == model::ActionKind::export_table)
            claim(a.argument, run.script_name + ": line " + std::to_string(a.line),
                  a.kind == model::ActionKind::screenshot);
    if (options.screenshot) claim(*options.screenshot, "--screenshot", true);
    if (standard_output_by) run.standard_output = &out;
    std::ostream& report = standard_output_by ? err : out;

    const auto start = std::chrono::steady_clock::now();
    model::Session session = model::Session::open(options.file, options.open);
    if (session.trace().version != trace_format_version) err << formats::format1_note(options.file) << '\n';
    if (const auto note = session.recording_note())
        err << "impulse-lab: note: " << *note << "; raise --max-trace-mb or narrow --record to see later frames\n";
    // Shown up to the frame before it: the frames that led there are what there is to debug.
    if (session.broken_run())
        err << "impulse-lab: note: the run stopped at "
            << model::broken_run_text(session.trace().scene, *session.broken_run())
            << "; the frames before it are shown\n";
    run.load_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.go_to)
        session.move_to(model::resolve_goto(session.trace(), model::parse_goto(*options.go_to, "--goto"), "--goto"));
    run.screenshot = options.screenshot;
    run.bench_frames = options.bench_frames;
    return gui::run_inspector(session, run, report, err);
}

}  // namespace impulse::cli
