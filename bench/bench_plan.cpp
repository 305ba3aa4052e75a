#include "bench/bench_plan.hpp"

#include "formats/suggest.hpp"

#include "formats/input_error.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "world/world.hpp"
#include "methods/method_table.hpp"
#include "bench/adapters/engine_adapter.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace impulse::bench {

namespace {

// Targets are stated once here and in docs/bench.md. Drift: 5 cm of the top body over the run (a stack that
// holds settles by a few millimetres to a few centimetres); a collapse is half a box (0.5 m; a brick course is
// 0.5 m high, so 0.25 m). Durations: 10 s (Bullet's figures are over 10 s), except the 1000-box grid (2 s:
// 4000 contacts a frame for 30 configurations); the default matrix must finish within 15 minutes on 2 cores.
const std::array<BenchScene, 12> scenes{{
    {"stack_10", Metric::top_drift, 0.05, 0.5, 600, true, true},
    {"stack_20", Metric::top_drift, 0.05, 0.5, 600, true, true},
    {"pyramid_20", Metric::top_drift, 0.05, 0.5, 600, true, true},
    {"brick_wall", Metric::top_drift, 0.05, 0.25, 600, true, true},
    {"mass_ratio_100", Metric::top_drift, 0.05, 0.5, 600, true, true},
    {"mass_ratio_1000", Metric::top_drift, 0.05, 0.5, 600, true, true},
    {"deep_plank", Metric::end_penetration, 0.011, 0.05, 120, true, true},
    {"box_resting", Metric::jitter, 0.005, 0.05, 600, true, true},
    {"spinning_box", Metric::energy_gain, 0.01, 0.05, 300, true, true},
    {"grid_1000", Metric::any_drift, 0.05, 0.5, 120, true, true},
    {"sphere_drop", Metric::restitution_error, 0.01, 0.0, 120, false, true},
    {"two_spheres", Metric::momentum_error, 1e-9, 0.0, 120, false, true},
}};

}  // namespace

namespace {

// Every metric's name (in results files), unit ("" for a ratio) and meaning (in charts and the summary), in one row.
struct MetricWords {
    Metric metric;
    std::string_view name, unit, meaning;
};
constexpr std::array<MetricWords, 7> metric_words{{
    {Metric::top_drift, "top_drift", "m", "top-body drift"},
    {Metric::any_drift, "any_drift", "m", "largest drift of any body"},
    {Metric::end_penetration, "end_penetration", "m", "deepest penetration at the end"},
    {Metric::jitter, "jitter", "m/s", "RMS speed over the last second"},
    {Metric::energy_gain, "energy_gain", "", "energy gained after the first contact"},
    {Metric::restitution_error, "restitution_error", "", "restitution error"},
    {Metric::momentum_error, "momentum_error", "", "momentum error"},
}};

const MetricWords& words_of(Metric metric) {
    for (const MetricWords& w : metric_words)
        if (w.metric == metric) return w;
    return metric_words.front();  // unreachable: every Metric has a row
}

}  // namespace

std::string_view metric_name(Metric metric) {
    return words_of(metric).name;
}

std::string_view metric_unit(Metric metric) {
    return words_of(metric).unit;
}

std::string_view metric_meaning(Metric metric) {
    return words_of(metric).meaning;
}

std::span<const BenchScene> bench_scenes() {
    return scenes;
}

const BenchScene* find_bench_scene(std::string_view name) {
    for (const BenchScene& s : scenes)
        if (s.name == name) return &s;
    return nullptr;
}

std::vector<std::string> default_methods() {
    std::vector<std::string> methods{"book", "sweep", "pgs", "pgs_split", "soft_step"};
    for (const EngineRow& e : built_engines()) methods.emplace_back(e.name);
    return methods;
}

std::vector<std::string> method_names() {
    std::vector<std::string> names;
    for (const std::string_view p : preset_names()) names.emplace_back(p);
    for (const EngineRow& e : built_engines()) names.emplace_back(e.name);
    return names;
}

std::span<const std::string_view> engine_names() {
    static constexpr std::array<std::string_view, 3> names{"bullet", "ode", "mujoco"};
    return names;
}

Metric metric_named(std::string_view name) {
    for (const MetricWords& w : metric_words)
        if (w.name == name) return w.metric;
    throw std::out_of_range("no metric named " + std::string(name));
}

namespace {

// Half the body's height along gravity: how far its top may drift before it counts as a collapse (half a box).
double half_height(const Scene& scene, std::size_t body) {
    const std::optional<Shape>& shape = scene.shapes[body];
    if (!shape) return 0.5;
    if (const auto* sphere = std::get_if<Sphere>(&*shape)) return sphere->radius;
    const Vec3 up = scene.world.gravity.isZero() ? Vec3::UnitY() : Vec3(-scene.world.gravity.normalized());
    const Vec3 along = scene.bodies[body].orientation.conjugate() * up;  // gravity in the body's axes
    return along.cwiseAbs().dot(std::get<Box>(*shape).half_size);
}

}  // namespace

bool declares_bench_block(std::string_view scene_text) {
    const nlohmann::ordered_json document = formats::parse_json_text(scene_text);
    return document.is_object() && document.contains("bench");
}

BenchScene declared_bench_scene(std::string name, std::string_view scene_text) {
    const nlohmann::ordered_json document = formats::parse_json_text(scene_text);
    const Scene scene = formats::read_scene(document);  // validates the whole file, the bench block with it
    const int own_frames = scene.world.frames;
    if (!document.contains("bench"))
        return {std::move(name),
                Metric::top_drift,
                std::numeric_limits<double>::quiet_NaN(),
                std::numeric_limits<double>::infinity(),
                own_frames,
                false,
                false};
    const auto& block = document["bench"];
    BenchScene spec{std::move(name),
                    metric_named(block["metric"].get<std::string>()),
                    block["target"].get<double>(),
                    0.0,
                    own_frames,
                    true,
                    true};
    if (block.contains("duration")) {
        const double frames = std::round(block["duration"].get<double>() / scene.settings.duration);
        if (frames < 1.0) throw formats::InputError("bench.duration", "is shorter than one frame of settings.duration");
        spec.frames = static_cast<int>(frames);
    }
    spec.stress = spec.metric != Metric::restitution_error && spec.metric != Metric::momentum_error;
    if (block.contains("failure_threshold"))
        spec.failure_threshold = block["failure_threshold"].get<double>();
    else if (spec.metric == Metric::top_drift || spec.metric == Metric::any_drift)
        spec.failure_threshold = half_height(scene, highest_body(scene));
    else if (spec.stress)
        spec.failure_threshold = 10.0 * spec.target;
    return spec;
}

Shard parse_shard(std::string_view text) {
    const std::size_t slash = text.find('/');
    Shard shard;
    const auto whole = [](std::string_view part, int& value) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return !part.empty() && error == std::errc() && end == part.data() + part.size();
    };
    if (slash == std::string_view::npos || !whole(text.substr(0, slash), shard.k) ||
        !whole(text.substr(slash + 1), shard.n) || shard.n < 1 || shard.n > 10000 || shard.k < 1 || shard.k > shard.n)
        throw formats::InputError("--shard", "expected K/N with whole numbers 1 <= K <= N <= 10000 (e.g. 2/4), got \"" +
                                                 std::string(text) + "\"");
    return shard;
}

std::vector<int> default_iterations() {
    return {1, 2, 4, 8, 16, 32};
}

void set_iteration_count(ResolverSettings& settings, int n) {
    method_row(settings.velocity_method).set_iterations(settings, n);
}

std::string_view iteration_setting(const ResolverSettings& settings) {
    return method_row(settings.velocity_method).iteration_setting;
}

namespace {

std::vector<std::string_view> split(std::string_view text) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        parts.push_back(text.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) return parts;
        start = comma + 1;
    }
}

}  // namespace

std::vector<int> parse_iterations(std::string_view text) {
    std::vector<int> counts;
    for (const std::string_view part : split(text)) {
        int n = 0;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), n);
        if (part.empty() || error != std::errc() || end != part.data() + part.size() || n < 1 || n > 1000)
            throw formats::InputError("--iterations",
                                      "expected counts from 1 to 1000 separated by commas (e.g. 1,2,4,8), "
                                      "got \"" +
                                          std::string(text) + "\"");
        if (std::find(counts.begin(), counts.end(), n) != counts.end())
            throw formats::InputError("--iterations", std::to_string(n) + " is given twice");
        counts.push_back(n);
    }
    return counts;
}

std::vector<std::string> parse_names(std::string_view text, std::span<const std::string> known, std::string_view flag,
                                     std::string_view what) {
    std::vector<std::string> names;
    for (const std::string_view part : split(text)) {
        if (std::find(known.begin(), known.end(), part) == known.end()) {
            std::string list;
            for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
            const std::optional<std::string> meant =
                formats::closest_name(part, std::vector<std::string>(known.begin(), known.end()));
            throw formats::InputError(std::string(flag),
                                      "no " + std::string(what) + " named \"" + std::string(part) + "\"" +
                                          (meant ? "; did you mean \"" + *meant + "\"?" : "") + " (" + list + ")");
        }
        if (std::find(names.begin(), names.end(), part) != names.end())
            throw formats::InputError(std::string(flag), "\"" + std::string(part) + "\" is given twice");
        names.emplace_back(part);
    }
    return names;
}

}  // namespace impulse::bench
