// Time per resolved contact, with the recorder off and on, and the time the preparation alone takes.
//
// Scene: N boxes (1 kg, 1 m cube) spaced apart, each landing on the ground on its four bottom corners
// (1-3 cm deep, closing at 1 m/s, a little sideways motion), so every contact needs both phases and the
// four contacts of a box share a body. The book preset resolves one frame; the time of a whole
// resolve_contacts call is divided by the number of contacts. The preparation figure times what
// resolve_contacts does before its phases: the bodies' mass properties and steps 1-5 of every contact
// (prepare_contacts). Each figure is the median of --repeats runs, each run repeating the call until
// --min-seconds have passed.
//
//   impulse-bench-resolve [--boxes 1,10,100] [--friction 0.5] [--repeats 15] [--min-seconds 0.2] [--csv FILE]
//
// The CSV (RFC 4180) is written atomically when the run is done; --csv - puts it on standard output and the table
// on standard error.

#include "command_line.hpp"
#include "formats/csv.hpp"
#include "record/trace_recorder.hpp"
#include "preparation/prepared_contact.hpp"
#include "resolver/resolver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>
#include <vector>

using namespace impulse;

namespace {

struct Landing {
    std::vector<RigidBody> bodies;
    std::vector<Contact> contacts;
};

Landing landing_boxes(int count, double friction) {
    Landing s;
    for (int i = 0; i < count; ++i) {
        RigidBody b;
        const double tilt = 0.01 * std::sin(i * 1.7);  // deterministic variety in depth and motion
        b.position = {3.0 * i, 0.48 + tilt, 0};
        b.velocity = {0.2 * std::cos(i * 0.9), -1.0, 0.2 * std::sin(i * 1.3)};
        b.angular_velocity = {0.1 * std::sin(i * 2.1), 0.0, 0.1 * std::cos(i * 0.7)};
        b.inverse_mass = 1.0;
        b.inverse_inertia_body = Mat3::Identity() * 6.0;  // 1 kg cube, side 1: I = m (b^2 + c^2) / 3 = 1/6
        s.bodies.push_back(b);
        for (double x : {-0.5, 0.5})
            for (double z : {-0.5, 0.5}) {
                const double depth = 0.02 - tilt + 0.005 * x;
                s.contacts.push_back({{i, world_body}, {3.0 * i + x, -depth, z}, {0, 1, 0}, depth, 0.2, friction});
            }
    }
    return s;
}

// Median seconds per call of `call`.
double median_seconds(const std::function<void()>& call, int repeats, double min_seconds) {
    using clock = std::chrono::steady_clock;
    std::vector<double> samples;
    for (int r = 0; r < repeats; ++r) {
        long calls = 0;
        const auto start = clock::now();
        double elapsed = 0.0;
        do {
            call();
            ++calls;
            elapsed = std::chrono::duration<double>(clock::now() - start).count();
        } while (elapsed < min_seconds);
        samples.push_back(elapsed / static_cast<double>(calls));
    }
    std::nth_element(samples.begin(), samples.begin() + repeats / 2, samples.end());
    return samples[static_cast<std::size_t>(repeats / 2)];
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "Time per resolved contact with the recorder off and on, and per prepared contact (book preset, one frame)",
        "impulse-bench-resolve"};
    std::vector<int> boxes{1, 10, 100};
    double friction = 0.5;
    int repeats = 15;
    double min_seconds = 0.2;
    app.add_option("--boxes", boxes, "Box counts (4 contacts each)")->delimiter(',')->check(CLI::PositiveNumber);
    app.add_option("--friction", friction, "Friction of every contact (0 = frictionless impulses)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--repeats", repeats, "Runs per figure; the median is reported")->check(CLI::Range(1, 1000));
    app.add_option("--min-seconds", min_seconds, "Least time per run")->check(CLI::Range(0.0, 60.0));
    const bench::CsvOutput csv(app);
    if (const std::optional<int> exit = bench::parse_command_line(app, argc, argv)) return *exit;
    // The CSV is checked before the run and written whole after it; on standard output, the table moves to stderr.
    if (!csv.check()) return 2;
    std::FILE* table = csv.table();

    const ResolverSettings settings = *preset("book");
    std::fprintf(table, "%6s %9s %11s %13s %13s %8s %18s\n", "boxes", "contacts", "iterations", "off ns/contact",
                 "on ns/contact", "on/off", "prepare ns/contact");
    std::string rows = formats::csv_row({"boxes", "contacts", "iterations", "friction", "off_ns_per_contact",
                                         "on_ns_per_contact", "recording_ratio", "prepare_ns_per_contact"});
    for (int count : boxes) {
        const Landing scene = landing_boxes(count, friction);
        std::vector<RigidBody> bodies;
        ResolutionSummary summary{};
        const double off = median_seconds(
            [&] {
                bodies = scene.bodies;
                summary = resolve_contacts(bodies, scene.contacts, settings);
            },
            repeats, min_seconds);
        const double on = median_seconds(
            [&] {
                bodies = scene.bodies;
                Trace trace;
                trace.scene.settings = settings;
                TraceRecorder recorder(trace);
                resolve_contacts(bodies, scene.contacts, settings, recorder);
            },
            repeats, min_seconds);
        std::size_t prepared = 0;
        const double prepare = median_seconds(
            [&] {
                const std::vector<MassProperties> mass = mass_properties(scene.bodies);
                std::pmr::vector<PreparedContact> contacts;
                prepare_contacts(scene.contacts, scene.bodies, mass, settings, contacts);
                prepared += contacts.size();
            },
            repeats, min_seconds);
        if (prepared == 0) return 1;  // keeps the preparation from being optimised away
        const double contacts = static_cast<double>(scene.contacts.size());
        const int iterations = summary.position.iterations_used + summary.velocity.iterations_used;
        std::fprintf(table, "%6d %9zu %11d %13.0f %13.0f %8.2f %18.1f\n", count, scene.contacts.size(), iterations,
                     off / contacts * 1e9, on / contacts * 1e9, on / off, prepare / contacts * 1e9);
        rows += formats::csv_row({std::to_string(count), std::to_string(scene.contacts.size()),
                                  std::to_string(iterations), formats::csv_number(friction),
                                  formats::csv_number(off / contacts * 1e9), formats::csv_number(on / contacts * 1e9),
                                  formats::csv_number(on / off), formats::csv_number(prepare / contacts * 1e9)});
    }
    return csv.write(rows) ? 0 : 2;
}
