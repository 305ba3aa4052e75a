#pragma once
// A trace: everything one run of the resolver computed, as plain structs. The JSON recorder fills it, the
// trace file stores it (formats/trace_json), and the inspector, lessons and `diff` read it back.

#include "record/contact_record.hpp"
#include "record/iteration_records.hpp"
#include "scene/scene.hpp"

#include <climits>
#include <optional>
#include <vector>

namespace impulse {

// The trace format these structs are written in (docs/trace-format.md): 2 since the words were renamed to the
// chapter's (formats/trace_format1 reads format 1).
inline constexpr int trace_format_version = 2;

// The part of a body's state that resolution changes.
struct BodyState {
    Vec3 position;
    Quat orientation;
    Vec3 velocity;
    Vec3 angular_velocity;

    bool operator==(const BodyState&) const = default;
};

template <typename Iteration>
struct PhaseLog {
    PhaseOutcome outcome;
    std::vector<Iteration> iterations;

    bool operator==(const PhaseLog&) const = default;
};

struct FrameRecord {
    int frame = 0;
    std::vector<BodyState> bodies_before;
    std::vector<Mat3> inverse_inertia_world;   // per body, as the whole frame uses it
    int contact_count = 0;                     // contacts resolved this frame, recorded or not; indices count from 0
    std::vector<ContactPreparation> contacts;  // steps 1-5 of each recorded contact
    PhaseOrder phase_order = PhaseOrder::positions_first;
    PhaseLog<PositionIteration> position;
    PhaseLog<VelocityIteration> velocity;
    std::vector<BodyState> bodies_after;

    bool operator==(const FrameRecord&) const = default;
};

// Which part of a run is recorded, so large scenes stay small.
struct TraceFilter {
    int first_frame = 0;
    int last_frame = INT_MAX;
    std::optional<std::vector<int>> contacts;  // absent = every contact

    bool records_frame(int frame) const { return frame >= first_frame && frame <= last_frame; }
    bool records_contact(int contact) const;

    bool operator==(const TraceFilter&) const = default;
};

// Ends `filter` before `frame`: last_frame = frame - 1, or, when that leaves nothing (frame 0), the empty
// range first_frame = 1, last_frame = 0 (frame numbers are never negative in a trace).
inline void end_recording_before(TraceFilter& filter, int frame) {
    filter.last_frame = std::min(filter.last_frame, frame - 1);
    if (filter.last_frame < 0) filter.first_frame = 1, filter.last_frame = 0;
}

struct Trace {
    int version = trace_format_version;  // the format the file was written in (a reader upgrades older ones)
    Scene scene;                         // the bodies and contacts as loaded, with the settings that ran
    TraceFilter recording;
    std::vector<FrameRecord> frames;

    bool operator==(const Trace&) const = default;
};

// Ends a trace before `frame`, the one that broke a run: drops that frame's record if it was recorded (its bodies
// after would be NaN, which JSON cannot hold) and ends the filter before it, so the trace stays valid.
inline void end_trace_before(Trace& trace, int frame) {
    if (!trace.frames.empty() && trace.frames.back().frame == frame) trace.frames.pop_back();
    end_recording_before(trace.recording, frame);
}

BodyState state_of(const RigidBody& body);

}  // namespace impulse
