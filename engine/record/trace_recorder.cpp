#include "record/trace_recorder.hpp"

namespace impulse {

void TraceRecorder::begin_frame(int frame, std::span<const RigidBody> bodies, std::span<const MassProperties> mass) {
    recording_ = trace_.recording.records_frame(frame);
    if (!recording_) return;
    FrameRecord& record = trace_.frames.emplace_back();
    record.frame = frame;
    record.phase_order = trace_.scene.settings.phase_order;
    for (const RigidBody& body : bodies) record.bodies_before.push_back(state_of(body));
    for (const MassProperties& m : mass) record.inverse_inertia_world.push_back(m.inverse_inertia_world);
}

void TraceRecorder::contacts_prepared(std::span<const PreparedContact> contacts) {
    if (!recording_) return;
    trace_.frames.back().contact_count = static_cast<int>(contacts.size());
    for (const PreparedContact& c : contacts)
        if (trace_.recording.records_contact(c.derivation.contact))
            trace_.frames.back().contacts.push_back(c.derivation);
}

template <typename Update>
std::vector<Update> TraceRecorder::kept_updates(const std::vector<Update>& updates) const {
    std::vector<Update> kept;
    for (const Update& u : updates)
        if (trace_.recording.records_contact(u.contact)) kept.push_back(u);
    return kept;
}

void TraceRecorder::position_iteration(const PositionIteration& iteration) {
    if (!recording_) return;
    PositionIteration& kept = trace_.frames.back().position.iterations.emplace_back(iteration);
    if (!trace_.recording.records_contact(iteration.contact)) kept.resolution.reset();
    if (trace_.recording.contacts) kept.updates = kept_updates(iteration.updates);
}

void TraceRecorder::velocity_iteration(const VelocityIteration& iteration) {
    if (!recording_) return;
    VelocityIteration& kept = trace_.frames.back().velocity.iterations.emplace_back(iteration);
    if (!trace_.recording.records_contact(iteration.contact)) kept.resolution.reset();
    if (trace_.recording.contacts) kept.updates = kept_updates(iteration.updates);
}

void TraceRecorder::end_phase(Phase phase, const PhaseOutcome& outcome) {
    if (!recording_) return;
    FrameRecord& frame = trace_.frames.back();
    (phase == Phase::position ? frame.position.outcome : frame.velocity.outcome) = outcome;
}

void TraceRecorder::end_frame(std::span<const RigidBody> bodies) {
    if (!recording_) return;
    for (const RigidBody& body : bodies) trace_.frames.back().bodies_after.push_back(state_of(body));
    recording_ = false;
}

}  // namespace impulse
