// impulse-trace-sums: the SHA-256 of every trace the determinism test compares, one line each, as `sha256sum`
// prints it: every shipped case resolved once and the first frames of every shipped scene, under every preset.
// The same program is built natively (the engine preset) and as WebAssembly run by node (the web preset); the
// test (determinism.mjs) runs both and requires the same lines. A trace is the text `impulse-lab resolve --trace`
// and `impulse-lab run --frames N --trace --max-trace-mb 16` write (a test of the default preset holds the two to
// each other), followed by the bits of every body's state after the resolution or after every frame.
//
//   impulse-trace-sums SCENES [--frames N] [--shard I/N] [--only NAME [--write FILE]]
//
// SCENES is the folder of scenes with the cases in SCENES/cases. --shard I/N computes every N-th trace from the
// I-th (from 0), so several processes share the list; --only NAME the one trace NAME (as the lines name it), which
// --write also writes out, to find where two builds part.

#include "sha256.hpp"

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "settings/settings.hpp"
#include "world/world.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace impulse;
namespace fs = std::filesystem;

// The recording's budget: 16 MB (as --max-trace-mb 16), not the program's default 200 (model/session.hpp). Ten
// traced frames of the largest shipped scenes were up to 190 MB each, and formatting, hashing and comparing 7.5 GB
// of traces took 7.5 minutes of a CI run, and 1 minute at 16 MB. Every preset's every kind of record is still
// compared (most scenes record 1 to 10 frames, and a stopped recording is compared too); the scenes whose first
// frame alone passes 16 MB (grid_1000 under every preset; tiny_pyramid, brick_wall and pyramid_20 under some)
// record nothing. The engine's bits for all the frames of every scene come from the states after every frame, appended
// to the text hashed.
constexpr std::size_t trace_budget = 16'000'000;

struct Job {
    std::string name;  // "case-ruler-book.json", "scene-stack_3-pgs.json": the names tools/dump-traces.sh gives
    fs::path file;
    std::string preset;
    bool is_case;
};

std::string read_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<fs::path> json_files(const fs::path& folder) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<Job> jobs(const fs::path& scenes) {
    std::vector<Job> list;
    for (std::string_view preset : preset_names()) {
        for (const fs::path& file : json_files(scenes / "cases"))
            list.push_back({"case-" + file.stem().string() + "-" + std::string(preset) + ".json", file,
                            std::string(preset), true});
        for (const fs::path& file : json_files(scenes))
            list.push_back({"scene-" + file.stem().string() + "-" + std::string(preset) + ".json", file,
                            std::string(preset), false});
    }
    return list;
}

// One line a body: its state's bits (position, orientation, velocity, angular velocity) as hexadecimal words, so
// the text is the same wherever the bits are, whatever a C library's number printing does.
void append_states(std::string& text, int frame, const std::vector<RigidBody>& bodies) {
    const auto word = [&text](double value) {
        std::uint64_t bits;  // std::bit_cast's work: emscripten 3.1.6's libc++ 13 has no std::bit_cast
        static_assert(sizeof bits == sizeof value);
        std::memcpy(&bits, &value, sizeof bits);
        char hex[18];
        std::snprintf(hex, sizeof hex, " %016llx", static_cast<unsigned long long>(bits));
        text += hex;
    };
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        text += "state " + std::to_string(frame) + " " + std::to_string(i);
        for (const double v : {b.position.x(), b.position.y(), b.position.z(), b.orientation.w(), b.orientation.x(),
                               b.orientation.y(), b.orientation.z(), b.velocity.x(), b.velocity.y(), b.velocity.z(),
                               b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z()})
            word(v);
        text += '\n';
    }
}

// As `resolve CASE --preset P --trace` (model/runs.cpp, resolve_once): the case's contacts, or those its shapes make;
// the trace, then the bodies after.
std::string resolve_case(const Scene& scene) {
    Trace trace;
    trace.scene = scene;
    const std::vector<Contact> contacts =
        scene.contacts.empty() ? detect_contacts(scene, scene.bodies).contacts : scene.contacts;
    std::vector<RigidBody> bodies = scene.bodies;
    TraceRecorder recorder(trace, trace_budget);
    resolve_contacts(bodies, contacts, scene.settings, recorder);
    std::string text = formats::format_json(formats::trace_json(trace));
    append_states(text, 0, bodies);
    return text;
}

// As `run SCENE --frames N --preset P --trace --max-trace-mb 16` (cli/run_command.cpp): the trace, then the bodies
// after every frame.
std::string run_scene(Scene scene, int frames) {
    Trace trace;
    trace.scene = std::move(scene);
    trace.scene.world.frames = frames;
    trace.scene.contacts.clear();
    World world(trace.scene);
    TraceRecorder recorder(trace, trace_budget);
    std::string states;
    for (int frame = 0; frame < frames; ++frame) {
        if (world.step(recorder).non_finite) throw std::runtime_error("a body became non-finite");
        append_states(states, frame, world.bodies());
    }
    return formats::format_json(formats::trace_json(trace)) + states;
}

std::string trace_text(const Job& job, int frames) {
    const Scene scene = formats::read_scene_text(read_file(job.file), job.preset);
    return job.is_case ? resolve_case(scene) : run_scene(scene, frames);
}

int usage(const std::string& problem) {
    std::cerr << "impulse-trace-sums: " << problem
              << "\nusage: impulse-trace-sums SCENES [--frames N] [--shard I/N] [--only NAME [--write FILE]]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::optional<fs::path> scenes;
    int frames = 10, shard = 0, shards = 1;
    std::optional<std::string> only, write;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
            return argv[++i];
        };
        try {
            if (arg == "--frames")
                frames = std::stoi(value());
            else if (arg == "--shard") {
                const std::string v = value();
                if (std::sscanf(v.c_str(), "%d/%d", &shard, &shards) != 2 || shards < 1 || shard < 0 || shard >= shards)
                    return usage("--shard takes I/N with 0 <= I < N, not " + v);
            } else if (arg == "--only")
                only = value();
            else if (arg == "--write")
                write = value();
            else if (!scenes && !arg.starts_with("--"))
                scenes = arg;
            else
                return usage("unknown argument " + arg);
        } catch (const std::exception& e) {
            return usage(e.what());
        }
    }
    if (!scenes) return usage("name the scenes folder");
    if (write && !only) return usage("--write needs --only");

    const std::vector<Job> list = jobs(*scenes);
    bool found = false;
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Job& job = list[i];
        if (only ? job.name != *only : static_cast<int>(i % static_cast<std::size_t>(shards)) != shard) continue;
        found = true;
        try {
            const std::string text = trace_text(job, frames);
            if (write) {
                std::ofstream out(*write, std::ios::binary);
                out << text;
                if (!out.flush()) throw std::runtime_error("cannot write " + *write);
            }
            std::cout << web_tests::sha256_hex(text) << "  " << job.name << std::endl;
        } catch (const std::exception& e) {
            std::cerr << "impulse-trace-sums: " << job.name << ": " << e.what() << '\n';
            return 1;
        }
    }
    if (only && !found) return usage("no trace is named " + *only);
    return 0;
}
