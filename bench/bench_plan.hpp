#pragma once
// What `impulse-lab bench` runs: its scenes with the accuracy metric and target each is judged by, the
// methods (preset names), and how one iteration count N maps onto each method's own knob.

#include "formats/json_values.hpp"
#include "settings/settings.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::bench {

// The quantity a scene is judged by: its "error" in the results, smaller is better.
enum class Metric {
    top_drift,           // m: the farthest the body that started highest moved from its start
    any_drift,           // m: the farthest any body moved from its start (a grid has no top)
    top_sideways_drift,  // m: the farthest the top body moved across gravity (a settling tower's fall not counted)
    end_penetration,     // m: the deepest penetration left after the last frame's resolution
    jitter,              // m/s: RMS linear speed of every body over the last second
    energy_gain,         // share of the impact's kinetic energy gained after the first contact
    restitution_error,   // |v_after + c v_before| / |c v_before| at the first bounce
    momentum_error,      // |p_end - p_start| / sum of m |v| at the start
    recovery_time,       // s: until the deepest penetration is at most 5 % of the deepest at the start
    slide_error,         // the largest |d - d_exact| / d_exact of a body sliding to a stop by Coulomb friction
};

std::string_view metric_name(Metric metric);  // "top_drift", ...
// The drift metrics, judged by a collapse (the drift passing the failure threshold).
bool is_drift(Metric metric);
std::string_view metric_unit(Metric metric);  // "m", "m/s" or "" (a ratio)
std::string_view metric_meaning(Metric metric);

struct BenchScene {
    std::string name;  // the scene file's name without ".json"
    Metric metric;
    double target;  // a configuration meets the target when its error is at most this
    // Where the scene fails (the stability verdict): drift metrics, the drift that counts as a collapse
    // (half the top body's height); end_penetration, jitter, recovery_time and slide_error, the value beyond which
    // it failed; energy_gain, the gain beyond which the box bounced higher than physics allows. Unused by the
    // isolated impacts.
    double failure_threshold;
    int frames;   // frames simulated (the scene's duration is frames x 1/60 s)
    bool stress;  // a column of the stability matrix
    // False for a scene file that declares no "bench" block: its error is the top body's drift (for the chart),
    // it has no target (NaN) and no verdict but NaN, and it is no column of the stability matrix.
    bool verdict;
    std::optional<double> min_travel =
        std::nullopt;  // m: every body must move at least this far from its start ("stalled")
    std::optional<double> leave_speed =
        std::nullopt;  // m/s, recovery_time: the fastest a body may move once apart ("exploded")
    // s, drift metrics: the error is the drift from the state at this time, so a settling that is over by then
    // does not count (a collapse is still judged from the start).
    std::optional<double> settle = std::nullopt;
};

// The bench's own scenes, by suite: `standard` is what `bench` runs by default, `large` what `--suite large` runs
// (scenes of thousands of bodies, minutes a configuration).
enum class Suite { standard, large };
std::string_view suite_name(Suite suite);  // "default", "large"
Suite suite_named(std::string_view name);  // throws formats::InputError("--suite", ...) for another name

struct ShippedScene {
    std::string_view name;  // the scene file's name without ".json"
    std::string_view file;  // its path in the scenes folder
    Suite suite;
};
// Every bench scene in the order they are run and drawn; each is judged by its file's "bench" block.
std::span<const ShippedScene> shipped_bench_scenes();
const ShippedScene* find_shipped_scene(std::string_view name);

// The bench scene a scene file declares (its "bench" block, docs/scenes.md), named `name`: metric, target,
// duration (default the scene's settings.frames) and failure threshold (default: for top_drift, any_drift and
// top_sideways_drift half the top body's height along gravity, for restitution_error and momentum_error none,
// else 10 x the target), min_travel, leave_speed (default 1 m/s for recovery_time, else none) and settle.
// Without a block: the general measures and no verdict. Throws formats::InputError (a JSON path) for a bad scene.
BenchScene declared_bench_scene(std::string name, std::string_view scene_text);
// The same from the file's document, parsed (formats::parse_json_text), and the scene read from it
// (formats::read_scene, which validates the bench block too; under any preset, as no preset sets the duration): for a
// caller that reads the scene itself, so the file is parsed and read once (each parse and read of Box3D's
// 5,050-cube pyramid took about 1 % of the profile of a 200-frame run).
BenchScene declared_bench_scene_of_document(std::string name, const formats::json& scene_document, const Scene& scene);
// Whether a scene file's document has a "bench" block.
bool declares_bench_block(const formats::json& scene_document);
Metric metric_named(std::string_view name);  // one of metric_name's; throws std::out_of_range otherwise

// Methods are preset names or other engines' (bench/adapters); the default set is every method but the chapter's
// text, then every engine this build has.
std::vector<std::string> default_methods();
// Every name --methods takes: the presets, then the built engines.
std::vector<std::string> method_names();
// The other engines a build may have, built or not ("bullet", "ode", "mujoco").
std::span<const std::string_view> engine_names();

// --shard K/N: this run is the K-th (from 1) of N shards, running configurations K-1, K-1+N, ... of the
// scene-major, then method, then N order.
struct Shard {
    int k = 1;
    int n = 1;
    bool runs(std::size_t configuration) const {
        return configuration % static_cast<std::size_t>(n) == static_cast<std::size_t>(k - 1);
    }
};
// "2/4" -> {2, 4}; throws formats::InputError("--shard", ...) unless 1 <= K <= N <= 10000.
Shard parse_shard(std::string_view text);
std::vector<int> default_iterations();  // 1, 2, 4, 8, 16, 32

// The one place an iteration count N becomes settings:
//   worst-first presets (book, chapter)   iterations_per_contact = N  (each phase's limit is N x contacts)
//   sweep, pgs, pgs_split                 sweeps = N
//   soft_step                             soft_step.substeps = N, with sweeps = 1 (one relax sweep each)
//   avbd                                  avbd.iterations = N
// Chosen by the settings' velocity method, so a preset keeps its mapping whatever it is called.
void set_iteration_count(ResolverSettings& settings, int n);
// The name of the setting N was written to, for the results: "iterations_per_contact", "sweeps",
// "soft_step.substeps" or "avbd.iterations".
std::string_view iteration_setting(const ResolverSettings& settings);

// "1,2,4" -> {1, 2, 4}: positive integers, no repeats. Throws formats::InputError("--iterations", ...).
std::vector<int> parse_iterations(std::string_view text);
// "a,b" -> names, each checked against `known`; throws formats::InputError(flag, ...) naming the unknown one.
std::vector<std::string> parse_names(std::string_view text, std::span<const std::string> known, std::string_view flag,
                                     std::string_view what);

}  // namespace impulse::bench
