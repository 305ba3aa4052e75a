#include "cli/run_summary.hpp"

#include "explain/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::cli {

namespace {

// A number with `decimals` after the point, or in exponent form once that would be long (a run of gravity
// −1e308 has depths of 300 digits: a fixed-width row cut them, and its line break with them).
std::string fixed(double v, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, std::abs(v) < 1e12 ? "%.*f" : "%.*g", std::abs(v) < 1e12 ? decimals : 4, v);
    return text;
}

// Up to 20 rows, evenly spread, for `frames` frames.
int every_for(int frames) {
    return std::max(1, (frames + 19) / 20);
}

}  // namespace

RunSummary::RunSummary(std::string scene_name, int frames_asked, double dt, const Scene& scene)
    : scene_name_(std::move(scene_name)),
      frames_asked_(frames_asked),
      dt_(dt),
      top_(highest_body(scene)),
      top_start_(scene.bodies[highest_body(scene)].position),
      top_end_(top_start_),
      asked_every_(every_for(frames_asked)) {}

void RunSummary::add(const StepReport& r, const std::vector<RigidBody>& bodies) {
    const auto ran_out = [](StopReason stop) {
        return stop == StopReason::iteration_limit || stop == StopReason::sweeps_complete ? 1 : 0;
    };
    ++frames_;
    position_limited_ += ran_out(r.resolution.position.stop);
    velocity_limited_ += ran_out(r.resolution.velocity.stop);
    total_.integrate += r.times.integrate;
    total_.broad_phase += r.times.broad_phase;
    total_.narrow_phase += r.times.narrow_phase;
    total_.prepare += r.times.prepare;
    total_.position += r.times.position;
    total_.velocity += r.times.velocity;
    if (r.deepest_penetration > deepest_) deepest_ = r.deepest_penetration, deepest_frame_ = r.frame;
    top_end_ = bodies[top_].position;
    const double drift = (top_end_ - top_start_).norm();
    if (drift > top_drift_most_) top_drift_most_ = drift, top_drift_frame_ = r.frame;

    last_ = {r.frame, r.contacts, r.deepest_penetration, r.kinetic_energy, r.times.total()};
    if (r.frame % asked_every_ == 0) asked_rows_.push_back(last_);
    if (r.frame % stride_ == 0) spread_rows_.push_back(last_);
    if (spread_rows_.size() > 64) {
        stride_ *= 2;
        std::erase_if(spread_rows_, [this](const Row& row) { return row.frame % stride_ != 0; });
    }
}

std::vector<RunSummary::Row> RunSummary::rows_to_show() const {
    std::vector<Row> rows;
    if (frames_ == frames_asked_) {
        rows = asked_rows_;
    } else {
        // Stopped early: every `every`th frame done, rounded up to a multiple of the stride kept.
        const int every = (every_for(frames_) + stride_ - 1) / stride_ * stride_;
        for (const Row& row : spread_rows_)
            if (row.frame % every == 0) rows.push_back(row);
    }
    if (frames_ > 0 && (rows.empty() || rows.back().frame != last_.frame)) rows.push_back(last_);
    return rows;
}

void RunSummary::write(std::ostream& out, const Scene& scene, const std::vector<RigidBody>& bodies) const {
    out << scene_name_ << ": " << bodies.size() << (bodies.size() == 1 ? " body" : " bodies")
        << (scene.ground ? ", ground" : "") << ", "
        << (frames_ == frames_asked_ ? std::to_string(frames_)
                                     : std::to_string(frames_) + " of " + std::to_string(frames_asked_))
        << " frames of " << explain::number(dt_) << " s (" << explain::number(frames_ * dt_) << " s), preset "
        << scene.settings.preset << "\n";
    out << "  frame    time s  contacts  deepest mm   kinetic J  ms/frame\n";
    for (const Row& r : rows_to_show()) {
        char line[160];
        std::snprintf(line, sizeof line, "  %5d  %8s  %8d  %10s  %10.4g  %8s", r.frame,
                      fixed((r.frame + 1) * dt_, 3).c_str(), r.contacts, fixed(r.deepest_penetration * 1e3, 3).c_str(),
                      r.kinetic_energy, fixed(r.seconds * 1e3, 3).c_str());
        out << line << '\n';
    }
    const double n = std::max(1, frames_);
    const auto ms = [n](double seconds) { return fixed(seconds / n * 1e3, 3) + " ms"; };
    out << "  per frame: integrate " << ms(total_.integrate) << ", broad phase " << ms(total_.broad_phase)
        << ", narrow phase " << ms(total_.narrow_phase) << ", prepare " << ms(total_.prepare) << ", position "
        << ms(total_.position) << ", velocity " << ms(total_.velocity) << "\n";
    out << "  iteration limit (or every sweep) used in " << position_limited_ << " of " << frames_
        << " frames (positions) and " << velocity_limited_ << " (velocities)\n";
    out << "  deepest penetration " << fixed(deepest_ * 1e3, 3) << " mm (frame " << deepest_frame_ << "); "
        << scene.body_names[top_] << " (highest at the start) ends " << fixed((top_end_ - top_start_).norm() * 1e3, 3)
        << " mm from where it started, at most " << fixed(top_drift_most_ * 1e3, 3) << " mm (frame " << top_drift_frame_
        << ")\n";
}

}  // namespace impulse::cli
