#pragma once
// What the bench concludes from its runs, without rendering: the Pareto front of time against error per scene,
// the cheapest configuration that meets each scene's target, the stability matrix, and the files
// results.csv, results.json and stability.md. The charts (gui/bench_charts) draw the same data.

#include "bench/bench_runs.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace impulse::bench {

// A point of the speed-accuracy plane.
struct TimeError {
    double time = 0.0;   // s per step
    double error = 0.0;  // the scene's metric
    bool held = true;    // a run that failed (collapsed, NaN, ...) is no configuration to choose
};

// Indices of the runs that held and that no other run that held beats on both (at most as slow and at most
// as wrong, and better on one), sorted by time. So the front starts at the fastest run that held, never at a
// fast collapse. Points whose error is NaN are never on the front.
std::vector<std::size_t> pareto_front(const std::vector<TimeError>& points);

// The row index of the fastest configuration of `scene` that meets its target, if any does.
std::optional<std::size_t> cheapest_meeting_target(const std::vector<RunResult>& rows, const std::string& scene);

// A stability-matrix cell: a method on a stress scene, judged at its largest iteration count. Three verdicts:
// it meets the target (held, error at most the target), it holds but misses the target, or it fails.
struct StabilityCell {
    bool ran = false;
    bool holds = false;
    bool meets_target = false;
    int n = 0;                           // the iteration count judged (the largest run)
    std::optional<int> holds_from;       // held at the largest N but not at every N: the smallest N from which
                                         // every larger one held
    std::string failure;                 // at n: why it failed
    std::optional<double> failure_time;  // s
    double error = 0.0;                  // at n: the scene's metric
};

struct StabilityMatrix {
    std::vector<std::string> methods;               // rows
    std::vector<const BenchScene*> scenes;          // columns: the stress scenes that ran
    std::vector<std::vector<StabilityCell>> cells;  // [method][scene]
};

StabilityMatrix stability_matrix(const std::vector<RunResult>& rows, const std::vector<std::string>& methods,
                                 const std::vector<const BenchScene*>& scenes);

// "0.123 m", "1.2e-05", "NaN": a metric value with its unit.
std::string metric_text(const BenchScene& spec, double value);
// The verdict of a cell: "meets target", "holds, misses target", "fails" (or "not run").
std::string_view verdict_text(const StabilityCell& cell);
// One line for a cell after its verdict: "from N = 4, top_drift 0.0295 m", "6.1 × the target, top_drift
// 0.306 m", "collapsed at 3.28 s, top_drift 2.22 m".
std::string cell_text(const BenchScene& spec, const StabilityCell& cell);

// Where the run happened: filled by the command (machine, compiler, commit, date).
struct Provenance {
    std::string cpu;
    int cores = 0;
    std::string compiler;
    std::string flags;
    std::string build_type;
    std::string commit;
    std::string date;  // ISO 8601, UTC
};

struct BenchRun {
    std::vector<const BenchScene*> scenes;
    std::vector<std::string> methods;
    std::vector<int> iterations;
    Timing timing;
    std::vector<RunResult> rows;  // scene-major, then method, then N
    double wall_time = 0.0;       // s
};

std::string results_csv(const BenchRun& run);
nlohmann::ordered_json results_json(const BenchRun& run, const Provenance& provenance);
std::string stability_markdown(const BenchRun& run);

}  // namespace impulse::bench
