// `impulse-lab resolve CASE.json`: resolve the case's contacts once (one frame), write the trace, and
// explain or summarise what happened.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "formats/input_files.hpp"
#include "cli/outputs.hpp"
#include "explain/explain.hpp"
#include "formats/scene_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "model/runs.hpp"

namespace impulse::cli {

int resolve_command(const ResolveOptions& options, std::ostream& out, std::ostream& err) {
    DistinctFiles files;
    files.input("the case CASE", options.case_file);
    if (options.trace_file) files.output("--trace", *options.trace_file);
    Outputs outputs(out, err);
    outputs.add("--trace", options.trace_file);
    Scene scene;
    try {
        scene = formats::read_scene_text(formats::read_input_file(options.case_file), options.preset);
    } catch (const formats::InputError& e) {
        throw formats::FileError{formats::input_name(options.case_file), e.where(), e.problem()};
    }
    for (const std::string& assignment : options.settings) formats::apply_setting(scene, assignment, "--set");
    TraceFilter recording;
    for (const std::string& spec : options.record) formats::apply_record_spec(spec, recording);
    std::optional<int> stopped_at;
    std::optional<model::BrokenRun> broken;
    Trace trace;
    try {
        trace = model::resolve_once(scene, recording, {formats::trace_budget_bytes(options.max_trace_mb), &stopped_at},
                                    &broken);
    } catch (const formats::ContactBudgetError& e) {
        throw formats::FileError{formats::input_name(options.case_file), e.where(), e.problem()};
    }
    if (stopped_at) err << formats::trace_stopped_note(*stopped_at, options.max_trace_mb) << '\n';
    // One frame, and it broke: there is nothing before it to write.
    if (broken) {
        err << "impulse-lab: " << model::broken_run_text(scene, *broken) << "; nothing written\n";
        return exit_non_finite;
    }

    // Everything the user asked for is checked before anything is written, and the trace is written
    // atomically, so a failed run leaves no file behind.
    if (options.trace_file) outputs.write({{"--trace", formats::format_json(formats::trace_json(trace))}});
    std::ostream& report = outputs.report();
    if (options.explain)
        explain::write_explanation(report, trace);
    else
        explain::write_summary(report, trace);
    if (!outputs.file_of("--trace").empty()) report << "trace written to " << outputs.file_of("--trace") << '\n';
    return exit_ok;
}

}  // namespace impulse::cli
