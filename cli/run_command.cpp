// `impulse-lab run SCENE.json`: simulate a scene frame by frame (integrate -> detect -> resolve), record the
// frames asked for, write a CSV of every body's state per frame, and summarise the run.

#include "bench/bench_metrics.hpp"
#include "bench/bench_plan.hpp"
#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "formats/input_files.hpp"
#include "cli/interrupt.hpp"
#include "cli/outputs.hpp"
#include "cli/progress.hpp"
#include "cli/run_summary.hpp"
#include "cli/states_csv.hpp"
#include "explain/format.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "model/session.hpp"
#include "record/trace_recorder.hpp"
#include "world/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace impulse::cli {

namespace {

// The frames the recorder has finished, written to the spool of the trace's frame list and dropped from memory.
void spool_frames(Trace& trace, formats::Spool& frames) {
    for (const FrameRecord& frame : trace.frames) {
        frames.append(frames.size() == 0 ? formats::trace_frames_open : formats::trace_frames_between);
        frames.append(formats::trace_frame_text(frame, trace.scene.settings));
    }
    trace.frames.clear();
}

// As soon as the frames recorded so far show the whole run will not fit the trace's size limit: how many frames
// will, said while the run goes on rather than only at its end. Empty while it may fit.
std::string trace_fit_note(const TraceRecorder& recorder, int frames_done, int frames,
                           std::optional<double> max_trace_mb) {
    const double per_frame = static_cast<double>(recorder.estimated_bytes()) / frames_done;
    const double budget = static_cast<double>(formats::trace_budget_bytes(max_trace_mb));
    if (per_frame <= 0.0 || per_frame * frames <= budget) return {};
    return "impulse-lab: note: --trace: at about " + explain::number(std::round(per_frame / 1e5) / 10) +
           " MB a frame so far, the whole run would take about " +
           explain::number(std::round(per_frame * frames / 1e6)) +
           " MB: the trace keeps the first frames that fit in --max-trace-mb " + explain::number(budget / 1e6) +
           " and the rest run unrecorded (a note at the end says where it stopped); --record frames=A..B picks "
           "others";
}

// The scene's bench block, judged on this run: its metric against its target, and whether it held.
std::string bench_verdict(const bench::BenchScene& spec, const bench::Accuracy& a, int frames) {
    const std::string unit(bench::metric_unit(spec.metric));
    const auto with_unit = [&](double v) { return explain::with_unit(explain::number(v), unit); };
    std::string text = "  bench block: " + std::string(bench::metric_name(spec.metric)) + " " + with_unit(a.error) +
                       ", target " + with_unit(spec.target) + ": " +
                       (std::isnan(a.error)         ? "no verdict (a state became NaN)"
                        : a.meets_target && a.holds ? "meets the target"
                        : a.meets_target            ? "meets the target but fails (" + a.failure + ")"
                        : a.holds                   ? "misses the target"
                                                    : "fails (" + a.failure + ")");
    if (frames != spec.frames)
        text += "; judged over the " + std::to_string(frames) + " frames run, the block's duration is " +
                std::to_string(spec.frames) + " frames";
    return text;
}

}  // namespace

int run_command(const RunOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress) {
    // A run can take minutes: find out now, not after it, if its results could not be written.
    DistinctFiles files;
    files.input("the scene SCENE", options.scene_file);
    if (options.trace_file) files.output("--trace", *options.trace_file);
    if (options.states_file) files.output("--states", *options.states_file);
    Outputs outputs(out, err);
    outputs.add("--trace", options.trace_file);
    outputs.add("--states", options.states_file);
    std::ostream& report = outputs.report();

    Trace trace;
    const std::string scene_name = formats::input_name(options.scene_file);
    // A scene with a "bench" block (docs/scenes.md) is judged by it at the end, as `bench` judges it.
    std::optional<bench::BenchScene> judged;
    try {
        const formats::json document = formats::parse_json_text(formats::read_input_file(options.scene_file));
        trace.scene = formats::read_scene(document, options.preset);
        if (bench::declares_bench_block(document))
            judged = bench::declared_bench_scene_of_document(scene_name, document, trace.scene);
    } catch (const formats::InputError& e) {
        throw formats::FileError{scene_name, e.where(), e.problem()};
    }
    Scene& scene = trace.scene;
    for (const std::string& assignment : options.settings) formats::apply_setting(scene, assignment, "--set");
    if (options.frames) scene.world.frames = *options.frames;
    if (options.dt) scene.settings.duration = *options.dt;
    for (const std::string& spec : options.record) formats::apply_record_spec(spec, trace.recording);
    if (!scene.contacts.empty())
        err << "impulse-lab: note: the " << scene.contacts.size() << " contact(s) written in " << scene_name
            << " are for `resolve`; `run` detects its own\n";
    // The trace header is the scene as run; a trace of `run` lists no hand-written contacts.
    scene.contacts.clear();

    World world(scene);
    world.set_stop_flag(&stop_requested());
    TraceRecorder trace_recorder(trace, formats::trace_budget_bytes(options.max_trace_mb));
    Recorder nobody;
    Recorder& recorder = options.trace_file ? static_cast<Recorder&>(trace_recorder) : nobody;

    // The outputs are written as the frames are made (on disk, not in memory) and put in place at the end: the
    // states row by row; the trace's frames into a spool, since the trace's head, which comes first, says where
    // the recording ended.
    std::optional<StreamedOutput> trace_out = outputs.stream("--trace");
    std::optional<StreamedOutput> states_out = outputs.stream("--states");
    std::optional<formats::Spool> trace_frames;
    if (trace_out)
        trace_frames.emplace(outputs.to_standard_output("--trace") ? std::filesystem::temp_directory_path() / "trace"
                                                                   : std::filesystem::path(*options.trace_file));

    const int frames = scene.world.frames;
    StatesCsv states(states_out ? &*states_out : nullptr, options.max_states_mb, scene);
    states.add(-1, world.time(), world.bodies());
    RunSummary summary(scene_name, frames, scene.settings.duration, scene);

    std::optional<bench::AccuracyTracker> accuracy;
    if (judged) accuracy.emplace(scene, *judged, frames);
    // Without --record the trace keeps every frame its size limit allows: said once the first frame shows how
    // large a frame is, rather than only at the end.
    const bool whole_run = options.trace_file && options.record.empty() && frames > 1;
    bool fit_said = false;

    ProgressBar bar(progress, frames);
    std::optional<int> broken_frame;  // the frame that left a body non-finite: the run stops there
    std::optional<NonFiniteBody> broken_body;
    std::optional<int> interrupted;  // Ctrl-C or SIGTERM stopped the run (cli/interrupt.hpp)
    const InterruptHandler interrupt_handler;
    for (int frame = 0; frame < frames; ++frame) {
        if ((interrupted = interrupt_received())) break;
        const StepReport report = world.step(recorder);
        if (report.over_contact_budget) {
            const formats::InputError e = formats::contact_budget_error(frame);
            throw formats::FileError{scene_name, e.where(), e.problem()};
        }
        if (report.resolution.cut_short) {  // a signal stopped it within the frame: the frame is not done
            interrupted = interrupt_received().value_or(SIGINT);
            end_trace_before(trace, frame);
            break;
        }
        if (report.non_finite) {
            broken_frame = frame;
            broken_body = report.non_finite;
            end_trace_before(trace, frame);
            break;
        }
        summary.add(report, world.bodies());
        if (trace_frames) spool_frames(trace, *trace_frames);
        states.add(frame, world.time(), world.bodies());
        if (frame == 0)
            if (const std::string note = states.fit_note(frames); !note.empty()) err << note << '\n';
        if (accuracy) accuracy->observe(frame, world.bodies(), report);
        if (whole_run && !fit_said)
            if (const std::string note = trace_fit_note(trace_recorder, frame + 1, frames, options.max_trace_mb);
                !note.empty())
                err << note << '\n', fit_said = true;
        bar.update(frame + 1);
    }
    bar.finish();
    const int frames_done = summary.frames();
    if (interrupted) {
        end_trace_before(trace, frames_done);
        forget_interrupt();  // a second signal from here on stops the writing
    }

    // Putting a long trace together takes a while: a signal meanwhile is the first (the run had ended: nothing is
    // written without --keep-partial) or the second (nothing is written at all).
    const bool write = !interrupted || options.keep_partial;
    if (write && trace_out) {
        trace_out->append(formats::trace_head_text(trace));
        if (trace_frames->size() == 0) {
            trace_out->append(formats::trace_no_frames);
        } else {
            trace_out->append(*trace_frames);
            trace_out->append(formats::trace_frames_close);
        }
    }
    if (write) states.flush();
    if (const std::optional<int> signal = interrupt_received()) {
        if (interrupted) throw Interrupted{*signal};
        interrupted = signal;
    }
    if (!interrupted || options.keep_partial) {
        if (trace_recorder.stopped_at())
            err << formats::trace_stopped_note(*trace_recorder.stopped_at(), options.max_trace_mb) << '\n';
        if (states.stopped_at()) err << states.stopped_note() << '\n';
        outputs.commit({trace_out ? &*trace_out : nullptr, states_out ? &*states_out : nullptr});
    }

    if (broken_frame) {
        err << "impulse-lab: " << model::broken_run_text(scene, {*broken_frame, *broken_body}) << '\n';
        if (!outputs.file_of("--trace").empty())
            report << "trace of the frames before it written to " << outputs.file_of("--trace") << '\n';
        if (!outputs.file_of("--states").empty())
            report << "states of the frames before it written to " << outputs.file_of("--states") << '\n';
        return exit_non_finite;
    }
    summary.write(report, scene, world.bodies());
    if (accuracy) report << bench_verdict(*judged, accuracy->finish(world.bodies()), frames_done) << '\n';
    if (interrupted) {
        err << "impulse-lab: interrupted (" << signal_name(*interrupted) << ") after " << frames_done << " of "
            << frames << " frames: "
            << (options.keep_partial
                    ? std::string(options.trace_file || options.states_file ? "the frames done are written"
                                                                            : "nothing to write")
                    : std::string("nothing written, the files already there are unchanged (--keep-partial writes "
                                  "the frames done)"))
            << '\n';
        return 128 + *interrupted;
    }
    if (!outputs.file_of("--trace").empty()) report << "trace written to " << outputs.file_of("--trace") << '\n';
    if (!outputs.file_of("--states").empty()) report << "states written to " << outputs.file_of("--states") << '\n';
    return exit_ok;
}

}  // namespace impulse::cli
