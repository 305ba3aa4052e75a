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

// The bench's scenes and their suites. Each scene's metric, target, duration and failure threshold are its
// file's "bench" block (written by scripts/make-scenes, one place); docs/bench.md lists them. The default suite
// is what the default matrix runs (about an hour on 2 cores with the other engines); the large suite's scenes
// take minutes a configuration.
constexpr std::array<ShippedScene, 23> shipped{{
    {"stack_10", "stack_10.json", Suite::standard},
    {"stack_20", "stack_20.json", Suite::standard},
    {"pyramid_20", "pyramid_20.json", Suite::standard},
    {"brick_wall", "brick_wall.json", Suite::standard},
    {"mass_ratio_100", "mass_ratio_100.json", Suite::standard},
    {"mass_ratio_1000", "mass_ratio_1000.json", Suite::standard},
    {"deep_plank", "deep_plank.json", Suite::standard},
    {"box_resting", "box_resting.json", Suite::standard},
    {"spinning_box", "spinning_box.json", Suite::standard},
    {"grid_1000", "grid_1000.json", Suite::standard},
    {"card_house", "card_house.json", Suite::standard},
    {"jenga_30", "jenga_30.json", Suite::standard},
    {"double_domino", "double_domino.json", Suite::standard},
    {"vertical_stack_15", "vertical_stack_15.json", Suite::standard},
    {"box_stack_40", "box_stack_40.json", Suite::standard},
    {"heavy_on_light", "heavy_on_light.json", Suite::standard},
    {"stack_ratio_1024", "stack_ratio_1024.json", Suite::standard},
    {"tiny_pyramid", "tiny_pyramid.json", Suite::standard},
    {"overlap_recovery", "overlap_recovery.json", Suite::standard},
    {"friction_static", "friction_static.json", Suite::standard},
    {"friction_dynamic", "friction_dynamic.json", Suite::standard},
    {"sphere_drop", "sphere_drop.json", Suite::standard},
    {"two_spheres", "two_spheres.json", Suite::standard},
}};

constexpr std::array<ShippedScene, 1> shipped_large{{
    {"large_pyramid", "large/large_pyramid.json", Suite::large},
}};

// Both lists as one, in order (the default suite first).
const std::vector<ShippedScene>& every_shipped() {
    static const std::vector<ShippedScene> all = [] {
        std::vector<ShippedScene> v(shipped.begin(), shipped.end());
        v.insert(v.end(), shipped_large.begin(), shipped_large.end());
        return v;
    }();
    return all;
}

}  // namespace

namespace {

// Every metric's name (in results files), unit ("" for a ratio) and meaning (in charts and the summary), in one row.
struct MetricWords {
    Metric metric;
    std::string_view name, unit, meaning;
};
constexpr std::array<MetricWords, 10> metric_words{{
    {Metric::top_drift, "top_drift", "m", "top-body drift"},
    {Metric::any_drift, "any_drift", "m", "largest drift of any body"},
    {Metric::top_sideways_drift, "top_sideways_drift", "m", "top-body drift across gravity"},
    {Metric::end_penetration, "end_penetration", "m", "deepest penetration at the end"},
    {Metric::jitter, "jitter", "m/s", "RMS speed over the last second"},
    {Metric::energy_gain, "energy_gain", "", "energy gained after the first contact"},
    {Metric::restitution_error, "restitution_error", "", "restitution error"},
    {Metric::momentum_error, "momentum_error", "", "momentum error"},
    {Metric::recovery_time, "recovery_time", "s", "time to push overlapping bodies apart"},
    {Metric::slide_error, "slide_error", "", "slide distance against Coulomb's"},
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

std::string_view suite_name(Suite suite) {
    return suite == Suite::large ? "large" : "default";
}

Suite suite_named(std::string_view name) {
    if (name == "default") return Suite::standard;
    if (name == "large") return Suite::large;
    throw formats::InputError("--suite", "no suite named \"" + std::string(name) + "\" (default, large)");
}

std::span<const ShippedScene> shipped_bench_scenes() {
    return every_shipped();
}

const ShippedScene* find_shipped_scene(std::string_view name) {
    for (const ShippedScene& s : every_shipped())
        if (s.name == name) return &s;
    return nullptr;
}

std::vector<std::string> default_methods() {
    // Every preset of ours but `chapter` (the book's velocities and pushes again, without the reference engine's
    // additions: it would repeat the book's row), then the other engines.
    std::vector<std::string> methods{
        "book",           "sweep", "pgs", "pgs_split", "soft_step", "soft_step_recycled", "soft_step_coloured",
        "soft_step_wide", "avbd"};
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

// slide_error compares each sliding body with Coulomb's answer on level ground: the ground must be level (its
// normal against gravity) and some body must start moving along it.
void check_sliding(const Scene& scene) {
    const Vec3 up = -scene.world.gravity.normalized();
    if (!scene.ground || scene.world.gravity.isZero() || scene.ground->plane.normal.dot(up) < 1.0 - 1e-12)
        throw formats::InputError("bench.metric",
                                  "slide_error needs gravity and level ground (its normal against gravity)");
    for (const RigidBody& b : scene.bodies)
        if (b.inverse_mass > 0.0 && b.velocity.norm() > 0.0) {
            if (std::abs(b.velocity.dot(up)) > 1e-12 * b.velocity.norm())
                throw formats::InputError("bench.metric",
                                          "slide_error needs the sliding bodies to start moving along the "
                                          "ground, not towards or away from it");
            return;
        }
    throw formats::InputError("bench.metric",
                              "slide_error needs a body that starts sliding (a velocity along the ground)");
}

}  // namespace

bool is_drift(Metric metric) {
    return metric == Metric::top_drift || metric == Metric::any_drift || metric == Metric::top_sideways_drift;
}

bool declares_bench_block(const formats::json& document) {
    return document.is_object() && document.contains("bench");
}

BenchScene declared_bench_scene(std::string name, std::string_view scene_text) {
    const formats::json document = formats::parse_json_text(scene_text);
    return declared_bench_scene_of_document(std::move(name), document, formats::read_scene(document));
}

BenchScene declared_bench_scene_of_document(std::string name, const formats::json& document, const Scene& scene) {
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
    else if (is_drift(spec.metric))
        spec.failure_threshold = half_height(scene, highest_body(scene));
    else if (spec.stress)
        spec.failure_threshold = 10.0 * spec.target;
    if (block.contains("min_travel")) spec.min_travel = block["min_travel"].get<double>();
    if (block.contains("leave_speed")) {
        if (spec.metric != Metric::recovery_time)
            throw formats::InputError("bench.leave_speed", "applies to the metric recovery_time only");
        spec.leave_speed = block["leave_speed"].get<double>();
    } else if (spec.metric == Metric::recovery_time) {
        spec.leave_speed = 1.0;
    }
    if (block.contains("settle")) {
        if (!is_drift(spec.metric))
            throw formats::InputError("bench.settle",
                                      "applies to the drift metrics only (top_drift, any_drift, "
                                      "top_sideways_drift)");
        spec.settle = block["settle"].get<double>();
        if (*spec.settle >= spec.frames * scene.settings.duration)
            throw formats::InputError("bench.settle", "is not before the end of the run");
    }
    if (spec.metric == Metric::slide_error) check_sliding(scene);
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
