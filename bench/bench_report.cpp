#include "bench/bench_report.hpp"

#include "formats/csv.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace impulse::bench {

std::vector<std::size_t> pareto_front(const std::vector<TimeError>& points) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < points.size(); ++i)
        if (points[i].held && !std::isnan(points[i].error) && !std::isnan(points[i].time)) order.push_back(i);
    // By time, ties by error: walking in this order, a point is on the front when its error is below every
    // error seen so far (equal points: only the first).
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return points[a].time != points[b].time ? points[a].time < points[b].time : points[a].error < points[b].error;
    });
    std::vector<std::size_t> front;
    double best = INFINITY;
    for (const std::size_t i : order)
        if (points[i].error < best) {
            front.push_back(i);
            best = points[i].error;
        }
    return front;
}

std::optional<std::size_t> cheapest_meeting_target(const std::vector<RunResult>& rows, const std::string& scene) {
    std::optional<std::size_t> best;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].scene != scene || !rows[i].accuracy.meets_target) continue;
        if (!best || rows[i].time_per_step < rows[*best].time_per_step) best = i;
    }
    return best;
}

StabilityMatrix stability_matrix(const std::vector<RunResult>& rows, const std::vector<std::string>& methods,
                                 const std::vector<const BenchScene*>& scenes) {
    StabilityMatrix m;
    m.methods = methods;
    for (const BenchScene* s : scenes)
        if (s->stress) m.scenes.push_back(s);
    m.cells.assign(methods.size(), std::vector<StabilityCell>(m.scenes.size()));
    for (std::size_t i = 0; i < methods.size(); ++i)
        for (std::size_t j = 0; j < m.scenes.size(); ++j) {
            StabilityCell& cell = m.cells[i][j];
            std::vector<std::pair<int, bool>> verdicts;  // (N, held)
            for (const RunResult& r : rows) {
                if (r.method != methods[i] || r.scene != m.scenes[j]->name) continue;
                verdicts.emplace_back(r.n, r.accuracy.holds);
                if (cell.ran && r.n < cell.n) continue;
                cell.ran = true;
                cell.n = r.n;
                cell.holds = r.accuracy.holds;
                cell.meets_target = r.accuracy.meets_target;
                cell.failure = r.accuracy.failure;
                cell.failure_time = r.accuracy.failure_time;
                cell.error = r.accuracy.error;
            }
            // "holds from N = k": every N from k up held, and a smaller one did not.
            std::sort(verdicts.begin(), verdicts.end());
            std::size_t first_of_run = verdicts.size();
            while (first_of_run > 0 && verdicts[first_of_run - 1].second) --first_of_run;
            if (first_of_run > 0 && first_of_run < verdicts.size()) cell.holds_from = verdicts[first_of_run].first;
        }
    return m;
}

namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string optional_number(const std::optional<double>& value) {
    return value ? formats::csv_number(*value) : "";
}

nlohmann::ordered_json json_number(double value) {
    if (!std::isfinite(value)) return nullptr;
    return value;
}

nlohmann::ordered_json json_number(const std::optional<double>& value) {
    return value ? json_number(*value) : nlohmann::ordered_json(nullptr);
}

// Which rows of `scene` are on its Pareto front.
std::vector<bool> front_flags(const std::vector<RunResult>& rows) {
    std::vector<bool> on(rows.size(), false);
    std::map<std::string, std::vector<std::size_t>> by_scene;
    for (std::size_t i = 0; i < rows.size(); ++i) by_scene[rows[i].scene].push_back(i);
    for (const auto& [scene, indices] : by_scene) {
        std::vector<TimeError> points;
        for (const std::size_t i : indices)
            points.push_back({rows[i].time_per_step, rows[i].accuracy.error, rows[i].accuracy.holds});
        for (const std::size_t k : pareto_front(points)) on[indices[k]] = true;
    }
    return on;
}

}  // namespace

const BenchScene* scene_of(const BenchRun& run, const std::string& name) {
    for (const BenchScene* s : run.scenes)
        if (s->name == name) return s;
    return nullptr;
}

std::string metric_text(const BenchScene& spec, double value) {
    if (std::isnan(value)) return "NaN";
    const std::string unit(metric_unit(spec.metric));
    if (unit.empty()) return format("%.3g", value);
    return format("%.3g", value) + " " + unit;
}

std::string_view verdict_text(const StabilityCell& cell) {
    if (!cell.ran) return "not run";
    if (!cell.holds) return "fails";
    return cell.meets_target ? "meets target" : "holds, misses target";
}

std::string cell_text(const BenchScene& spec, const StabilityCell& cell) {
    if (!cell.ran) return "";
    if (cell.holds) {
        std::string text;
        if (cell.holds_from) text = "from N = " + std::to_string(*cell.holds_from) + ", ";
        // How far off a run that holds is: the target missed twice is not the target missed a hundred times.
        if (!cell.meets_target && spec.target > 0.0 && std::isfinite(cell.error))
            text += format("%.2g", cell.error / spec.target) + " × the target, ";
        return text + std::string(metric_name(spec.metric)) + " " + metric_text(spec, cell.error);
    }
    std::string text = cell.failure;
    if (cell.failure_time) text += " at " + format("%.2f", *cell.failure_time) + " s";
    if (cell.failure != "NaN")
        text += ", " + std::string(metric_name(spec.metric)) + " " + metric_text(spec, cell.error);
    return text;
}

std::string results_csv(const BenchRun& run) {
    std::string csv =
        "scene,metric,unit,target,method,n,iteration_setting,frames,simulated_s,contacts_per_frame,time_per_step_ms,"
        "timed_frames,error,meets_target,holds,failure,failure_time_s,end_penetration_m,top_drift_end_m,"
        "top_drift_most_m,any_drift_most_m,top_sideways_drift_most_m,settled_drift_most_m,least_travel_m,collapse_time_"
        "s,"
        "end_kinetic_energy_j,"
        "jitter_rms_m_per_s,energy_gain,restitution_error,momentum_error,recovery_time_s,leave_speed_m_per_s,"
        "slide_error,nan,nan_time_s,on_pareto_front,recording_ratio\n";
    const std::vector<bool> front = front_flags(run.rows);
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
        const RunResult& r = run.rows[i];
        const Accuracy& a = r.accuracy;
        const BenchScene& spec = *scene_of(run, r.scene);
        const std::vector<std::string> fields{
            r.scene,
            std::string(metric_name(spec.metric)),
            std::string(metric_unit(spec.metric)),
            spec.verdict ? formats::csv_number(spec.target) : "",
            r.method,
            std::to_string(r.n),
            r.iteration_setting,
            std::to_string(r.frames),
            formats::csv_number(r.frames * r.duration),
            formats::csv_number(r.contacts_per_frame),
            formats::csv_number(r.time_per_step * 1e3),
            std::to_string(r.timed_frames),
            formats::csv_number(a.error),
            a.meets_target ? "true" : "false",
            a.holds ? "true" : "false",
            formats::csv_field(a.failure),
            optional_number(a.failure_time),
            formats::csv_number(a.end_penetration),
            formats::csv_number(a.top_drift_end),
            formats::csv_number(a.top_drift_most),
            formats::csv_number(a.any_drift_most),
            formats::csv_number(a.top_sideways_drift_most),
            optional_number(a.settled_drift),
            formats::csv_number(a.least_travel),
            optional_number(a.collapse_time),
            formats::csv_number(a.end_kinetic_energy),
            formats::csv_number(a.jitter),
            formats::csv_number(a.energy_gain),
            optional_number(a.restitution_error),
            optional_number(a.momentum_error),
            optional_number(a.recovery_time),
            optional_number(a.leave_speed),
            optional_number(a.slide_error),
            a.nan_time ? "true" : "false",
            optional_number(a.nan_time),
            front[i] ? "true" : "false",
            optional_number(r.recording_ratio),
        };
        for (std::size_t k = 0; k < fields.size(); ++k) csv += (k ? "," : "") + fields[k];
        csv += '\n';
    }
    return csv;
}

nlohmann::ordered_json results_json(const BenchRun& run, const Provenance& provenance) {
    using json = nlohmann::ordered_json;
    json doc;
    doc["format"] = "impulse-lab-bench";
    doc["version"] = 1;
    doc["date"] = provenance.date;
    doc["commit"] = provenance.commit;
    doc["machine"] = {{"cpu", provenance.cpu}, {"cores", provenance.cores}};
    doc["compiler"] = {
        {"id_version", provenance.compiler}, {"build_type", provenance.build_type}, {"flags", provenance.flags}};
    doc["timing"] = {{"repeats", run.timing.repeats},
                     {"warm_up_frames", run.timing.warm_up},
                     {"window_frames", run.timing.window},
                     {"time_per_step", "median step time over the frames of every timed window (recorder off)"},
                     {"wall_time_s", run.wall_time}};
    doc["methods"] = run.methods;
    doc["iterations"] = run.iterations;
    json mapping = json::object();
    json engines = json::object();
    for (const std::string& m : run.methods)
        if (const auto s = preset(m)) {
            mapping[m] = iteration_setting(*s);
        } else if (const EngineRow* e = find_engine(m)) {
            mapping[m] = e->iteration_setting;
            engines[m] = e->version;
        }
    doc["iteration_mapping"] = mapping;
    doc["engines"] = engines;  // the other engines' library versions
    doc["shard"] = {{"k", run.shard.k}, {"n", run.shard.n}};
    if (!run.merged_from.empty()) doc["merged_from"] = run.merged_from;

    const std::vector<bool> front = front_flags(run.rows);
    json scenes = json::array();
    for (const BenchScene* s : run.scenes) {
        const int frames = frames_for(*s, run.timing);
        json scene = {{"name", s->name},
                      {"metric", metric_name(s->metric)},
                      {"meaning", metric_meaning(s->metric)},
                      {"unit", metric_unit(s->metric)},
                      {"target", s->verdict ? json(s->target) : json(nullptr)},
                      {"failure_threshold", s->stress ? json(s->failure_threshold) : json(nullptr)},
                      {"stress", s->stress},
                      {"verdict", s->verdict},
                      {"min_travel", json_number(s->min_travel)},
                      {"leave_speed", json_number(s->leave_speed)},
                      {"settle_s", json_number(s->settle)},
                      {"frames", frames},
                      {"warm_up_frames", warm_up_for(frames, run.timing)},
                      {"window_frames", window_for(frames, run.timing)}};
        json cheapest = nullptr;
        if (const auto best = cheapest_meeting_target(run.rows, s->name)) {
            const RunResult& r = run.rows[*best];
            cheapest = {{"method", r.method},
                        {"n", r.n},
                        {"time_per_step_ms", r.time_per_step * 1e3},
                        {"error", json_number(r.accuracy.error)}};
        }
        scene["cheapest_meeting_target"] = cheapest;
        json pareto = json::array();
        for (std::size_t i = 0; i < run.rows.size(); ++i)
            if (front[i] && run.rows[i].scene == s->name)
                pareto.push_back({{"method", run.rows[i].method}, {"n", run.rows[i].n}});
        scene["pareto_front"] = pareto;
        for (const RunResult& r : run.rows)
            if (r.scene == s->name && r.recording_ratio)
                scene["recording_overhead"] = {
                    {"method", r.method}, {"n", r.n}, {"ratio", json_number(*r.recording_ratio)}};
        scenes.push_back(scene);
    }
    doc["scenes"] = scenes;

    json rows = json::array();
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
        const RunResult& r = run.rows[i];
        const Accuracy& a = r.accuracy;
        rows.push_back({{"scene", r.scene},
                        {"method", r.method},
                        {"n", r.n},
                        {"iteration_setting", r.iteration_setting},
                        {"frames", r.frames},
                        {"simulated_s", r.frames * r.duration},
                        {"contacts_per_frame", r.contacts_per_frame},
                        {"time_per_step_ms", r.time_per_step * 1e3},
                        {"timed_frames", r.timed_frames},
                        {"error", json_number(a.error)},
                        {"meets_target", a.meets_target},
                        {"holds", a.holds},
                        {"failure", a.failure.empty() ? json(nullptr) : json(a.failure)},
                        {"failure_time_s", json_number(a.failure_time)},
                        {"end_penetration_m", json_number(a.end_penetration)},
                        {"top_drift_end_m", json_number(a.top_drift_end)},
                        {"top_drift_most_m", json_number(a.top_drift_most)},
                        {"any_drift_most_m", json_number(a.any_drift_most)},
                        {"top_sideways_drift_most_m", json_number(a.top_sideways_drift_most)},
                        {"settled_drift_most_m", json_number(a.settled_drift)},
                        {"least_travel_m", json_number(a.least_travel)},
                        {"collapse_time_s", json_number(a.collapse_time)},
                        {"end_kinetic_energy_j", json_number(a.end_kinetic_energy)},
                        {"jitter_rms_m_per_s", json_number(a.jitter)},
                        {"energy_gain", json_number(a.energy_gain)},
                        {"restitution_error", json_number(a.restitution_error)},
                        {"momentum_error", json_number(a.momentum_error)},
                        {"recovery_time_s", json_number(a.recovery_time)},
                        {"leave_speed_m_per_s", json_number(a.leave_speed)},
                        {"slide_error", json_number(a.slide_error)},
                        {"nan", a.nan_time.has_value()},
                        {"nan_time_s", json_number(a.nan_time)},
                        {"on_pareto_front", static_cast<bool>(front[i])},
                        {"recording_ratio", json_number(r.recording_ratio)}});
    }
    doc["rows"] = rows;
    return doc;
}

std::string stability_markdown(const BenchRun& run) {
    const StabilityMatrix m = stability_matrix(run.rows, run.methods, run.scenes);
    std::string md = "# Stability matrix\n\nEach method on each stress scene at its largest iteration count N (";
    for (std::size_t i = 0; i < run.iterations.size(); ++i) md += (i ? ", " : "") + std::to_string(run.iterations[i]);
    md +=
        "): it **meets target** (holds, error at most the target), it **holds, misses target** (by how many times "
        "the target), or it **fails** (with the failure and its time), and the scene's metric (docs/bench.md). "
        "\"from N = k\": smaller counts failed.\n\n| scene | metric, target |";
    for (const std::string& method : m.methods) md += " " + method + " |";
    md += "\n|---|---|";
    for (std::size_t i = 0; i < m.methods.size(); ++i) md += "---|";
    md += '\n';
    for (std::size_t j = 0; j < m.scenes.size(); ++j) {
        const BenchScene& spec = *m.scenes[j];
        md += "| " + spec.name + " | " + std::string(metric_name(spec.metric)) +
              " <= " + metric_text(spec, spec.target) + " |";
        for (std::size_t i = 0; i < m.methods.size(); ++i) {
            const StabilityCell& cell = m.cells[i][j];
            const std::string text = cell_text(spec, cell);
            md += " " + (cell.ran ? "**" + std::string(verdict_text(cell)) + "**: " + text : "not run") + " |";
        }
        md += '\n';
    }
    md +=
        "\n## Cheapest configuration per scene\n\nThe lowest median time per step among the (method, N) that meet the "
        "scene's target: model no more than a scene needs.\n\n| scene | metric | target | cheapest | time per step | "
        "error |\n|---|---|---|---|---|---|\n";
    for (const BenchScene* s : run.scenes) {
        if (!s->verdict) {
            md += "| " + s->name + " | no bench block: general measures | none | no verdict | | |\n";
            continue;
        }
        md += "| " + s->name + " | " + std::string(metric_meaning(s->metric)) + " | <= " + metric_text(*s, s->target) +
              " | ";
        if (const auto best = cheapest_meeting_target(run.rows, s->name)) {
            const RunResult& r = run.rows[*best];
            md += r.method + ", N = " + std::to_string(r.n) + " | " + format("%.3g", r.time_per_step * 1e3) + " ms | " +
                  metric_text(*s, r.accuracy.error) + " |\n";
        } else {
            md += "none meets it | | |\n";
        }
    }
    md +=
        "\n## Recording overhead\n\nThe same timed frames with a TraceRecorder on, over the recorder off (median "
        "step times).\n\n| scene | method | N | ratio |\n|---|---|---|---|\n";
    for (const RunResult& r : run.rows)
        if (r.recording_ratio)
            md += "| " + r.scene + " | " + r.method + " | " + std::to_string(r.n) + " | " +
                  format("%.2f", *r.recording_ratio) + " |\n";
    return md;
}

}  // namespace impulse::bench
