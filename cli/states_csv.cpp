#include "cli/states_csv.hpp"

#include "explain/format.hpp"
#include "formats/csv.hpp"

#include <cmath>
#include <cstdio>

namespace impulse::cli {

namespace {

// The rows are handed to the output in pieces of about this size.
constexpr std::size_t piece_bytes = 1 << 20;

// One CSV row per body.
void append_rows(std::string& csv, int frame, double time, const Scene& scene, const std::vector<RigidBody>& bodies) {
    char line[512];
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const RigidBody& b = bodies[i];
        std::snprintf(line, sizeof line, "%d,%.17g,%zu,", frame, time, i);
        csv += line;
        csv += formats::csv_field(scene.body_names[i]);
        std::snprintf(line, sizeof line,
                      ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                      b.position.x(), b.position.y(), b.position.z(), b.orientation.w(), b.orientation.x(),
                      b.orientation.y(), b.orientation.z(), b.velocity.x(), b.velocity.y(), b.velocity.z(),
                      b.angular_velocity.x(), b.angular_velocity.y(), b.angular_velocity.z(), kinetic_energy(b));
        csv += line;
    }
}

}  // namespace

StatesCsv::StatesCsv(StreamedOutput* output, std::optional<double> max_states_mb, const Scene& scene)
    : output_(output), budget_(max_states_mb.value_or(default_max_states_mb) * 1e6), scene_(scene) {
    if (!output_) return;
    rows_ = "frame,time,body,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,kinetic_energy\n";
    written_ = rows_.size();
}

void StatesCsv::add(int frame, double time, const std::vector<RigidBody>& bodies) {
    if (!output_ || stopped_at_) return;
    const std::size_t before = rows_.size();
    append_rows(rows_, frame, time, scene_, bodies);
    last_frame_bytes_ = rows_.size() - before;
    if (static_cast<double>(written_ + last_frame_bytes_) > budget_) {
        rows_.resize(before);  // the frame that does not fit is not written: the CSV ends with a whole frame
        stopped_at_ = frame;
        return;
    }
    written_ += last_frame_bytes_;
    if (rows_.size() >= piece_bytes) flush();
}

void StatesCsv::flush() {
    if (!output_) return;
    output_->append(rows_);
    rows_.clear();
}

std::string StatesCsv::fit_note(int frames) {
    if (!output_ || fit_said_ || last_frame_bytes_ == 0) return {};
    fit_said_ = true;
    // Every frame's rows are nearly the same size: the numbers' digits vary, not their count.
    const double whole_run = static_cast<double>(written_) + static_cast<double>(last_frame_bytes_) * (frames - 1);
    if (whole_run <= budget_) return {};
    return "impulse-lab: note: --states: at " + explain::number(static_cast<double>(last_frame_bytes_) / 1e6) +
           " MB a frame, the whole run would take about " + explain::number(std::round(whole_run / 1e6)) +
           " MB: the states keep the first frames that fit in --max-states-mb " + explain::number(budget_ / 1e6) +
           " and the rest run without them (a note at the end says where they stopped)";
}

std::string StatesCsv::stopped_note() const {
    if (!stopped_at_) return {};
    return "impulse-lab: note: the states reached --max-states-mb " + explain::number(budget_ / 1e6) + " at frame " +
           std::to_string(*stopped_at_) + " and end with frame " + std::to_string(*stopped_at_ - 1) +
           "; the frames after it ran without them (raise --max-states-mb)";
}

}  // namespace impulse::cli
