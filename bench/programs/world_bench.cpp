// Time per frame of whole scenes, split by stage, and the drift of the body that started highest.
//
//   impulse-bench-world SCENE... [--frames N] [--repeats R] [--set NAME=VALUE]... [--csv FILE]
//
// A scene may be - (standard input). The CSV (RFC 4180) is written atomically when every scene has run; --csv -
// puts it on standard output and the table on standard error.
//
// Each repeat simulates the scene from its start for N frames (default: the scene's own frames); the
// reported time per frame is the median over repeats of each repeat's mean. Drift comes from the first repeat
// (every repeat is identical: runs are deterministic).

#include "command_line.hpp"
#include "formats/input_files.hpp"
#include "formats/csv.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "world/world.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

using namespace impulse;

namespace {

struct Figures {
    double frame_ms = 0.0;
    StageTimes stage_ms;
    double contacts = 0.0;  // mean per frame
    double pairs = 0.0;     // mean per frame
    double drift_end_mm = 0.0;
    double drift_most_mm = 0.0;
    int limited_frames = 0;  // frames where a phase hit its iteration limit
};

Figures simulate(const Scene& scene, int frames) {
    Figures f;
    World world(scene);
    const std::size_t top = highest_body(scene);
    for (int frame = 0; frame < frames; ++frame) {
        const StepReport r = world.step();
        if (r.over_contact_budget) throw formats::contact_budget_error(frame);
        f.stage_ms.integrate += r.times.integrate * 1e3 / frames;
        f.stage_ms.broad_phase += r.times.broad_phase * 1e3 / frames;
        f.stage_ms.narrow_phase += r.times.narrow_phase * 1e3 / frames;
        f.stage_ms.prepare += r.times.prepare * 1e3 / frames;
        f.stage_ms.position += r.times.position * 1e3 / frames;
        f.stage_ms.velocity += r.times.velocity * 1e3 / frames;
        f.contacts += static_cast<double>(r.contacts) / frames;
        f.pairs += static_cast<double>(r.pairs_tested) / frames;
        f.limited_frames += r.resolution.position.stop == StopReason::iteration_limit ||
                            r.resolution.velocity.stop == StopReason::iteration_limit;
        const double drift = (world.bodies()[top].position - scene.bodies[top].position).norm() * 1e3;
        f.drift_most_mm = std::max(f.drift_most_mm, drift);
        f.drift_end_mm = drift;
    }
    f.frame_ms = f.stage_ms.total();
    return f;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Time per frame of whole scenes, and the drift of the body that started highest",
                 "impulse-bench-world"};
    std::vector<std::string> scenes, settings;
    std::optional<int> frames;
    int repeats = 3;
    app.add_option("SCENE", scenes, "Scene files (- for standard input)")->required();
    app.add_option("--frames", frames, "Frames per run (default: each scene's settings.frames)")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--repeats", repeats, "Runs per scene; the median time is reported")->check(CLI::Range(1, 100));
    app.add_option("--set", settings, "Change one setting in every scene, e.g. --set iterations_per_contact=100");
    const bench::CsvOutput csv(app);
    if (const std::optional<int> exit = bench::parse_command_line(app, argc, argv)) return *exit;
    // The CSV is checked before the runs and written whole after them; on standard output, the table moves to stderr.
    if (!csv.check()) return 2;
    std::FILE* table = csv.table();

    // The profile's rows are the world step's stages (StageTimes, resolver/resolver.hpp), in the step's order.
    std::string rows =
        formats::csv_row({"scene", "bodies", "frames", "contacts_per_frame", "pairs_per_frame", "ms_per_frame",
                          "integrate_ms", "broad_phase_ms", "narrow_phase_ms", "prepare_ms", "position_ms",
                          "velocity_ms", "limited_frames", "top_drift_end_mm", "top_drift_most_mm"});
    std::fprintf(table, "%-22s %6s %6s %9s %9s %10s %9s %9s %9s %9s %9s %9s %8s %11s %11s\n", "scene", "bodies",
                 "frames", "contacts", "pairs", "ms/frame", "integr.", "broad", "narrow", "prepare", "position",
                 "velocity", "limited", "drift end", "drift most");
    for (const std::string& file : scenes) {
        Scene scene;
        try {
            scene = formats::read_scene_text(formats::read_input_file(file));
            for (const std::string& s : settings) formats::apply_setting(scene, s, "--set");
        } catch (const formats::FileError& e) {
            std::cerr << "impulse-bench-world: " << e.file << ": " << e.problem << '\n';
            return 2;
        } catch (const formats::InputError& e) {
            std::cerr << "impulse-bench-world: " << formats::input_name(file) << ": " << e.what() << '\n';
            return 2;
        }
        const int n = frames.value_or(scene.world.frames);
        std::vector<Figures> runs;
        try {
            for (int r = 0; r < repeats; ++r) runs.push_back(simulate(scene, n));
        } catch (const formats::InputError& e) {  // a frame past the contact budget
            std::cerr << "impulse-bench-world: " << formats::input_name(file) << ": " << e.what() << '\n';
            return 2;
        }
        std::vector<Figures> sorted = runs;
        std::sort(sorted.begin(), sorted.end(),
                  [](const Figures& a, const Figures& b) { return a.frame_ms < b.frame_ms; });
        const Figures& median = sorted[sorted.size() / 2];
        const Figures& first = runs.front();
        const std::string name = formats::input_name(file.substr(file.find_last_of('/') + 1));
        const StageTimes& ms = median.stage_ms;
        std::fprintf(table, "%-22s %6zu %6d %9.1f %9.1f %10.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %8d %11.2f %11.2f\n",
                     name.c_str(), scene.bodies.size(), n, first.contacts, first.pairs, median.frame_ms, ms.integrate,
                     ms.broad_phase, ms.narrow_phase, ms.prepare, ms.position, ms.velocity, first.limited_frames,
                     first.drift_end_mm, first.drift_most_mm);
        rows += formats::csv_row(
            {name, std::to_string(scene.bodies.size()), std::to_string(n), formats::csv_number(first.contacts),
             formats::csv_number(first.pairs), formats::csv_number(median.frame_ms), formats::csv_number(ms.integrate),
             formats::csv_number(ms.broad_phase), formats::csv_number(ms.narrow_phase), formats::csv_number(ms.prepare),
             formats::csv_number(ms.position), formats::csv_number(ms.velocity), std::to_string(first.limited_frames),
             formats::csv_number(first.drift_end_mm), formats::csv_number(first.drift_most_mm)});
    }
    return csv.write(rows) ? 0 : 2;
}
