#pragma once
// `run --states`: every body's state per frame as CSV, written as the frames are made (a piece at a time into
// the output's staged file, so memory does not grow with the run) and bounded on disk by --max-states-mb: a frame
// whose rows would pass the bound is not written, nor any after it, and the CSV ends with the last whole frame.
// Unbounded, 100000 frames of grid_1000 would have written about 23 GB.

#include "cli/outputs.hpp"
#include "scene/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace impulse::cli {

inline constexpr double default_max_states_mb = 1000.0;

class StatesCsv {
public:
    // `output` may be null (no --states): then every call does nothing.
    StatesCsv(StreamedOutput* output, std::optional<double> max_states_mb, const Scene& scene);

    // The rows of one frame (-1: the scene as given, at time 0), if they fit under the bound.
    void add(int frame, double time, const std::vector<RigidBody>& bodies);
    // The rows still held, written to the output.
    void flush();

    // As soon as the first frame shows the whole run will not fit: a note saying how many frames will. Empty
    // otherwise, and after the first time it was said.
    std::string fit_note(int frames);
    // The frame the bound stopped the states at, if it did.
    std::optional<int> stopped_at() const { return stopped_at_; }
    std::string stopped_note() const;

private:
    StreamedOutput* output_;
    double budget_;  // bytes
    const Scene& scene_;
    std::string rows_;
    std::size_t written_ = 0;  // bytes, those in rows_ included
    std::size_t last_frame_bytes_ = 0;
    std::optional<int> stopped_at_;
    bool fit_said_ = false;
};

}  // namespace impulse::cli
