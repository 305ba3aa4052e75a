// How reading a scene grows with its size: a scene of N boxes (each a line of JSON with a name, a shape, a mass and
// a position, as scenes/grid_1000.json writes them) is generated in memory and read as `run` and `resolve` read a
// file (formats::read_scene_text: the JSON reader, the schema, the checks of every body), and the time per body is
// printed for each N. A reader that is linear in its input keeps that time flat from 10k to 1M bodies; the callback
// parser the reader replaced took 0.4 s for 30k bodies and 11 s for 240k (issue 29).
//
//   impulse-bench-read [--bodies 10000,100000,1000000] [--repeats 3] [--csv FILE]
//
// Each figure is the median of --repeats reads. The CSV (RFC 4180) is written atomically when the run is done.

#include "command_line.hpp"
#include "formats/csv.hpp"
#include "formats/scene_file.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace impulse;

namespace {

// N resting boxes in rows of 1000, 1.1 m apart.
std::string grid_scene(int bodies) {
    std::string text = "{\n  \"format\": \"impulse-lab-scene\",\n  \"ground\": {},\n  \"bodies\": [\n";
    char line[200];
    for (int i = 0; i < bodies; ++i) {
        std::snprintf(line, sizeof line,
                      "    {\"name\": \"box%d\", \"shape\": {\"type\": \"box\", \"half_size\": [0.5, 0.5, 0.5]}, "
                      "\"mass\": 1, \"position\": [%g, 0.5, %g]}%s\n",
                      i, (i % 1000) * 1.1, (i / 1000) * 1.1, i + 1 < bodies ? "," : "");
        text += line;
    }
    return text + "  ]\n}\n";
}

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Reading a scene of 10k, 100k and 1M bodies: time per body (linear reading keeps it flat)",
                 "impulse-bench-read");
    std::vector<int> sizes{10'000, 100'000, 1'000'000};
    int repeats = 3;
    app.add_option("--bodies", sizes, "Scene sizes, in bodies")->delimiter(',')->check(CLI::Range(1, 2'000'000));
    app.add_option("--repeats", repeats, "Reads per figure; the median is reported")->check(CLI::Range(1, 100));
    const bench::CsvOutput csv(app);
    if (const std::optional<int> exit = bench::parse_command_line(app, argc, argv)) return *exit;
    if (!csv.check()) return 2;
    std::FILE* table = csv.table();

    std::string rows = formats::csv_row({"bodies", "bytes", "seconds", "bodies_per_second", "ns_per_body"});
    std::fprintf(table, "%9s %10s %9s %15s %12s\n", "bodies", "MB", "seconds", "bodies/s", "ns per body");
    for (const int bodies : sizes) {
        const std::string text = grid_scene(bodies);
        std::vector<double> seconds;
        for (int r = 0; r < repeats; ++r) {
            const auto start = std::chrono::steady_clock::now();
            const Scene scene = formats::read_scene_text(text);
            seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            if (scene.bodies.size() != static_cast<std::size_t>(bodies)) return 1;
        }
        const double s = median(seconds);
        std::fprintf(table, "%9d %10.1f %9.3f %15.0f %12.0f\n", bodies, text.size() / 1e6, s, bodies / s,
                     s / bodies * 1e9);
        rows += formats::csv_row({std::to_string(bodies), std::to_string(text.size()), formats::csv_number(s),
                                  formats::csv_number(bodies / s), formats::csv_number(s / bodies * 1e9)});
        std::fflush(table);
    }
    return csv.write(rows) ? 0 : 2;
}
