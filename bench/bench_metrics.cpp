#include "bench/bench_metrics.hpp"

#include "body/integrate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impulse::bench {

namespace {

bool finite(const RigidBody& b) {
    return b.position.allFinite() && b.velocity.allFinite() && b.angular_velocity.allFinite() &&
           b.orientation.coeffs().allFinite();
}

Vec3 linear_momentum(const std::vector<RigidBody>& bodies) {
    Vec3 p = Vec3::Zero();
    for (const RigidBody& b : bodies)
        if (b.inverse_mass > 0.0) p += b.velocity / b.inverse_mass;
    return p;
}

double momentum_scale(const std::vector<RigidBody>& bodies) {
    double sum = 0.0;
    for (const RigidBody& b : bodies)
        if (b.inverse_mass > 0.0) sum += b.velocity.norm() / b.inverse_mass;
    return sum;
}

Vec3 ground_normal(const Scene& scene) {
    return scene.ground ? scene.ground->plane.normal : Vec3::UnitY();
}

// Against gravity (+y without gravity): "sideways" is across it.
Vec3 up_of(const Scene& scene) {
    return scene.world.gravity.isZero() ? Vec3::UnitY() : Vec3(-scene.world.gravity.normalized());
}

double deepest_penetration(const Scene& scene, const std::vector<RigidBody>& bodies) {
    double deepest = 0.0;
    for (const Contact& c : detect_contacts(scene, bodies).contacts) deepest = std::max(deepest, c.penetration);
    return deepest;
}

double fastest(const std::vector<RigidBody>& bodies) {
    double speed = 0.0;
    for (const RigidBody& b : bodies) speed = std::max(speed, b.velocity.norm());
    return speed;
}

// A separated overlap: the deepest penetration at most this share of the deepest at the start.
constexpr double recovered_share = 0.05;

}  // namespace

AccuracyTracker::AccuracyTracker(const Scene& scene, const BenchScene& spec, int frames)
    : scene_(scene),
      spec_(spec),
      dt_(scene.settings.duration),
      top_(highest_body(scene)),
      jitter_from_frame_(std::max(0, frames - static_cast<int>(std::lround(1.0 / scene.settings.duration)))) {
    for (const RigidBody& b : scene.bodies) principal_.push_back(principal_inertia(b));
    const Energy start = energy(scene.bodies);
    previous_energy_ = start.mechanical;
    previous_kinetic_ = start.kinetic;
    if (!scene.bodies.empty()) previous_body0_ = scene.bodies[0];
    travel_.assign(scene.bodies.size(), 0.0);
    for (const RigidBody& b : scene.bodies) start_positions_.push_back(b.position);
    if (spec.settle) settle_frame_ = static_cast<int>(std::lround(*spec.settle / dt_)) - 1;
    if (spec.metric == Metric::recovery_time) deepest_at_start_ = deepest_penetration(scene, scene.bodies);
    // The isolated impact's restitution: body 0's material against the ground's (or against body 1's).
    if (!scene.bodies.empty() && !scene.body_materials.empty()) {
        const Material& own = scene.materials.at(scene.body_materials[0]);
        const Material& other = scene.ground
                                    ? scene.materials.at(scene.ground->material)
                                    : scene.materials.at(scene.body_materials.size() > 1 ? scene.body_materials[1]
                                                                                         : scene.body_materials[0]);
        restitution_ = combine(own, other).restitution;
    }
}

double AccuracyTracker::whole_drift(const std::vector<RigidBody>& bodies, const std::vector<Vec3>& from) const {
    if (spec_.metric == Metric::any_drift) return drift(bodies, from);
    return (bodies[top_].position - from[top_]).norm();
}

double AccuracyTracker::drift(const std::vector<RigidBody>& bodies, const std::vector<Vec3>& from) const {
    if (spec_.metric == Metric::any_drift) {
        double any = 0.0;
        for (std::size_t i = 0; i < bodies.size(); ++i) any = std::max(any, (bodies[i].position - from[i]).norm());
        return any;
    }
    const Vec3 move = bodies[top_].position - from[top_];
    if (spec_.metric == Metric::top_sideways_drift) {
        const Vec3 up = up_of(scene_);
        return (move - move.dot(up) * up).norm();
    }
    return move.norm();
}

AccuracyTracker::Energy AccuracyTracker::energy(const std::vector<RigidBody>& bodies) const {
    Energy e;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        const double kinetic = kinetic_energy(b, principal_[i]);
        e.kinetic += kinetic;
        e.mechanical += kinetic;
        if (b.inverse_mass > 0.0) e.mechanical -= scene_.world.gravity.dot(b.position) / b.inverse_mass;
    }
    return e;
}

bool AccuracyTracker::observe(int frame, const std::vector<RigidBody>& bodies, const StepReport& report) {
    last_frame_ = frame;
    const double time = (frame + 1) * dt_;
    if (!std::all_of(bodies.begin(), bodies.end(), finite)) {
        a_.nan_time = time;
        return false;
    }
    const Vec3 top_move = bodies[top_].position - scene_.bodies[top_].position;
    const double top_drift = top_move.norm();
    a_.top_drift_most = std::max(a_.top_drift_most, top_drift);
    a_.top_drift_end = top_drift;
    // Across gravity: the move less its part along up, d - (d . u) u.
    const Vec3 up = up_of(scene_);
    a_.top_sideways_drift_most = std::max(a_.top_sideways_drift_most, (top_move - top_move.dot(up) * up).norm());
    double any = 0.0;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const double moved = (bodies[i].position - scene_.bodies[i].position).norm();
        travel_[i] = std::max(travel_[i], moved);
        any = std::max(any, moved);
    }
    a_.any_drift_most = std::max(a_.any_drift_most, any);
    if (is_drift(spec_.metric)) {
        // A collapse: the metric's drift from the start passes the threshold (a tower toppling while it settles),
        // or, once settled, the whole move of the watched bodies from the settled state does (a pyramid crumbling
        // straight down moves its top little sideways).
        bool collapsed = drift(bodies, start_positions_) > spec_.failure_threshold;
        if (frame == settle_frame_)
            for (const RigidBody& b : bodies) settled_.push_back(b.position);
        if (!settled_.empty()) {
            a_.settled_drift = std::max(a_.settled_drift.value_or(0.0), drift(bodies, settled_));
            collapsed = collapsed || whole_drift(bodies, settled_) > spec_.failure_threshold;
        }
        if (!a_.collapse_time && collapsed) a_.collapse_time = time;
    }

    // Jitter is the motion the eye sees: each body's displacement over the frame / the frame's duration. The
    // velocity left after a step is not it: with Baumgarte and the integrate-first step, a resting box leaves
    // every step at +g h upwards, exactly what the next step's gravity removes, and never moves.
    if (frame >= jitter_from_frame_ && previous_positions_.size() == bodies.size()) {
        for (std::size_t i = 0; i < bodies.size(); ++i)
            jitter_sum_ += ((bodies[i].position - previous_positions_[i]) / dt_).squaredNorm();
        jitter_samples_ += static_cast<long>(bodies.size());
    }
    previous_positions_.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) previous_positions_[i] = bodies[i].position;

    // Energy: the reference is the state arriving at the first contact (the end of the frame before it).
    const Energy now = energy(bodies);
    if (report.contacts > 0 && !energy_before_contact_) {
        energy_before_contact_ = previous_energy_;
        kinetic_before_contact_ = previous_kinetic_;
    }
    if (energy_before_contact_ && kinetic_before_contact_ > 0.0) {
        a_.energy_gain = std::max(a_.energy_gain, (now.mechanical - *energy_before_contact_) / kinetic_before_contact_);
        if (!energy_gain_time_ && a_.energy_gain > spec_.failure_threshold) energy_gain_time_ = time;
    }
    previous_energy_ = now.mechanical;
    previous_kinetic_ = now.kinetic;

    observe_bounce(bodies, report);
    if (spec_.metric == Metric::recovery_time) observe_recovery(time, bodies);
    return true;
}

void AccuracyTracker::observe_bounce(const std::vector<RigidBody>& bodies, const StepReport& report) {
    // Restitution of body 0's first bounce: v_before is its normal velocity at the end of the frame before the
    // first contact; v_after at the end of the last frame of that contact in which the contact acted, that is,
    // whose change of the normal velocity is not what gravity (and damping) alone give. The velocity this frame's
    // gravity added before the contact is not part of the collision (the book removes it:
    // velocity_from_acceleration); nor are the frames of free flight that follow a bounce while the body is still
    // below the surface it left (docs/bench.md: a method that bounces a body from inside the ground, as soft step
    // does, has it overlap the ground for a frame or two while it flies out, and gravity's g dt in those frames is
    // no part of its restitution).
    const Vec3 normal = ground_normal(scene_);
    const double normal_velocity = bodies[0].velocity.dot(normal);
    if (!bounce_done_) {
        if (report.contacts > 0) {
            RigidBody free = previous_body0_;
            integrate_velocity(free, scene_.world.gravity, dt_,
                               {scene_.world.linear_damping, scene_.world.angular_damping});
            const double free_velocity = free.velocity.dot(normal);
            // To 1e-6 relative: a single-precision solve (soft_step_wide) that warm starts a total and takes it
            // back leaves a float's last bit, 2.4e-7 m/s on 2.58 m/s, which is rounding, not the contact acting.
            const bool acted =
                std::abs(normal_velocity - free_velocity) > 1e-6 * std::max(1.0, std::abs(free_velocity));
            if (!arriving_) {
                arriving_ = previous_body0_.velocity.dot(normal);
                leaving_ = normal_velocity;
            }
            if (acted) leaving_ = normal_velocity;
        } else if (arriving_) {
            bounce_done_ = true;
        }
    }
    previous_body0_ = bodies[0];
}

void AccuracyTracker::observe_recovery(double time, const std::vector<RigidBody>& bodies) {
    // Separated once the deepest penetration the collision tests find after the frame is at most 5 % of the
    // deepest at the start; from then on, the fastest any body moves is what the push left it with.
    if (!a_.recovery_time) {
        if (deepest_penetration(scene_, bodies) > recovered_share * deepest_at_start_) return;
        a_.recovery_time = time;
        a_.leave_speed = 0.0;
    }
    a_.leave_speed = std::max(*a_.leave_speed, fastest(bodies));
    if (!explode_time_ && spec_.leave_speed && *a_.leave_speed > *spec_.leave_speed) explode_time_ = time;
}

std::optional<double> AccuracyTracker::slide_error(const std::vector<RigidBody>& bodies, double time) const {
    // Coulomb on level ground: a body sliding at v0 decelerates at a = mu g until it stops, after t_s = v0 / a,
    // so at time t it has slid d = v0 t' - a t'^2 / 2 with t' = min(t, t_s) (v0^2 / (2 mu g) once stopped).
    // d is measured along its first velocity; mu is its material's with the ground's (docs/scenes.md).
    const double g = scene_.world.gravity.norm();
    std::optional<double> worst;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& start = scene_.bodies[i];
        const double v0 = start.velocity.norm();
        if (start.inverse_mass == 0.0 || v0 == 0.0 || !scene_.ground) continue;
        const double mu =
            combine(scene_.materials.at(scene_.body_materials[i]), scene_.materials.at(scene_.ground->material))
                .friction;
        const double a = mu * g;
        const double t = a > 0.0 ? std::min(time, v0 / a) : time;
        const double exact = v0 * t - 0.5 * a * t * t;
        const double slid = (bodies[i].position - start.position).dot(start.velocity / v0);
        const double error = std::abs(slid - exact) / exact;
        worst = std::max(worst.value_or(0.0), error);
    }
    return worst;
}

Accuracy AccuracyTracker::finish(const std::vector<RigidBody>& bodies) const {
    Accuracy a = a_;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (!a.nan_time) {
        for (const Contact& c : detect_contacts(scene_, bodies).contacts)
            a.end_penetration = std::max(a.end_penetration, c.penetration);
        a.end_kinetic_energy = energy(bodies).kinetic;
        a.jitter = jitter_samples_ > 0 ? std::sqrt(jitter_sum_ / static_cast<double>(jitter_samples_)) : 0.0;
        a.least_travel = travel_.empty() ? 0.0 : *std::min_element(travel_.begin(), travel_.end());
        if (spec_.metric == Metric::slide_error) a.slide_error = slide_error(bodies, (last_frame_ + 1) * dt_);
        if (arriving_ && restitution_ > 0.0 && *arriving_ != 0.0)
            a.restitution_error = std::abs(leaving_ + restitution_ * *arriving_) / std::abs(restitution_ * *arriving_);
        if (scene_.world.gravity.isZero()) {
            const double scale = momentum_scale(scene_.bodies);
            if (scale > 0.0)
                a.momentum_error = (linear_momentum(bodies) - linear_momentum(scene_.bodies)).norm() / scale;
        }
    } else {
        a.end_penetration = a.end_kinetic_energy = a.jitter = nan;
    }

    switch (spec_.metric) {
        // With a settle time, from the state then (from the start in a run that ended before it).
        case Metric::top_drift:
            a.error = a.settled_drift.value_or(a.top_drift_most);
            break;
        case Metric::any_drift:
            a.error = a.settled_drift.value_or(a.any_drift_most);
            break;
        case Metric::top_sideways_drift:
            a.error = a.settled_drift.value_or(a.top_sideways_drift_most);
            break;
        case Metric::recovery_time:
            a.error = a.recovery_time.value_or(nan);
            break;
        case Metric::slide_error:
            a.error = a.slide_error.value_or(nan);
            break;
        case Metric::end_penetration:
            a.error = a.end_penetration;
            break;
        case Metric::jitter:
            a.error = a.jitter;
            break;
        case Metric::energy_gain:
            a.error = a.energy_gain;
            break;
        case Metric::restitution_error:
            a.error = a.restitution_error.value_or(nan);
            break;
        case Metric::momentum_error:
            a.error = a.momentum_error.value_or(nan);
            break;
    }
    const double end_time = (last_frame_ + 1) * dt_;
    if (a.nan_time) {
        a.error = nan;
        a.failure = "NaN";
        a.failure_time = a.nan_time;
    } else if (a.collapse_time) {
        a.failure = "collapsed";
        a.failure_time = a.collapse_time;
    } else if (spec_.metric == Metric::end_penetration && a.end_penetration > spec_.failure_threshold) {
        a.failure = "left deep";
        a.failure_time = end_time;
    } else if (spec_.metric == Metric::jitter && a.jitter > spec_.failure_threshold) {
        a.failure = "jitters";
        a.failure_time = end_time;
    } else if (spec_.metric == Metric::energy_gain && energy_gain_time_) {
        a.failure = "gained energy";
        a.failure_time = energy_gain_time_;
    } else if (spec_.metric == Metric::energy_gain && a.end_kinetic_energy > 0.01 * kinetic_before_contact_) {
        // It must come to rest: at the end at most 1 % of the kinetic energy it struck with.
        a.failure = "not at rest";
        a.failure_time = end_time;
    } else if (spec_.metric == Metric::recovery_time && !a.recovery_time) {
        a.failure = "stays overlapped";
        a.failure_time = end_time;
    } else if (explode_time_) {
        a.failure = "exploded";  // a body left the separated pile faster than the scene allows
        a.failure_time = explode_time_;
    } else if ((spec_.metric == Metric::recovery_time || spec_.metric == Metric::slide_error) &&
               a.error > spec_.failure_threshold) {
        a.failure = spec_.metric == Metric::recovery_time ? "separates late" : "slides wrong";
        a.failure_time = end_time;
    } else if (spec_.min_travel && a.least_travel < *spec_.min_travel) {
        a.failure = "stalled";  // a body that should have moved (a domino that should have fallen) did not
        a.failure_time = end_time;
    } else if (std::isnan(a.error)) {
        a.failure = "no " + std::string(metric_meaning(spec_.metric));  // e.g. the ball never bounced
        a.failure_time = end_time;
    }
    a.holds = a.failure.empty();
    a.meets_target = a.holds && a.error <= spec_.target;
    return a;
}

}  // namespace impulse::bench
