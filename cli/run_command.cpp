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
#include "formats/csv.hpp"
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
#include <cmath>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace impulse::cli {

namespace {

// One CSV row per body per frame; frame -1 is the scene as given (time 0).
void append_states(std::string& csv, int frame, double time, const Scene& scene, const std::vector<RigidBody>& bodies) {
    char line[512];
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        std::snprintf(line, sizeof line, "%d,%.17g,%zu,", frame, time, i);
        csv += line;
        csv += formats::csv_field(scene.body_names[i]);
        std::snprintf(line, sizeof line,
                      ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                      b.position.x(), b.position.y(), b.position.z(), b.orientation.w(), b.orientation.x(),
                      b.orientation.y(), b.orientation.z(), b.velocity.x(), b.velocity.y(), b.velocity.z(),
                      b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z(), kinetic_energy(b));
        csv += line;
    }
}

// A number with `decimals` after the point, or in exponent form once that would be long (a run of gravity
// −1e308 has depths of 300 digits: a fixed-width row cut them, and its line break with them).
std::string fixed(double v, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, std::abs(v) < 1e12 ? "%.*f" : "%.*g", std::abs(v) < 1e12 ? decimals : 4, v);
    return text;
}

// The summary of the frames run (all of them, or those done before a Ctrl-C): up to 20 frames evenly spread,
// and always the last.
struct RunSummary {
    std::string scene_name;
    int frames_asked = 0;
    double dt = 0.0;
    std::size_t top = 0;  // the body that started highest
    Vec3 top_start = Vec3::Zero();
    double top_drift_most = 0.0;
    int top_drift_frame = 0;
};

void write_summary(std::ostream& out, const RunSummary& s, const Scene& scene, const std::vector<RigidBody>& bodies,
                   const std::vector<StepReport>& reports) {
    const int frames = static_cast<int>(reports.size());
    const double dt = s.dt;
    out << s.scene_name << ": " << bodies.size() << (bodies.size() == 1 ? " body" : " bodies")
        << (scene.ground ? ", ground" : "") << ", "
        << (frames == s.frames_asked ? std::to_string(frames)
                                     : std::to_string(frames) + " of " + std::to_string(s.frames_asked))
        << " frames of " << explain::number(dt) << " s (" << explain::number(frames * dt) << " s), preset "
        << scene.settings.preset << "\n";
    out << "  frame    time s  contacts  deepest mm   kinetic J  ms/frame\n";
    const int every = std::max(1, (frames + 19) / 20);
    StageTimes total;
    double deepest = 0.0;
    int deepest_frame = 0;
    int position_limited = 0, velocity_limited = 0;
    for (const StepReport& r : reports) {
        const auto ran_out = [](StopReason stop) {
            return stop == StopReason::iteration_limit || stop == StopReason::sweeps_complete ? 1 : 0;
        };
        position_limited += ran_out(r.resolution.position.stop);
        velocity_limited += ran_out(r.resolution.velocity.stop);
        total.integrate += r.times.integrate;
        total.broad_phase += r.times.broad_phase;
        total.narrow_phase += r.times.narrow_phase;
        total.resolve += r.times.resolve;
        if (r.deepest_penetration > deepest) deepest = r.deepest_penetration, deepest_frame = r.frame;
        if (r.frame % every != 0 && r.frame != frames - 1) continue;
        char line[160];
        std::snprintf(
            line, sizeof line, "  %5d  %8s  %8d  %10s  %10.4g  %8s", r.frame, fixed((r.frame + 1) * dt, 3).c_str(),
            r.contacts, fixed(r.deepest_penetration * 1e3, 3).c_str(), r.kinetic_energy,
            fixed((r.times.integrate + r.times.broad_phase + r.times.narrow_phase + r.times.resolve) * 1e3, 3).c_str());
        out << line << '\n';
    }
    const double n = std::max(1, frames);
    out << "  per frame: integrate " << fixed(total.integrate / n * 1e3, 3) << " ms, broad phase "
        << fixed(total.broad_phase / n * 1e3, 3) << " ms, pair tests " << fixed(total.narrow_phase / n * 1e3, 3)
        << " ms, resolve " << fixed(total.resolve / n * 1e3, 3) << " ms\n";
    out << "  iteration limit (or every sweep) used in " << position_limited << " of " << frames
        << " frames (positions) and " << velocity_limited << " (velocities)\n";
    out << "  deepest penetration " << fixed(deepest * 1e3, 3) << " mm (frame " << deepest_frame << "); "
        << scene.body_names[s.top] << " (highest at the start) ends "
        << fixed((bodies[s.top].position - s.top_start).norm() * 1e3, 3) << " mm from where it started, at most "
        << fixed(s.top_drift_most * 1e3, 3) << " mm (frame " << s.top_drift_frame << ")\n";
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
        const std::string text = formats::read_input_file(options.scene_file);
        trace.scene = formats::read_scene_text(text, options.preset);
        if (bench::declares_bench_block(text)) judged = bench::declared_bench_scene(scene_name, text);
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
    TraceRecorder trace_recorder(trace, formats::trace_budget_bytes(options.max_trace_mb));
    Recorder nobody;
    Recorder& recorder = options.trace_file ? static_cast<Recorder&>(trace_recorder) : nobody;

    const int frames = scene.world.frames;
    const double dt = scene.settings.duration;
    std::string states;
    if (options.states_file) {
        states = "frame,time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
        append_states(states, -1, world.time(), scene, world.bodies());
    }
    RunSummary summary{scene_name, frames, dt, highest_body(scene), {}, 0.0, 0};
    summary.top_start = world.bodies()[summary.top].position;

    std::optional<bench::AccuracyTracker> accuracy;
    if (judged) accuracy.emplace(scene, *judged, frames);
    // Without --record the trace keeps every frame its size limit allows: said once the first frame shows how
    // large a frame is, rather than only at the end.
    const bool whole_run = options.trace_file && options.record.empty() && frames > 1;
    bool fit_said = false;

    std::vector<StepReport> reports;
    reports.reserve(static_cast<std::size_t>(frames));
    ProgressBar bar(progress, frames);
    std::optional<int> broken_frame;  // the frame that left a body non-finite: the run stops there
    std::optional<int> interrupted;   // Ctrl-C or SIGTERM stopped the run between frames (cli/interrupt.hpp)
    const InterruptHandler interrupt_handler;
    for (int frame = 0; frame < frames; ++frame) {
        if ((interrupted = interrupt_received())) break;
        reports.push_back(world.step(recorder));
        if (reports.back().over_contact_budget) {
            const formats::InputError e = formats::contact_budget_error(frame);
            throw formats::FileError{scene_name, e.where(), e.problem()};
        }
        if (reports.back().non_finite) {
            broken_frame = frame;
            break;
        }
        if (options.states_file) append_states(states, frame, world.time(), scene, world.bodies());
        if (accuracy) accuracy->observe(frame, world.bodies(), reports.back());
        if (whole_run && !fit_said)
            if (const std::string note = trace_fit_note(trace_recorder, frame + 1, frames, options.max_trace_mb);
                !note.empty())
                err << note << '\n', fit_said = true;
        const double drift = (world.bodies()[summary.top].position - summary.top_start).norm();
        if (drift > summary.top_drift_most) summary.top_drift_most = drift, summary.top_drift_frame = frame;
        bar.update(frame + 1);
    }
    bar.finish();
    if (broken_frame && options.trace_file) end_trace_before(trace, *broken_frame);
    const int frames_done = static_cast<int>(reports.size()) - (broken_frame ? 1 : 0);
    if (interrupted) {
        end_trace_before(trace, frames_done);
        forget_interrupt();  // a second signal from here on stops the writing
    }

    // Formatting a long trace takes a while: a signal meanwhile is the first (the run had ended: nothing is
    // written without --keep-partial) or the second (nothing is written at all).
    const bool write = !interrupted || options.keep_partial;
    const std::string trace_text =
        options.trace_file && write ? formats::format_json(formats::trace_json(trace)) : std::string();
    if (const std::optional<int> signal = interrupt_received()) {
        if (interrupted) throw Interrupted{*signal};
        interrupted = signal;
    }
    if (!interrupted || options.keep_partial) {
        if (trace_recorder.stopped_at())
            err << formats::trace_stopped_note(*trace_recorder.stopped_at(), options.max_trace_mb) << '\n';
        outputs.write({{"--trace", trace_text}, {"--states", states}});
    }

    if (broken_frame) {
        err << "impulse-lab: " << model::broken_run_text(scene, {*broken_frame, *reports.back().non_finite}) << '\n';
        if (!outputs.file_of("--trace").empty())
            report << "trace of the frames before it written to " << outputs.file_of("--trace") << '\n';
        if (!outputs.file_of("--states").empty())
            report << "states of the frames before it written to " << outputs.file_of("--states") << '\n';
        return exit_non_finite;
    }
    write_summary(report, summary, scene, world.bodies(), reports);
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
