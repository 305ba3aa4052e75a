#pragma once
// The bench's own scenes as the tests read them: each judged by its shipped file's "bench" block.

#include "bench/bench_plan.hpp"

#include <deque>
#include <fstream>
#include <sstream>
#include <string>

namespace impulse::test {

// The text of a bench scene's shipped file (scenes/<file> as bench_plan.cpp's table places it).
inline std::string bench_scene_text(const std::string& name) {
    const bench::ShippedScene* shipped = bench::find_shipped_scene(name);
    std::ifstream in(IMPULSE_SOURCE_DIR "/scenes/" + (shipped ? std::string(shipped->file) : name + ".json"));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Its spec, read once and kept for the whole test run (a BenchRun points to its scenes).
inline const bench::BenchScene* bench_scene(const std::string& name) {
    static std::deque<bench::BenchScene> read;
    for (const bench::BenchScene& s : read)
        if (s.name == name) return &s;
    return &read.emplace_back(bench::declared_bench_scene(name, bench_scene_text(name)));
}

}  // namespace impulse::test
