// `impulse-lab bench`: every scene x method x iteration count, timed with the recorder off and judged by each
// scene's accuracy metric; writes results.csv, results.json, speed_accuracy.png, stability.md and stability.png
// into --out (docs/bench.md). `--scaling` instead times the book's worst-first search on growing grids.

#include "bench/bench_charts.hpp"
#include "bench/chart_canvas.hpp"
#include "bench/bench_merge.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_runs.hpp"
#include "cli/cli.hpp"
#include "cli/commands.hpp"
#include "cli/data_folder.hpp"
#include "formats/input_files.hpp"
#include "cli/progress.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "formats/suggest.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "world/world.hpp"

#include <chrono>
#include <deque>
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
            throw formats::InputError("--out", "cannot write into '" + text + "': not a folder");
        formats::check_writable(folder / "results.csv", "--out");
    } else {
        formats::check_writable(folder, "--out");
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
    // The commit of the checkout the program's data comes from when it runs from a build folder (asked at run
    // time: the build may be older); an installed program has no checkout, and says so.
    try {
        std::error_code error;
        const fs::path checkout = shipped_scenes_folder().parent_path();
        if (fs::exists(checkout / ".git", error) && checkout.string().find('\'') == std::string::npos)
            p.commit = first_line_of(("git -C '" + checkout.string() + "' rev-parse --short HEAD 2>/dev/null").c_str());
    } catch (const formats::InputError&) {
        // No data folder (--scene-dir named the scenes): no checkout to ask.
    }
    if (p.commit.empty()) p.commit = "unknown";
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
    p.date = date;
    return p;
}

fs::path scenes_folder(const BenchOptions& options) {
    return options.scene_dir ? fs::path(*options.scene_dir) : shipped_scenes_folder();
}

// A bench scene's file: where the table puts it in the scenes folder (scenes/large/ for the large suite).
std::string scene_path(const BenchOptions& options, const std::string& name) {
    const bench::ShippedScene* shipped = bench::find_shipped_scene(name);
    return (scenes_folder(options) / (shipped ? std::string(shipped->file) : name + ".json")).string();
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
    for (const std::string& g : grids) texts.push_back(formats::read_input_file(scene_path(options, g)));
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
            Scene scene = formats::read_scene_text(texts[g], std::string("book"));
            scene.settings.worst_first_search = search;
            World world(scene);
            std::vector<double> resolve_ms, per_resolution_us;
            double contacts = 0, resolutions = 0;
            for (int frame = 0; frame < frames; ++frame) {
                const StepReport r = world.step();
                const int used = r.resolution.position.iterations_used + r.resolution.velocity.iterations_used;
                contacts += r.contacts;
                resolutions += used;
                resolve_ms.push_back(r.times.resolve() * 1e3);
                if (used > 0) per_resolution_us.push_back(r.times.resolve() * 1e6 / used);
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
    formats::write_file_atomically(folder / "scaling.csv", csv, "--out");
    out << "written: " << (folder / "scaling.csv").string() << '\n';
    return exit_ok;
}

}  // namespace

namespace {

// The scenes --scenes names, each either a bench scene's name (its file in the scenes folder, bench_plan.cpp's
// table) or a scene file's path; either is judged by its file's "bench" block, or the general measures without one.
// Without --scenes, the scenes of --suite (default: the default suite). `specs` owns what run.scenes points to.
void choose_scenes(const BenchOptions& options, bench::BenchRun& run, std::deque<bench::BenchScene>& specs,
                   std::vector<std::string>& texts, std::vector<std::string>& paths) {
    std::vector<std::string> entries;
    if (options.scenes && options.suite)
        throw formats::InputError("--suite", "cannot be combined with --scenes (name the scenes of any suite there)");
    if (options.scenes) {
        std::string_view list = *options.scenes;
        for (std::size_t start = 0;;) {
            const std::size_t comma = list.find(',', start);
            entries.emplace_back(list.substr(start, comma == std::string_view::npos ? comma : comma - start));
            if (comma == std::string_view::npos) break;
            start = comma + 1;
        }
    } else {
        const bench::Suite suite = options.suite ? bench::suite_named(*options.suite) : bench::Suite::standard;
        for (const bench::ShippedScene& s : bench::shipped_bench_scenes())
            if (s.suite == suite) entries.emplace_back(s.name);
    }
    std::string known;
    for (const bench::ShippedScene& s : bench::shipped_bench_scenes())
        known += (known.empty() ? "" : ", ") + std::string(s.name);
    for (const std::string& entry : entries) {
        const bool is_path = entry.find('/') != std::string::npos || fs::path(entry).extension() == ".json";
        if (entry.empty()) throw formats::InputError("--scenes", "an empty scene name in \"" + *options.scenes + "\"");
        std::string path = is_path ? entry : scene_path(options, entry);
        if (!is_path && !bench::find_shipped_scene(entry)) {
            std::vector<std::string> names;
            for (const bench::ShippedScene& s : bench::shipped_bench_scenes()) names.emplace_back(s.name);
            const std::optional<std::string> meant = formats::closest_name(entry, names);
            throw formats::InputError("--scenes", "no bench scene named \"" + entry + "\"" +
                                                      (meant ? "; did you mean \"" + *meant + "\"?" : "") + " (" +
                                                      known +
                                                      "); give your own scene by its path, e.g. scenes/stack_3.json");
        }
        std::string text;
        try {
            text = formats::read_input_file(path);
        } catch (const formats::FileError& e) {
            throw formats::InputError("--scenes", "cannot read '" + path + "': " + e.problem);
        }
        const std::string name = fs::path(path).stem().string();
        bench::BenchScene spec;
        try {
            spec = bench::declared_bench_scene(name, text);
        } catch (const formats::InputError& e) {
            throw formats::FileError{path, e.where(), e.problem()};
        }
        for (const bench::BenchScene* s : run.scenes)
            if (s->name == name)
                throw formats::InputError("--scenes", "two scenes are called \"" + name +
                                                          "\" (a scene is named by its "
                                                          "file's name)");
        specs.push_back(spec);
        run.scenes.push_back(&specs.back());
        texts.push_back(std::move(text));
        paths.push_back(path);
    }
}

std::vector<std::string> chosen_methods(const BenchOptions& options) {
    if (!options.methods) return bench::default_methods();
    const std::vector<std::string> known = bench::method_names();
    // An engine this build does not have is not a typo: say why it is missing.
    std::string_view list = *options.methods;
    for (const std::string_view engine : bench::engine_names())
        if (!bench::find_engine(engine))
            for (std::size_t at = list.find(engine); at != std::string_view::npos; at = list.find(engine, at + 1)) {
                const std::size_t end = at + engine.size();
                if ((at == 0 || list[at - 1] == ',') && (end == list.size() || list[end] == ','))
                    throw formats::InputError("--methods",
                                              std::string(engine) +
                                                  " is not in this build: its library was not found when "
                                                  "impulse-lab was configured (scripts/install-deps installs it)");
            }
    return bench::parse_names(*options.methods, known, "--methods", "method");
}

// The five files, then the summary: per scene, the cheapest configuration that meets its target.
int write_results(const bench::BenchRun& run, const bench::Provenance& where, const fs::path& folder, std::ostream& out,
                  std::ostream& err) {
    const formats::HeldInterruptions held;  // Ctrl-C waits until every file is in place (or none is)
    std::vector<formats::StagedFile> files;
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw formats::InputError("--out", "cannot create '" + folder.string() + "': " + error.message());
    files.emplace_back(folder / "results.csv", bench::results_csv(run), "--out");
    files.emplace_back(folder / "results.json", formats::format_json(bench::results_json(run, where)), "--out");
    files.emplace_back(folder / "stability.md", bench::stability_markdown(run), "--out");
    std::string charts_problem;
    try {
        files.emplace_back(folder / "speed_accuracy.png", bench::speed_accuracy_png(run), "--out");
        files.emplace_back(folder / "stability.png", bench::stability_png(run), "--out");
    } catch (const bench::ChartError& e) {
        charts_problem = e.what();
        while (files.size() > 3) files.pop_back();
    }
    for (formats::StagedFile& f : files) f.commit();

    out << "bench: " << run.scenes.size() << " scene(s) x " << run.methods.size() << " method(s) x "
        << run.iterations.size() << " iteration count(s)"
        << (run.shard.n > 1 ? ", shard " + std::to_string(run.shard.k) + "/" + std::to_string(run.shard.n) : "")
        << (run.merged_from.empty() ? "" : ", merged from " + std::to_string(run.merged_from.size()) + " shards")
        << " = " << run.rows.size() << " runs in " << fixed("%.0f", run.wall_time) << " s (" << run.timing.repeats
        << " timed window(s) each)\n";
    out << "scene             metric                                  target       cheapest meeting it      ms/step    "
           " "
           "error\n";
    for (const bench::BenchScene* s : run.scenes) {
        char line[256];
        const std::string target = s->verdict ? "<= " + bench::metric_text(*s, s->target) : "none";
        std::string cheapest = s->verdict ? "none" : "no verdict", ms, error_text;
        if (const auto best = bench::cheapest_meeting_target(run.rows, s->name)) {
            const bench::RunResult& r = run.rows[*best];
            cheapest = r.method + ", N = " + std::to_string(r.n);
            ms = fixed("%.3g", r.time_per_step * 1e3);
            error_text = bench::metric_text(*s, r.accuracy.error);
        }
        const std::string meaning =
            s->verdict ? std::string(bench::metric_meaning(s->metric)) : "general measures (no bench block)";
        std::snprintf(line, sizeof line, "%-17s %-39s %-12s %-24s %7s  %s\n", s->name.c_str(), meaning.c_str(),
                      target.c_str(), cheapest.c_str(), ms.c_str(), error_text.c_str());
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

// --merge DIR...: the shards' results.json joined, and the five files written from them.
int merge(const BenchOptions& options, const fs::path& folder, std::ostream& out, std::ostream& err) {
    for (const auto& [given, flag] : {std::pair{options.scenes.has_value(), "--scenes"},
                                      {options.methods.has_value(), "--methods"},
                                      {options.iterations.has_value(), "--iterations"},
                                      {options.shard.has_value(), "--shard"},
                                      {options.frames.has_value(), "--frames"},
                                      {options.scaling, "--scaling"}})
        if (given)
            throw formats::InputError("--merge",
                                      std::string("cannot be combined with ") + flag + " (the shards say what ran)");
    std::vector<nlohmann::ordered_json> documents;
    for (const std::string& dir : options.merge) {
        const fs::path file = fs::path(dir) / "results.json";
        std::string text;
        try {
            text = formats::read_input_file(file.string());
        } catch (const formats::FileError& e) {
            throw formats::InputError("--merge", "cannot read '" + file.string() + "': " + e.problem);
        }
        try {
            documents.push_back(formats::parse_json_text(text));
        } catch (const formats::InputError& e) {
            throw formats::InputError("--merge", "'" + file.string() + "' is not JSON: " + e.problem());
        }
    }
    const std::unique_ptr<bench::MergedRun> merged = bench::merge_results(documents, options.merge);
    return write_results(merged->run, merged->provenance, folder, out, err);
}

}  // namespace

int bench_command(const BenchOptions& options, std::ostream& out, std::ostream& err, std::ostream* progress) {
    // Every flag is checked before anything runs.
    const fs::path folder = checked_out_folder(options.out);
    if (!options.merge.empty()) return merge(options, folder, out, err);
    bench::BenchRun run;
    run.methods = chosen_methods(options);
    run.iterations = options.iterations ? bench::parse_iterations(*options.iterations) : bench::default_iterations();
    if (options.repeats < 1)
        throw formats::InputError("--repeats", "must be >= 1, got " + std::to_string(options.repeats));
    if (options.shard) run.shard = bench::parse_shard(*options.shard);
    std::deque<bench::BenchScene> specs;
    std::vector<std::string> texts, paths;
    if (!options.scaling) choose_scenes(options, run, specs, texts, paths);
    if (options.scaling) return scaling(options, folder, out, progress);

    run.timing.repeats = options.repeats;
    run.timing.frames = options.frames;
    run.timing.measure_recording = true;  // only for the representative configuration, below

    // Recording overhead for one configuration per scene: the first method at the iteration count nearest 4
    // (the book's own), so the ratio is measured where the recorder is used most.
    int representative = run.iterations.front();
    for (const int n : run.iterations)
        if (std::abs(n - 4) < std::abs(representative - 4)) representative = n;

    // Configurations are numbered scene-major, then method, then N; a shard runs every N-th from its K-th.
    int total = 0;
    std::size_t configuration = 0;
    for (const bench::BenchScene* s : run.scenes)
        for (std::size_t m = 0; m < run.methods.size() * run.iterations.size(); ++m)
            if (run.shard.runs(configuration++)) total += bench::frames_for(*s, run.timing);
    ProgressBar bar(progress, total);
    int done = 0;
    configuration = 0;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < run.scenes.size(); ++i)
        for (const std::string& method : run.methods)
            for (const int n : run.iterations) {
                if (!run.shard.runs(configuration++)) continue;
                bench::Timing timing = run.timing;
                timing.measure_recording = method == run.methods.front() && n == representative;
                try {
                    run.rows.push_back(bench::run_configuration(texts[i], *run.scenes[i], method, n, timing));
                } catch (const formats::InputError& e) {
                    throw formats::FileError{paths[i], e.where(), e.problem()};
                }
                done += bench::frames_for(*run.scenes[i], run.timing);
                bar.update(done);
            }
    bar.finish();
    run.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return write_results(run, provenance(), folder, out, err);
}

}  // namespace impulse::cli
