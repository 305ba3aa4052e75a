// `impulse-lab run SCENE.json`: simulate a scene frame by frame (integrate -> detect -> resolve), record the
// frames asked for, write a CSV of every body's state per frame, and summarise the run.

#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/input_files.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "explain/csv.hpp"
#include "explain/format.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "io/scene_file.hpp"
#include "io/settings_json.hpp"
#include "io/trace_json.hpp"
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
        csv += explain::csv_field(scene.body_names[i]);
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

}  // namespace

int run_command(const RunOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress) {
    Trace trace;
    try {
        trace.scene = io::read_scene_text(read_input_file(options.scene_file), options.preset);
    } catch (const io::InputError& e) {
        throw FileError{options.scene_file, e.where(), e.problem()};
    }
    Scene& scene = trace.scene;
    for (const std::string& assignment : options.settings) io::apply_setting(scene, assignment, "--set");
    if (options.frames) scene.world.frames = *options.frames;
    if (options.dt) scene.settings.duration = *options.dt;
    for (const std::string& spec : options.record) apply_record_spec(spec, trace.recording);
    // A run can take minutes: find out now, not after it, if its results could not be written.
    if (options.trace_file) io::check_writable(*options.trace_file, "--trace");
    if (options.states_file) io::check_writable(*options.states_file, "--states");
    if (!scene.contacts.empty())
        err << "impulse-lab: note: the " << scene.contacts.size() << " contact(s) written in " << options.scene_file
            << " are for `resolve`; `run` detects its own\n";
    // The trace header is the scene as run; a trace of `run` lists no hand-written contacts.
    scene.contacts.clear();

    std::vector<RigidBody> bodies = scene.bodies;
    TraceRecorder trace_recorder(trace, inspect::trace_budget_bytes(options.max_trace_mb));
    Recorder nobody;
    Recorder& recorder = options.trace_file ? static_cast<Recorder&>(trace_recorder) : nobody;

    const int frames = scene.world.frames;
    const double dt = scene.settings.duration;
    std::string states;
    if (options.states_file) {
        states = "frame,time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
        append_states(states, -1, 0.0, scene, bodies);
    }
    const std::size_t top = highest_body(scene);
    const Vec3 top_start = bodies[top].position;
    double top_drift_most = 0.0;
    int top_drift_frame = 0;

    std::vector<StepReport> reports;
    reports.reserve(static_cast<std::size_t>(frames));
    ProgressBar bar(progress, frames);
    ContactMemory memory;
    std::optional<int> broken_frame;  // the frame that left a body non-finite: the run stops there
    // Ctrl-C stops the run between frames and writes nothing (cli/interrupt.hpp).
    const InterruptHandler interrupt_handler;
    for (int frame = 0; frame < frames; ++frame) {
        throw_if_interrupted();
        reports.push_back(step(scene, bodies, recorder, frame, &memory));
        if (reports.back().non_finite) {
            broken_frame = frame;
            break;
        }
        if (options.states_file) append_states(states, frame, (frame + 1) * dt, scene, bodies);
        const double drift = (bodies[top].position - top_start).norm();
        if (drift > top_drift_most) top_drift_most = drift, top_drift_frame = frame;
        bar.update(frame + 1);
    }
    bar.finish();
    if (trace_recorder.stopped_at()) err << trace_stopped_note(*trace_recorder.stopped_at(), options.max_trace_mb) << '\n';
    if (broken_frame && options.trace_file) end_trace_before(trace, *broken_frame);

    // Formatting a long trace takes a while: a Ctrl-C meanwhile still writes nothing.
    const std::string trace_text = options.trace_file ? io::format_json(io::trace_json(trace)) : std::string();
    throw_if_interrupted();
    {
        // Both files are written to temporaries first and renamed only when both succeeded; a signal from here
        // on waits until both are in place.
        const io::DeferredSignals held;
        std::vector<io::StagedFile> outputs;
        if (options.trace_file) outputs.emplace_back(*options.trace_file, trace_text, "--trace");
        if (options.states_file) outputs.emplace_back(*options.states_file, states, "--states");
        for (io::StagedFile& file : outputs) file.commit();
    }
    if (broken_frame) {
        err << "impulse-lab: " << inspect::broken_run_text(scene, {*broken_frame, *reports.back().non_finite}) << '\n';
        if (options.trace_file) out << "trace of the frames before it written to " << *options.trace_file << '\n';
        if (options.states_file) out << "states of the frames before it written to " << *options.states_file << '\n';
        return exit_non_finite;
    }

    // The summary: up to 20 frames evenly spread, and always the last.
    out << options.scene_file << ": " << bodies.size() << (bodies.size() == 1 ? " body" : " bodies")
        << (scene.ground ? ", ground" : "") << ", " << frames << " frames of " << explain::number(dt) << " s ("
        << explain::number(frames * dt) << " s), preset " << scene.settings.preset << "\n";
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
        << scene.body_names[top] << " (highest at the start) ends "
        << fixed((bodies[top].position - top_start).norm() * 1e3, 3) << " mm from where it started, at most "
        << fixed(top_drift_most * 1e3, 3) << " mm (frame " << top_drift_frame << ")\n";
    if (options.trace_file) out << "trace written to " << *options.trace_file << '\n';
    if (options.states_file) out << "states written to " << *options.states_file << '\n';
    return 0;
}

}  // namespace impulse::cli
