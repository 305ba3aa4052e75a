// `impulse-lab run SCENE.json`: simulate a scene frame by frame (integrate -> detect -> resolve), record the
// frames asked for, write a CSV of every body's state per frame, and summarise the run.

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
#include <array>
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

std::string fixed(double v, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, v);
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
        std::snprintf(line, sizeof line, "  %5d  %8.3f  %8d  %10.3f  %10.4g  %8.3f\n", r.frame, (r.frame + 1) * dt,
                      r.contacts, r.deepest_penetration * 1e3, r.kinetic_energy,
                      (r.times.integrate + r.times.broad_phase + r.times.narrow_phase + r.times.resolve) * 1e3);
        out << line;
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

}  // namespace

int run_command(const RunOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress) {
    // A run can take minutes: find out now, not after it, if its results could not be written.
    Outputs outputs(out, err);
    outputs.add("--trace", options.trace_file);
    outputs.add("--states", options.states_file);
    std::ostream& report = outputs.report();

    Trace trace;
    const std::string scene_name = formats::input_name(options.scene_file);
    try {
        trace.scene = formats::read_scene_text(formats::read_input_file(options.scene_file), options.preset);
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

    std::vector<StepReport> reports;
    reports.reserve(static_cast<std::size_t>(frames));
    ProgressBar bar(progress, frames);
    std::optional<int> broken_frame;  // the frame that left a body non-finite: the run stops there
    std::optional<int> interrupted;   // Ctrl-C or SIGTERM stopped the run between frames (cli/interrupt.hpp)
    const InterruptHandler interrupt_handler;
    for (int frame = 0; frame < frames; ++frame) {
        if ((interrupted = interrupt_received())) break;
        reports.push_back(world.step(recorder));
        if (reports.back().non_finite) {
            broken_frame = frame;
            break;
        }
        if (options.states_file) append_states(states, frame, world.time(), scene, world.bodies());
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
