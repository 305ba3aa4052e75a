#pragma once
// The recorder that keeps everything: per frame the bodies before and after, steps 1-5 of each contact,
// and each iteration of both phases with its derivation values and its updates to other contacts. A frame
// range and a contact set keep large scenes small: an iteration that resolves a contact outside the set is
// kept as a line (which contact, its value) without its derivation, and only updates to recorded contacts
// are kept, so the status of every recorded contact can still be replayed exactly.
//
// A byte budget keeps a long run from filling the memory and the disk: the recorder estimates the size the
// trace will have as JSON while it records (a fixed size per record, no formatting), and once the estimate
// passes the budget it drops the frame in progress, ends the recording filter at the frame before
// (last_frame), and records nothing more. The trace stays valid; the run itself goes on.

#include "record/recorder.hpp"
#include "record/trace.hpp"
#include "record/visit_records.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace impulse {

class TraceRecorder final : public Recorder {
public:
    // Appends frames to `trace`, whose header (scene, settings, filter) the caller fills.
    explicit TraceRecorder(Trace& trace, std::size_t byte_budget = SIZE_MAX) : trace_(trace), budget_(byte_budget) {}

    void begin_frame(int frame, std::span<const RigidBody> bodies, std::span<const MassProperties> mass) override;
    bool keeps_frame() const override { return recording_; }
    void contacts_prepared(const PreparedFrame& frame) override;
    void position_visit(const PositionVisit& visit) override;
    void velocity_visit(const VelocityVisit& visit) override;
    void body_visit(const SweepPlace& place, const BodyVisitRecord& visit) override;
    void dual_visit(const SweepPlace& place, const DualUpdateRecord& update) override;
    void end_phase(Phase phase, const PhaseOutcome& outcome) override;
    void end_frame(std::span<const RigidBody> bodies) override;

    // The estimated size of the trace as written (JSON, formatted), in bytes, from per-record sizes fitted to
    // real traces (trace_recorder.cpp says how); its worst-case error has not been measured yet.
    std::size_t estimated_bytes() const { return estimated_; }
    // The frame at which the budget ran out (not kept), if it did.
    std::optional<int> stopped_at() const { return stopped_at_; }

private:
    // Adds a record's estimated size; past the budget, drops the frame in progress and stops recording.
    void count(std::size_t bytes);

    // Drops what `records` holds of the contacts the recording leaves out (updates, a body visit's contacts).
    void keep_recorded(auto& records) const {
        std::erase_if(records, [this](const auto& r) { return !trace_.recording.records_contact(r.contact); });
    }

    Trace& trace_;
    VisitRecords visits_;  // the frame's iterations, from the methods' visits
    bool recording_ = false;
    std::size_t budget_;
    std::size_t estimated_ = 0;
    std::optional<int> stopped_at_;
};

}  // namespace impulse
