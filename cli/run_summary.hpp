#pragma once
// The summary `run` prints of the frames it ran (all of them, or those done before a Ctrl-C or a broken frame):
// its head, up to 20 frames evenly spread and always the last, the time per stage, how often each phase ran out of
// iterations, the deepest penetration and the drift of the body that started highest. It is gathered frame by
// frame in memory that does not grow with the run: `--frames 10000000` kept every frame's report (gigabytes).

#include "scene/scene.hpp"
#include "world/world.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace impulse::cli {

class RunSummary {
public:
    RunSummary(std::string scene_name, int frames_asked, double dt, const Scene& scene);

    // One frame done; `bodies` are the bodies after it.
    void add(const StepReport& report, const std::vector<RigidBody>& bodies);
    int frames() const { return frames_; }

    void write(std::ostream& out, const Scene& scene, const std::vector<RigidBody>& bodies) const;

private:
    struct Row {
        int frame = 0;
        int contacts = 0;
        double deepest_penetration = 0.0;  // m
        double kinetic_energy = 0.0;       // J
        double seconds = 0.0;              // the frame's four stages
    };
    std::vector<Row> rows_to_show() const;

    std::string scene_name_;
    int frames_asked_ = 0;
    double dt_ = 0.0;
    int frames_ = 0;
    StageTimes total_;
    double deepest_ = 0.0;
    int deepest_frame_ = 0;
    int position_limited_ = 0, velocity_limited_ = 0;
    std::size_t top_ = 0;  // the body that started highest
    Vec3 top_start_ = Vec3::Zero();
    Vec3 top_end_ = Vec3::Zero();  // after the last frame done (not one a signal cut short)
    double top_drift_most_ = 0.0;
    int top_drift_frame_ = 0;
    // The rows to show: every `asked_every_`th frame, as a run that does all its frames shows them; and, for a run
    // stopped early, every `stride_`th (a power of two, doubled whenever more than 64 are kept).
    int asked_every_ = 1;
    std::vector<Row> asked_rows_;
    int stride_ = 1;
    std::vector<Row> spread_rows_;
    Row last_;
};

}  // namespace impulse::cli
