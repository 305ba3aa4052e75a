// The projected Gauss-Seidel velocity solve against a lean scalar kernel of the same three rows.
//
//   impulse-bench-pgs [SCENE] [--frame 60] [--sweeps 10] [--repeats 31] [--min-seconds 0.05]
//
// Simulates SCENE (default scenes/pyramid_20.json) with the pgs preset up to --frame, then takes that frame's
// contacts (detected after the frame's integration, as the world step does) and times, from the same start
// each time:
//   production   the pgs velocity method as the resolver runs it (methods/projected_gauss_seidel.cpp): its rows
//                built from the prepared contacts, the warm start from the contact memory, the sweeps, the
//                velocities written back and the totals remembered; the contacts' preparation (steps 1-5) is
//                timed apart, as `prepare`;
//   lean kernel  the same three rows (normal row, two friction rows solved together, the cone, the same early
//                stop) written as plain loops over plain arrays of doubles, on the same contacts' data with the
//                same warm-start totals: the least a sweep of these rows costs here. Its setup is not timed.
// Each figure is the median over --repeats runs of the time per call (a run repeats the call until
// --min-seconds have passed; the three are timed in turn within each repeat), printed in ns per contact-iteration: time
// / (active contacts x sweeps run), the production sweeps counted from a recorded run. Both must end with the same
// velocities to rounding; the largest difference is printed.

#include "command_line.hpp"
#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"
#include "formats/settings_json.hpp"
#include "methods/contact_rows.hpp"
#include "methods/method_table.hpp"
#include "methods/solver_common.hpp"
#include "record/trace_recorder.hpp"
#include "body/integrate.hpp"
#include "world/world.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

using namespace impulse;

namespace {

// --- the lean kernel ----------------------------------------------------------------------------------------

struct LeanBody {
    double v[3], w[3];
    double inverse_mass;
    double inverse_inertia[9];  // row-major
};

struct LeanContact {
    int body0, body1;  // body1 < 0: the world
    double n[3], t1[3], t2[3];
    double r0[3], r1[3];
    double normal_mass, normal_response, target, friction;
    double k_tn[2];      // K_tn
    double k_tt[3];      // K_tt: (11, 12, 22)
    double k_tt_inv[3];  // K_tt^-1
    double lambda[3];
};

inline double dot(const double* a, const double* b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// The disc point nearest `free` in K_tt's metric (the same Newton iteration as methods/contact_rows.cpp).
inline void project(const double* k, const double* k_inverse, double& x, double& y, double limit) {
    const double wx = k[0] * x + k[1] * y, wy = k[1] * x + k[2] * y;
    const double inverse_limit = 1.0 / limit;
    double m00 = k_inverse[0], m01 = k_inverse[1], m11 = k_inverse[2], nu = 0.0;
    for (int step = 0; step < 16; ++step) {
        const double s2 = x * x + y * y, s = std::sqrt(s2);
        if (s <= limit * (1.0 + 1e-13)) break;
        nu += s2 * (s * inverse_limit - 1.0) / (x * (m00 * x + m01 * y) + y * (m01 * x + m11 * y));
        const double a = k[0] + nu, c = k[2] + nu, inv = 1.0 / (a * c - k[1] * k[1]);
        m00 = c * inv, m01 = -k[1] * inv, m11 = a * inv;
        x = m00 * wx + m01 * wy;
        y = m01 * wx + m11 * wy;
    }
    const double scale = limit / std::sqrt(x * x + y * y);
    x *= scale;
    y *= scale;
}

inline void apply(LeanBody& b, const double* r, const double* p, double sign) {
    const double m = b.inverse_mass * sign;
    b.v[0] += p[0] * m, b.v[1] += p[1] * m, b.v[2] += p[2] * m;
    const double t[3] = {sign * (r[1] * p[2] - r[2] * p[1]), sign * (r[2] * p[0] - r[0] * p[2]),
                         sign * (r[0] * p[1] - r[1] * p[0])};
    const double* i = b.inverse_inertia;
    b.w[0] += i[0] * t[0] + i[1] * t[1] + i[2] * t[2];
    b.w[1] += i[3] * t[0] + i[4] * t[1] + i[5] * t[2];
    b.w[2] += i[6] * t[0] + i[7] * t[1] + i[8] * t[2];
}

// Sweeps until no visit changed its contact's velocity by more than epsilon; returns the sweeps run.
int lean_sweeps(std::vector<LeanBody>& bodies, std::vector<LeanContact>& contacts, int sweeps, double epsilon) {
    const double epsilon2 = epsilon * epsilon;
    for (int pass = 0; pass < sweeps; ++pass) {
        double largest = 0.0;
        for (LeanContact& c : contacts) {
            LeanBody& a = bodies[static_cast<std::size_t>(c.body0)];
            double d[3] = {a.v[0] + a.w[1] * c.r0[2] - a.w[2] * c.r0[1], a.v[1] + a.w[2] * c.r0[0] - a.w[0] * c.r0[2],
                           a.v[2] + a.w[0] * c.r0[1] - a.w[1] * c.r0[0]};
            if (c.body1 >= 0) {
                const LeanBody& b = bodies[static_cast<std::size_t>(c.body1)];
                d[0] -= b.v[0] + b.w[1] * c.r1[2] - b.w[2] * c.r1[1];
                d[1] -= b.v[1] + b.w[2] * c.r1[0] - b.w[0] * c.r1[2];
                d[2] -= b.v[2] + b.w[0] * c.r1[1] - b.w[1] * c.r1[0];
            }
            const double vn = dot(c.n, d), v1 = dot(c.t1, d), v2 = dot(c.t2, d);
            const double n_before = c.lambda[0];
            const double n_after = std::max(n_before + c.normal_mass * (c.target - vn), 0.0);
            const double dn = n_after - n_before;
            double d1 = 0.0, d2 = 0.0;
            if (c.friction != 0.0) {
                const double s1 = v1 + c.k_tn[0] * dn, s2 = v2 + c.k_tn[1] * dn;
                double x = c.lambda[1] - (c.k_tt_inv[0] * s1 + c.k_tt_inv[1] * s2);
                double y = c.lambda[2] - (c.k_tt_inv[1] * s1 + c.k_tt_inv[2] * s2);
                const double limit = c.friction * n_after;
                if (x * x + y * y > limit * limit) {
                    if (limit <= 0.0)
                        x = y = 0.0;
                    else
                        project(c.k_tt, c.k_tt_inv, x, y, limit);
                }
                d1 = x - c.lambda[1];
                d2 = y - c.lambda[2];
                c.lambda[1] = x;
                c.lambda[2] = y;
            }
            c.lambda[0] = n_after;
            // |K delta lambda|^2.
            const double cn = c.normal_response * dn + c.k_tn[0] * d1 + c.k_tn[1] * d2;
            const double c1 = c.k_tn[0] * dn + c.k_tt[0] * d1 + c.k_tt[1] * d2;
            const double c2 = c.k_tn[1] * dn + c.k_tt[1] * d1 + c.k_tt[2] * d2;
            largest = std::max(largest, cn * cn + c1 * c1 + c2 * c2);
            const double p[3] = {c.n[0] * dn + c.t1[0] * d1 + c.t2[0] * d2, c.n[1] * dn + c.t1[1] * d1 + c.t2[1] * d2,
                                 c.n[2] * dn + c.t1[2] * d1 + c.t2[2] * d2};
            apply(a, c.r0, p, 1.0);
            if (c.body1 >= 0) apply(bodies[static_cast<std::size_t>(c.body1)], c.r1, p, -1.0);
        }
        if (largest <= epsilon2) return pass + 1;
    }
    return sweeps;
}

// The lean kernel's data, from the production rows (the same numbers), warm-start totals applied.
void lean_setup(const std::vector<RigidBody>& rigid, std::span<const PreparedContact> prepared,
                const ContactMemory& memory, std::vector<LeanBody>& bodies, std::vector<LeanContact>& contacts) {
    const std::pmr::vector<SolverBody> solver = solver_bodies(rigid, mass_properties(rigid));
    bodies.clear();
    for (const SolverBody& s : solver) {
        LeanBody b{};
        for (int k = 0; k < 3; ++k) b.v[k] = s.velocity[k], b.w[k] = s.angular_velocity[k];
        b.inverse_mass = s.mass.inverse_mass;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) b.inverse_inertia[3 * r + c] = s.mass.inverse_inertia_world(r, c);
        bodies.push_back(b);
    }
    std::vector<ContactRow> rows;
    for (const PreparedContact& c : prepared)
        if (can_move(c)) fill_contact_row(rows.emplace_back(), c, solver.data());
    RememberedTotals remembered(memory, std::pmr::new_delete_resource());
    contacts.clear();
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const ContactRow& row = rows[r];
        const PreparedContact& d = prepared[static_cast<std::size_t>(row.contact)];
        LeanContact c{};
        c.body0 = row.body[0];
        c.body1 = row.body[1];
        for (int k = 0; k < 3; ++k) {
            c.n[k] = row.basis(k, 0), c.t1[k] = row.basis(k, 1), c.t2[k] = row.basis(k, 2);
            c.r0[k] = row.anchor[0][k], c.r1[k] = row.anchor[1][k];
        }
        c.normal_mass = row.normal_mass;
        c.normal_response = row.normal_response;
        c.target = prepared_normal_velocity(d);
        c.friction = row.friction;
        for (int k = 0; k < 2; ++k) c.k_tn[k] = row.normal_to_tangent[static_cast<std::size_t>(k)];
        for (int k = 0; k < 3; ++k) {
            c.k_tt[k] = row.tangent_response[static_cast<std::size_t>(k)];
            c.k_tt_inv[k] = row.tangent_mass[static_cast<std::size_t>(k)];
        }
        if (const std::optional<RowVisit> warm = remembered.of(row.basis, row.friction, contact_key(d))) {
            const Vec3 total = vector_of(warm->after);
            for (int k = 0; k < 3; ++k) c.lambda[k] = total[k];
            const double p[3] = {c.n[0] * total.x() + c.t1[0] * total.y() + c.t2[0] * total.z(),
                                 c.n[1] * total.x() + c.t1[1] * total.y() + c.t2[1] * total.z(),
                                 c.n[2] * total.x() + c.t1[2] * total.y() + c.t2[2] * total.z()};
            apply(bodies[static_cast<std::size_t>(c.body0)], c.r0, p, 1.0);
            if (c.body1 >= 0) apply(bodies[static_cast<std::size_t>(c.body1)], c.r1, p, -1.0);
        }
        contacts.push_back(c);
    }
}

// --- timing -------------------------------------------------------------------------------------------------

// The two timed calls, kept out of line so an instruction count can be collected for each alone
// (valgrind --tool=callgrind --toggle-collect='*timed_production*').
[[gnu::noinline]] PhaseOutcome timed_production(FrameContext& context) {
    return method_row(VelocityMethod::projected_gauss_seidel).solve(context);
}

[[gnu::noinline]] int timed_lean(std::vector<LeanBody>& bodies, std::vector<LeanContact>& contacts, int sweeps,
                                 double epsilon) {
    return lean_sweeps(bodies, contacts, sweeps, epsilon);
}

// Seconds per `call` over one run: setup + call repeated until `min_seconds` of calls have passed; only the
// calls are timed.
double run_seconds(const std::function<void()>& setup, const std::function<void()>& call, double min_seconds) {
    using clock = std::chrono::steady_clock;
    long calls = 0;
    double elapsed = 0.0;
    do {
        setup();
        const auto start = clock::now();
        call();
        elapsed += std::chrono::duration<double>(clock::now() - start).count();
        ++calls;
    } while (elapsed < min_seconds);
    return elapsed / static_cast<double>(calls);
}

double median(std::vector<double> samples) {
    std::nth_element(samples.begin(), samples.begin() + static_cast<long>(samples.size() / 2), samples.end());
    return samples[samples.size() / 2];
}

Scene load(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw formats::InputError(path, "cannot be read");
    std::stringstream text;
    text << in.rdbuf();
    return formats::read_scene_text(text.str());
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"The pgs velocity solve against a lean scalar kernel of the same three rows", "impulse-bench-pgs"};
    std::string scene_path = "scenes/pyramid_20.json";
    int frame = 60, sweeps = 10, repeats = 31;
    double min_seconds = 0.05;
    app.add_option("SCENE", scene_path, "Scene file")->check(CLI::ExistingFile);
    app.add_option("--frame", frame, "The frame whose contacts are solved")->check(CLI::Range(0, 100000));
    app.add_option("--sweeps", sweeps, "sweeps (N)")->check(CLI::Range(1, 1000));
    app.add_option("--repeats", repeats, "Runs; the median is printed")->check(CLI::Range(1, 1000));
    app.add_option("--min-seconds", min_seconds, "Least time per run")->check(CLI::Range(0.0, 10.0));
    if (const std::optional<int> exit = bench::parse_command_line(app, argc, argv)) return *exit;
    Scene scene;
    try {
        scene = load(scene_path);
        formats::apply_setting(scene, "preset=pgs", "--set");
        formats::apply_setting(scene, "sweeps=" + std::to_string(sweeps), "--set");
    } catch (const formats::InputError& e) {
        std::cerr << "impulse-bench-pgs: " << e.where() << ": " << e.problem() << '\n';
        return 2;
    }
    const ResolverSettings& settings = scene.settings;

    // The state at the start of `frame`, then that frame's integration and contacts, as the world step makes them.
    World world(scene);
    while (world.frame() < frame) world.step();
    std::vector<RigidBody> bodies = world.bodies();
    const ContactMemory& memory = world.contact_memory();
    Recorder nobody;
    for (RigidBody& b : bodies)
        integrate(b, scene.world.gravity, settings.duration, {scene.world.linear_damping, scene.world.angular_damping},
                  settings.orientation_update);
    const std::vector<Contact> contacts = detect_contacts(scene, bodies).contacts;
    const std::vector<MassProperties> mass = mass_properties(bodies);
    std::pmr::vector<PreparedContact> prepared;
    prepare_contacts(contacts, bodies, mass, settings, prepared);

    // The production velocity phase, as the resolver calls it, from copies of the frame's start.
    std::vector<RigidBody> out;
    std::pmr::vector<PreparedContact> work;
    ContactMemory kept;
    const auto setup = [&] {
        out = bodies;
        work = prepared;
        kept = memory;
    };
    Trace trace;
    trace.scene = scene;
    TraceRecorder recorder(trace);
    recorder.begin_frame(frame, bodies, mass);
    recorder.contacts_prepared({contacts, prepared, bodies, mass, settings});
    setup();
    FrameContext recorded{out, work, mass, settings, recorder, true, nullptr, &kept, {}};
    method_row(VelocityMethod::projected_gauss_seidel).solve(recorded);
    int production_sweeps = 0;
    for (const VelocityIteration& it : trace.frames.back().velocity.iterations)
        if (it.sweep && it.sweep->stage == SolverStage::solve)
            production_sweeps = std::max(production_sweeps, it.sweep->pass + 1);

    std::vector<LeanBody> lean_bodies, lean_start;
    std::vector<LeanContact> lean_contacts, lean_contacts_start;
    lean_setup(bodies, prepared, memory, lean_start, lean_contacts_start);
    const int active = static_cast<int>(lean_contacts_start.size());  // one per row an impulse can move
    int lean_sweeps_run = 0;

    // Interleaved: each repeat times the preparation, the production phase and the lean kernel in turn, so a
    // change of machine load touches all three alike; the medians are printed.
    std::vector<double> prepare_samples, production_samples, lean_samples;
    for (int r = 0; r < repeats; ++r) {
        prepare_samples.push_back(run_seconds([] {},
                                              [&] {
                                                  // What the resolver prepares: the bodies' mass, then
                                                  // every contact.
                                                  const std::vector<MassProperties> again_mass =
                                                      mass_properties(bodies);
                                                  std::pmr::vector<PreparedContact> again;
                                                  prepare_contacts(contacts, bodies, again_mass, settings, again);
                                                  if (again.size() != prepared.size()) std::abort();
                                              },
                                              min_seconds));
        production_samples.push_back(run_seconds(
            setup,
            [&] {
                // As the resolver calls it when nothing records.
                FrameContext context{out, work, mass, settings, nobody, false, nullptr, &kept, {}};
                timed_production(context);
            },
            min_seconds));
        lean_samples.push_back(run_seconds(
            [&] {
                lean_bodies = lean_start;
                lean_contacts = lean_contacts_start;
            },
            [&] { lean_sweeps_run = timed_lean(lean_bodies, lean_contacts, sweeps, settings.velocity_epsilon); },
            min_seconds));
    }
    const double prepare_s = median(prepare_samples), production_s = median(production_samples),
                 lean_s = median(lean_samples);

    setup();
    FrameContext unrecorded{out, work, mass, settings, nobody, false, nullptr, &kept, {}};
    method_row(VelocityMethod::projected_gauss_seidel).solve(unrecorded);
    double difference = 0.0;
    for (std::size_t b = 0; b < out.size(); ++b)
        for (int k = 0; k < 3; ++k)
            difference = std::max({difference, std::abs(out[b].velocity[k] - lean_bodies[b].v[k]),
                                   std::abs(out[b].angular_velocity[k] - lean_bodies[b].w[k])});

    const double production_ns = production_s * 1e9 / (double(active) * production_sweeps);
    const double lean_ns = lean_s * 1e9 / (double(active) * lean_sweeps_run);
    std::printf("scene %s, frame %d: %zu contacts (%d active), %zu bodies\n", scene_path.c_str(), frame,
                prepared.size(), active, bodies.size());
    std::printf("prepare (steps 1-5)          %8.3f ms  (%.1f ns per contact)\n", prepare_s * 1e3,
                prepare_s * 1e9 / double(prepared.size()));
    std::printf("production velocity phase   %8.3f ms  %d sweeps  %6.1f ns per contact-iteration\n", production_s * 1e3,
                production_sweeps, production_ns);
    std::printf("lean kernel sweeps          %8.3f ms  %d sweeps  %6.1f ns per contact-iteration\n", lean_s * 1e3,
                lean_sweeps_run, lean_ns);
    std::printf("ratio production / lean     %8.2f\n", production_ns / lean_ns);
    std::printf("largest velocity difference %8.1e m/s or rad/s\n", difference);
    return 0;
}
