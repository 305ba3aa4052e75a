// `impulse-lab bench`: every scene x method x iteration count, timed with the recorder off and judged by each
// scene's accuracy metric; writes results.csv, results.json, speed_accuracy.png, stability.md and stability.png
// into --out (docs/bench.md). `--scaling` instead times the book's worst-first search on growing grids.

#include "bench/bench_report.hpp"
#include "bench/bench_runs.hpp"
#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/input_files.hpp"
#include "cli/progress.hpp"
#include "gui/bench_charts.hpp"
#include "gui/display.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "io/json_text.hpp"
#include "io/scene_file.hpp"
#include "world/world.hpp"

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

namespace impulse::cli {

namespace {

namespace fs = std::filesystem;

// The folder --out names, checked before anything runs: an existing folder we may write in, or a new one
// whose parent exists and is writable. It is created only when the results are ready.
fs::path checked_out_folder(const std::string& text) {
    fs::path folder = fs::path(text).lexically_normal();
    if (folder.filename().empty()) folder = folder.parent_path();  // "bench-results/"
    if (folder.empty()) folder = ".";
    std::error_code error;
    if (fs::exists(folder, error)) {
        if (!fs::is_directory(folder, error))
            throw io::InputError("--out", "cannot write into '" + text + "': not a folder");
        io::check_writable(folder / "results.csv", "--out");
    } else {
        io::check_writable(folder, "--out");
    }
    return folder;
}

std::string first_line_of(const char* command) {
    std::string line;
    if (std::FILE* pipe = ::popen(command, "r")) {
        char buffer[256];
        if (std::fgets(buffer, sizeof buffer, pipe)) line = buffer;
        ::pclose(pipe);
    }
    while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
    return line;
}

bench::Provenance provenance() {
    bench::Provenance p;
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0) {
            p.cpu = line.substr(line.find(':') + 2);
            break;
        }
    if (p.cpu.empty()) p.cpu = "unknown";
    p.cores = static_cast<int>(std::thread::hardware_concurrency());
    p.compiler = IMPULSE_CXX_COMPILER;
    p.flags = IMPULSE_CXX_FLAGS;
    p.flags.erase(0, p.flags.find_first_not_of(' '));  // CMAKE_CXX_FLAGS is often empty
    p.build_type = IMPULSE_BUILD_TYPE;
    // The commit of the source tree the program was built from, asked at run time (the build may be older).
    p.commit = first_line_of("git -C '" IMPULSE_SOURCE_DIR "' rev-parse --short HEAD 2>/dev/null");
    if (p.commit.empty()) p.commit = "unknown";
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    p.date = date;
    return p;
}

std::string scene_path(const BenchOptions& options, const std::string& name) {
    return (fs::path(options.scene_dir.value_or(IMPULSE_SCENES_DIR)) / (name + ".json")).string();
}

std::string fixed(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// Time per resolved contact of the book preset's worst-first search on grid_10, grid_100 and grid_1000.
int scaling(const BenchOptions& options, const fs::path& folder, std::ostream& out, std::ostream* progress) {
    const std::vector<std::string> grids{"grid_10", "grid_100", "grid_1000"};
    std::vector<std::string> texts;
    for (const std::string& g : grids) texts.push_back(read_input_file(scene_path(options, g)));
    const int frames = options.frames.value_or(30);
    std::string csv =
        "scene,search,frames,contacts_per_frame,resolutions_per_frame,resolve_ms_per_frame,"
        "us_per_resolved_contact\n";
    out << "Time per resolved contact, book preset (" << frames << " frames, median over frames)\n"
        << "scene        search           contacts  resolutions  resolve ms/frame  µs per resolution\n";
    ProgressBar bar(progress, static_cast<int>(grids.size()) * 2 * frames);
    int done = 0;
    for (std::size_t g = 0; g < grids.size(); ++g)
        for (const WorstFirstSearch search : {WorstFirstSearch::priority_queue, WorstFirstSearch::full_scan}) {
            Scene scene = io::read_scene_text(texts[g], std::string("book"));
            scene.settings.worst_first_search = search;
            std::vector<RigidBody> bodies = scene.bodies;
            Recorder nobody;
            std::vector<double> resolve_ms, per_resolution_us;
            double contacts = 0, resolutions = 0;
            for (int frame = 0; frame < frames; ++frame) {
                const StepReport r = step(scene, bodies, nobody, frame);
                const int used = r.resolution.position.iterations_used + r.resolution.velocity.iterations_used;
                contacts += r.contacts;
                resolutions += used;
                resolve_ms.push_back(r.times.resolve * 1e3);
                if (used > 0) per_resolution_us.push_back(r.times.resolve * 1e6 / used);
                bar.update(++done);
            }
            const char* name = search == WorstFirstSearch::priority_queue ? "priority_queue" : "full_scan";
            const double us = bench::median(per_resolution_us);
            const double ms = bench::median(resolve_ms);
            char line[200];
            std::snprintf(line, sizeof line, "%-12s %-15s %9.0f %12.0f %17.3f %18.3f\n", grids[g].c_str(), name,
                          contacts / frames, resolutions / frames, ms, us);
            out << line;
            csv += grids[g] + "," + name + "," + std::to_string(frames) + "," + fixed("%.6g", contacts / frames) + "," +
                   fixed("%.6g", resolutions / frames) + "," + fixed("%.6g", ms) + "," + fixed("%.6g", us) + "\n";
        }
    bar.finish();
    fs::create_directories(folder);
    io::write_file_atomically(folder / "scaling.csv", csv, "--out");
    out << "written: " << (folder / "scaling.csv").string() << '\n';
    return exit_ok;
}

}  // namespace

int bench_command(const BenchOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress) {
    // Every flag is checked before anything runs.
    bench::BenchRun run;
    std::vector<std::string> scene_names;
    for (const bench::BenchScene& s : bench::bench_scenes()) scene_names.push_back(s.name);
    const std::vector<std::string> chosen_scenes =
        options.scenes ? bench::parse_names(*options.scenes, scene_names, "--scenes", "bench scene") : scene_names;
    std::vector<std::string> preset_list;
    for (const std::string_view p : preset_names()) preset_list.emplace_back(p);
    run.methods = options.methods ? bench::parse_names(*options.methods, preset_list, "--methods", "method")
                                  : bench::default_methods();
    run.iterations = options.iterations ? bench::parse_iterations(*options.iterations) : bench::default_iterations();
    if (options.repeats < 1) throw io::InputError("--repeats", "must be >= 1, got " + std::to_string(options.repeats));
    const fs::path folder = checked_out_folder(options.out);
    if (options.scaling) return scaling(options, folder, out, progress);

    run.timing.repeats = options.repeats;
    run.timing.frames = options.frames;
    run.timing.measure_recording = true;  // only for the representative configuration, below
    std::vector<std::string> texts;
    for (const std::string& name : chosen_scenes) {
        run.scenes.push_back(bench::find_bench_scene(name));
        texts.push_back(read_input_file(scene_path(options, name)));
    }

    // Recording overhead for one configuration per scene: the first method at the iteration count nearest 4
    // (the book's own), so the ratio is measured where the recorder is used most.
    int representative = run.iterations.front();
    for (const int n : run.iterations)
        if (std::abs(n - 4) < std::abs(representative - 4)) representative = n;

    int total = 0;
    for (const bench::BenchScene* s : run.scenes)
        total += bench::frames_for(*s, run.timing) * static_cast<int>(run.methods.size() * run.iterations.size());
    ProgressBar bar(progress, total);
    int done = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < run.scenes.size(); ++i)
        for (const std::string& method : run.methods)
            for (const int n : run.iterations) {
                bench::Timing timing = run.timing;
                timing.measure_recording = method == run.methods.front() && n == representative;
                try {
                    run.rows.push_back(bench::run_configuration(texts[i], *run.scenes[i], method, n, timing));
                } catch (const io::InputError& e) {
                    throw FileError{scene_path(options, run.scenes[i]->name), e.where(), e.problem()};
                }
                done += bench::frames_for(*run.scenes[i], run.timing);
                bar.update(done);
            }
    bar.finish();
    run.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // The files: text first, then the pictures; all staged, then renamed together.
    const bench::Provenance where = provenance();
    const io::DeferredSignals held;  // Ctrl-C waits until every file is in place (or none is)
    std::vector<io::StagedFile> files;
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw io::InputError("--out", "cannot create '" + folder.string() + "': " + error.message());
    files.emplace_back(folder / "results.csv", bench::results_csv(run), "--out");
    files.emplace_back(folder / "results.json", io::format_json(bench::results_json(run, where)), "--out");
    files.emplace_back(folder / "stability.md", bench::stability_markdown(run), "--out");
    std::string charts_problem;
    try {
        files.emplace_back(folder / "speed_accuracy.png", gui::speed_accuracy_png(run), "--out");
        files.emplace_back(folder / "stability.png", gui::stability_png(run), "--out");
    } catch (const gui::DisplayError& e) {
        charts_problem = e.what();
        while (files.size() > 3) files.pop_back();
    }
    for (io::StagedFile& f : files) f.commit();

    // The summary: per scene, the cheapest configuration that meets its target.
    out << "bench: " << run.scenes.size() << " scene(s) x " << run.methods.size() << " method(s) x "
        << run.iterations.size() << " iteration count(s) = " << run.rows.size() << " runs in "
        << fixed("%.0f", run.wall_time) << " s (" << run.timing.repeats << " timed window(s) each)\n";
    out << "scene             metric                                  target       cheapest meeting it      ms/step    "
           " "
           "error\n";
    for (const bench::BenchScene* s : run.scenes) {
        char line[256];
        const std::string target = "<= " + bench::metric_text(*s, s->target);
        std::string cheapest = "none", ms, error_text;
        if (const auto best = bench::cheapest_meeting_target(run.rows, s->name)) {
            const bench::RunResult& r = run.rows[*best];
            cheapest = r.method + ", N = " + std::to_string(r.n);
            ms = fixed("%.3g", r.time_per_step * 1e3);
            error_text = bench::metric_text(*s, r.accuracy.error);
        }
        std::snprintf(line, sizeof line, "%-17s %-39s %-12s %-24s %7s  %s\n", s->name.c_str(),
                      std::string(bench::metric_meaning(s->metric)).c_str(), target.c_str(), cheapest.c_str(),
                      ms.c_str(), error_text.c_str());
        out << line;
    }
    for (const bench::RunResult& r : run.rows)
        if (r.recording_ratio)
            out << "recording overhead " << r.scene << " (" << r.method << ", N = " << r.n << "): x"
                << fixed("%.2f", *r.recording_ratio) << '\n';
    out << "written to " << folder.string() << ": results.csv, results.json, stability.md"
        << (charts_problem.empty() ? ", speed_accuracy.png, stability.png" : "") << '\n';
    if (!charts_problem.empty()) {
        err << "impulse-lab: bench: the charts could not be drawn: " << charts_problem << '\n';
        return exit_internal_error;
    }
    return exit_ok;
}

}  // namespace impulse::cli
