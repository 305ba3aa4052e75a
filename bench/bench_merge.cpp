#include "bench/bench_merge.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>

namespace impulse::bench {

namespace {

using json = nlohmann::ordered_json;

double number_or_nan(const json& value) {
    return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> optional_number(const json& value) {
    if (value.is_number()) return value.get<double>();
    return std::nullopt;
}

// A results.json row back into the result it was written from (bench_report.cpp, results_json).
RunResult read_row(const json& j) {
    RunResult r;
    r.scene = j.at("scene").get<std::string>();
    r.method = j.at("method").get<std::string>();
    r.n = j.at("n").get<int>();
    r.iteration_setting = j.at("iteration_setting").get<std::string>();
    r.frames = j.at("frames").get<int>();
    r.duration = r.frames > 0 ? j.at("simulated_s").get<double>() / r.frames : 0.0;
    r.contacts_per_frame = j.at("contacts_per_frame").get<double>();
    r.time_per_step = number_or_nan(j.at("time_per_step_ms")) * 1e-3;  // null for a configuration not run
    r.timed_frames = j.at("timed_frames").get<int>();
    r.recording_ratio = optional_number(j.at("recording_ratio"));
    Accuracy& a = r.accuracy;
    a.error = number_or_nan(j.at("error"));
    a.meets_target = j.at("meets_target").get<bool>();
    a.holds = j.at("holds").get<bool>();
    a.failure = j.at("failure").is_string() ? j.at("failure").get<std::string>() : "";
    a.failure_time = optional_number(j.at("failure_time_s"));
    a.end_penetration = number_or_nan(j.at("end_penetration_m"));
    a.top_drift_end = number_or_nan(j.at("top_drift_end_m"));
    a.top_drift_most = number_or_nan(j.at("top_drift_most_m"));
    a.any_drift_most = number_or_nan(j.at("any_drift_most_m"));
    a.top_sideways_drift_most = number_or_nan(j.at("top_sideways_drift_most_m"));
    a.settled_drift = optional_number(j.at("settled_drift_most_m"));
    a.least_travel = number_or_nan(j.at("least_travel_m"));
    a.collapse_time = optional_number(j.at("collapse_time_s"));
    a.end_kinetic_energy = number_or_nan(j.at("end_kinetic_energy_j"));
    a.jitter = number_or_nan(j.at("jitter_rms_m_per_s"));
    a.energy_gain = number_or_nan(j.at("energy_gain"));
    a.restitution_error = optional_number(j.at("restitution_error"));
    a.momentum_error = optional_number(j.at("momentum_error"));
    a.recovery_time = optional_number(j.at("recovery_time_s"));
    a.leave_speed = optional_number(j.at("leave_speed_m_per_s"));
    a.slide_error = optional_number(j.at("slide_error"));
    a.nan_time = optional_number(j.at("nan_time_s"));
    return r;
}

BenchScene read_scene_spec(const json& j) {
    BenchScene s{j.at("name").get<std::string>(),
                 metric_named(j.at("metric").get<std::string>()),
                 number_or_nan(j.at("target")),
                 j.at("failure_threshold").is_number() ? j.at("failure_threshold").get<double>()
                                                       : std::numeric_limits<double>::infinity(),
                 j.at("frames").get<int>(),
                 j.at("stress").get<bool>(),
                 j.at("verdict").get<bool>(),
                 optional_number(j.at("min_travel")),
                 optional_number(j.at("leave_speed")),
                 optional_number(j.at("settle_s"))};
    return s;
}

// What must be the same in every shard of one matrix.
json matrix_of(const json& doc) {
    json scenes = json::array();
    for (const json& s : doc.at("scenes"))
        scenes.push_back({s.at("name"), s.at("metric"), s.at("target"), s.at("failure_threshold"), s.at("frames"),
                          s.at("verdict"), s.at("min_travel"), s.at("leave_speed"), s.at("settle_s")});
    return {{"scenes", scenes},
            {"methods", doc.at("methods")},
            {"iterations", doc.at("iterations")},
            {"repeats", doc.at("timing").at("repeats")},
            {"shards", doc.at("shard").at("n")}};
}

}  // namespace

std::unique_ptr<MergedRun> merge_results(const std::vector<json>& documents, const std::vector<std::string>& folders) {
    auto merged = std::make_unique<MergedRun>();
    BenchRun& run = merged->run;
    std::map<int, std::string> shard_folders;  // k -> folder
    json first_matrix;
    for (std::size_t d = 0; d < documents.size(); ++d) {
        const json& doc = documents[d];
        const std::string& folder = folders[d];
        try {
            if (!doc.is_object() || doc.value("format", "") != "impulse-lab-bench" || doc.value("version", 0) != 1)
                throw formats::InputError("--merge",
                                          "'" + folder + "/results.json' is not the results of impulse-lab bench");
            const json matrix = matrix_of(doc);
            const int k = doc.at("shard").at("k").get<int>();
            const int n = doc.at("shard").at("n").get<int>();
            if (d == 0) {
                first_matrix = matrix;
                for (const json& s : doc.at("scenes")) merged->scenes.push_back(read_scene_spec(s));
                for (const BenchScene& s : merged->scenes) run.scenes.push_back(&s);
                run.methods = doc.at("methods").get<std::vector<std::string>>();
                run.iterations = doc.at("iterations").get<std::vector<int>>();
                const json& timing = doc.at("timing");
                run.timing.repeats = timing.at("repeats").get<int>();
                run.timing.warm_up = timing.at("warm_up_frames").get<int>();
                run.timing.window = timing.at("window_frames").get<int>();
                run.shard = {1, 1};
                Provenance& p = merged->provenance;
                p.cpu = doc.at("machine").at("cpu").get<std::string>();
                p.cores = doc.at("machine").at("cores").get<int>();
                p.compiler = doc.at("compiler").at("id_version").get<std::string>();
                p.build_type = doc.at("compiler").at("build_type").get<std::string>();
                p.flags = doc.at("compiler").at("flags").get<std::string>();
                p.commit = doc.at("commit").get<std::string>();
                p.date = doc.at("date").get<std::string>();
            } else if (matrix != first_matrix) {
                throw formats::InputError("--merge",
                                          "'" + folder + "' holds a shard of another matrix than '" + folders[0] +
                                              "' (its scenes, methods, iterations, repeats or shard count differ)");
            }
            if (const auto [at, added] = shard_folders.emplace(k, folder); !added)
                throw formats::InputError("--merge", "'" + folder + "' and '" + at->second + "' both hold shard " +
                                                         std::to_string(k) + "/" + std::to_string(n));
            for (const json& row : doc.at("rows")) run.rows.push_back(read_row(row));
            run.wall_time += doc.at("timing").at("wall_time_s").get<double>();
            run.merged_from.push_back({{"folder", folder},
                                       {"shard", doc.at("shard")},
                                       {"machine", doc.at("machine")},
                                       {"commit", doc.at("commit")},
                                       {"date", doc.at("date")},
                                       {"wall_time_s", doc.at("timing").at("wall_time_s")}});
        } catch (const nlohmann::json::exception& e) {
            throw formats::InputError("--merge",
                                      "'" + folder + "/results.json' is not a whole bench result: " + e.what());
        } catch (const std::out_of_range& e) {
            throw formats::InputError("--merge", "'" + folder + "/results.json' names an unknown metric");
        }
    }
    const int n = first_matrix.at("shards").get<int>();
    for (int k = 1; k <= n; ++k)
        if (!shard_folders.count(k))
            throw formats::InputError("--merge", "shard " + std::to_string(k) + "/" + std::to_string(n) +
                                                     " is missing (given: " + std::to_string(shard_folders.size()) +
                                                     " of " + std::to_string(n) + ")");

    // Back into the order one run writes (scene-major, then method, then N), each configuration exactly once.
    const auto position = [&](const RunResult& r) {
        std::size_t s = 0, m = 0, i = 0;
        while (s < run.scenes.size() && run.scenes[s]->name != r.scene) ++s;
        while (m < run.methods.size() && run.methods[m] != r.method) ++m;
        while (i < run.iterations.size() && run.iterations[i] != r.n) ++i;
        return std::make_tuple(s, m, i);
    };
    std::stable_sort(run.rows.begin(), run.rows.end(),
                     [&](const RunResult& a, const RunResult& b) { return position(a) < position(b); });
    const std::size_t expected = run.scenes.size() * run.methods.size() * run.iterations.size();
    for (std::size_t r = 0; r < run.rows.size(); ++r) {
        const auto [s, m, i] = position(run.rows[r]);
        const std::size_t index = (s * run.methods.size() + m) * run.iterations.size() + i;
        if (index != r || r >= expected)
            throw formats::InputError("--merge", "the shards do not hold every configuration exactly once (at " +
                                                     run.rows[r].scene + ", " + run.rows[r].method +
                                                     ", N = " + std::to_string(run.rows[r].n) + ")");
    }
    if (run.rows.size() != expected)
        throw formats::InputError("--merge", "the shards hold " + std::to_string(run.rows.size()) + " of the " +
                                                 std::to_string(expected) + " configurations");
    return merged;
}

}  // namespace impulse::bench
