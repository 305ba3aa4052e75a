#pragma once
// The recorder that keeps everything: per frame the bodies before and after, steps 1-5 of each contact,
// and each iteration of both phases with its derivation values and its updates to other contacts. A frame
// range and a contact set keep large scenes small: an iteration that resolves a contact outside the set is
// kept as a line (which contact, its value) without its derivation, and only updates to recorded contacts
// are kept, so the status of every recorded contact can still be replayed exactly.

#include "record/recorder.hpp"
#include "record/trace.hpp"

namespace impulse {

class TraceRecorder final : public Recorder {
public:
    // Appends frames to `trace`, whose header (scene, settings, filter) the caller fills.
    explicit TraceRecorder(Trace& trace) : trace_(trace) {}

    bool wants_updates() const override { return recording_; }
    void begin_frame(int frame, std::span<const RigidBody> bodies, std::span<const MassProperties> mass) override;
    void contacts_prepared(std::span<const PreparedContact> contacts) override;
    void position_iteration(const PositionIteration& iteration) override;
    void velocity_iteration(const VelocityIteration& iteration) override;
    void end_phase(Phase phase, const PhaseOutcome& outcome) override;
    void end_frame(std::span<const RigidBody> bodies) override;

private:
    template <typename Update>
    std::vector<Update> kept_updates(const std::vector<Update>& updates) const;

    Trace& trace_;
    bool recording_ = false;
};

}  // namespace impulse
