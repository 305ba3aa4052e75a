#pragma once
// `impulse-lab bench --merge DIR...`: the shards of one matrix (each run with --shard K/N, each folder holding its
// results.json) read back and joined into one run, from which the same five files are written. So a large
// matrix can be spread over the machines of a job array and merged.

#include "bench/bench_report.hpp"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace impulse::bench {

struct MergedRun {
    BenchRun run;
    std::deque<BenchScene> scenes;  // what run.scenes points to
    Provenance provenance;          // the first shard's (its machine, compiler, commit and date)
};

// `documents[i]` is the results.json found in `folders[i]`. Every shard of one matrix must be there once: the
// same scenes (and their metrics and targets), methods, iteration counts and repeats, shards 1..N of one N, and
// every configuration exactly once. Throws formats::InputError("--merge", ...) saying which folder and what is wrong.
std::unique_ptr<MergedRun> merge_results(const std::vector<nlohmann::ordered_json>& documents,
                                         const std::vector<std::string>& folders);

}  // namespace impulse::bench
