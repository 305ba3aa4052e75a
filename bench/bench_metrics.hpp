#pragma once
// The accuracy of one run, measured as it goes: a tracker sees the bodies after every frame and, at the end,
// gives every measure the results report (not only the scene's own metric), the scene's error, whether it
// met its target and whether it held.

#include "bench/bench_plan.hpp"
#include "scene/scene.hpp"
#include "world/world.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impulse::bench {

struct Accuracy {
    double end_penetration = 0.0;             // m: deepest contact left after the last frame
    double top_drift_end = 0.0;               // m: the top body's distance from its start after the last frame
    double top_drift_most = 0.0;              // m: its largest distance from its start
    double any_drift_most = 0.0;              // m: the largest distance any body moved from its start
    double top_sideways_drift_most = 0.0;     // m: the top body's largest distance from its start across gravity
    double least_travel = 0.0;                // m: the smallest of the bodies' largest distances from their start
    std::optional<double> settled_drift;      // m: with a settle time, the metric's drift from the state then
    std::optional<double> collapse_time;      // s: when the scene's drift first passed its collapse threshold
    double end_kinetic_energy = 0.0;          // J
    double jitter = 0.0;                      // m/s: RMS of |displacement| / frame over the last second, every body
    double energy_gain = 0.0;                 // share of the kinetic energy at the first contact gained after it
    std::optional<double> restitution_error;  // the isolated impact, once it bounced
    std::optional<double> momentum_error;     // scenes without gravity
    std::optional<double> recovery_time;      // s: recovery_time scenes, once the overlap is gone
    std::optional<double> leave_speed;        // m/s: the fastest any body moved after that
    std::optional<double> slide_error;        // slide_error scenes: the worst body's |d - d_exact| / d_exact
    std::optional<double> nan_time;           // s: when a state first became NaN or infinite

    double error = 0.0;  // the scene's metric (BenchScene::metric); NaN when the run produced NaN
    bool meets_target = false;
    bool holds = false;
    std::optional<double> failure_time;  // s, when it failed (the end of the run for end-of-run measures)
    std::string failure;                 // why it failed, one phrase; empty when it holds
};

class AccuracyTracker {
public:
    // `scene` is the scene as run (its bodies are the start); frames are `scene.settings.duration` long.
    AccuracyTracker(const Scene& scene, const BenchScene& spec, int frames);

    // After frame `frame` was stepped: the bodies and what the step reported. Returns false once a state is
    // NaN (the run should stop: nothing after it means anything).
    bool observe(int frame, const std::vector<RigidBody>& bodies, const StepReport& report);

    // After the last observed frame: `bodies` as they ended.
    Accuracy finish(const std::vector<RigidBody>& bodies) const;

private:
    // The bodies' mechanical energy, 1/2 m v^2 + 1/2 w.Iw - m g.p summed (potential energy against gravity, zero at
    // the origin), and their kinetic energy alone.
    struct Energy {
        double mechanical = 0.0, kinetic = 0.0;
    };
    Energy energy(const std::vector<RigidBody>& bodies) const;
    // The metric's drift (top, sideways or any) of `bodies` from the positions `from`.
    double drift(const std::vector<RigidBody>& bodies, const std::vector<Vec3>& from) const;
    // The same bodies' move in every direction (top_sideways_drift's top body included along gravity).
    double whole_drift(const std::vector<RigidBody>& bodies, const std::vector<Vec3>& from) const;
    void observe_bounce(const std::vector<RigidBody>& bodies, const StepReport& report);
    void observe_recovery(double time, const std::vector<RigidBody>& bodies);
    std::optional<double> slide_error(const std::vector<RigidBody>& bodies, double time) const;

    const Scene& scene_;
    // Each body's principal moments, found once (a body's inertia never changes): kinetic_energy(body) would
    // decompose its inertia again for every body, twice a frame: 1.8 % of the profile of a run of Box3D's large
    // pyramid, 0.8 % with them kept.
    std::vector<PrincipalInertia> principal_;
    BenchScene spec_;
    double dt_;
    std::size_t top_;
    Accuracy a_;
    int last_frame_ = -1;
    // Jitter: squared speeds over the last second.
    int jitter_from_frame_;
    double jitter_sum_ = 0.0;
    long jitter_samples_ = 0;
    std::vector<Vec3> previous_positions_;  // each body's position after the previous frame
    // Energy: the reference at the first contact.
    std::optional<double> energy_before_contact_;
    double kinetic_before_contact_ = 0.0;
    double previous_energy_ = 0.0, previous_kinetic_ = 0.0;
    std::optional<double> energy_gain_time_;  // s: when the gain first passed the failure threshold
    // Restitution: the normal velocity arriving, and the one leaving when the contact last acted in the first
    // contact (the last frame whose change of velocity was not free flight's).
    RigidBody previous_body0_;
    std::optional<double> arriving_;
    double leaving_ = 0.0;
    bool bounce_done_ = false;
    double restitution_ = 0.0;
    // Overlap recovery: the deepest penetration at the start, and when it fell to 5 % of it.
    double deepest_at_start_ = 0.0;
    std::optional<double> explode_time_;  // s: when a body first left faster than the scene's leave_speed
    std::vector<double> travel_;          // each body's largest distance from its start
    // With a settle time: the frame that ends then, and the bodies' positions at its end.
    int settle_frame_ = -1;
    std::vector<Vec3> start_positions_, settled_;
};

}  // namespace impulse::bench
