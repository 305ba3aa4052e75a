#include "record/trace_recorder.hpp"

namespace impulse {

namespace {

// Bytes each record takes in the formatted JSON of a trace: a least-squares fit of the record counts to the
// real sizes of 20-frame traces of 8 shipped scenes under all 6 presets. Numbers print with up to 17 digits,
// so these are averages, not bounds; the line size is a guess (no calibration trace filtered contacts).
constexpr std::size_t header_bytes = 2500;      // the scene and settings, plus per body:
constexpr std::size_t header_body_bytes = 500;  // a body in the header's scene
constexpr std::size_t frame_bytes = 1050;       // a frame's own keys and phase outcomes
constexpr std::size_t frame_body_bytes = 180;   // a body before and after, with its world inverse inertia
constexpr std::size_t contact_bytes = 2300;     // steps 1-5 of a contact
constexpr std::size_t position_iteration_bytes = 600;
constexpr std::size_t velocity_iteration_bytes = 1850;
constexpr std::size_t iteration_line_bytes = 250;   // an iteration on a contact outside the recorded set,
constexpr std::size_t sweep_place_bytes = 130;      // plus, on such a line, where in the sweeps it is
constexpr std::size_t accumulated_bytes = 300;      // and its accumulated impulse (counted from formatted traces)
constexpr std::size_t position_update_bytes = 300;  // one update to a contact sharing a body
constexpr std::size_t velocity_update_bytes = 570;
// AVBD's, beside the line and sweep sizes above: fitted to the iterations of a 30-frame trace of mass_ratio_100 (a
// body visit 2066 bytes + 344 per contact it gathered, a dual update 629).
constexpr std::size_t body_visit_bytes = 1690;
constexpr std::size_t gathered_bytes = 345;
constexpr std::size_t dual_update_bytes = 250;

}  // namespace

void TraceRecorder::count(std::size_t bytes) {
    if (estimated_ == 0) estimated_ = header_bytes + header_body_bytes * trace_.scene.bodies.size();
    estimated_ += bytes;
    if (estimated_ <= budget_) return;
    // Over budget: the frame in progress is dropped whole, so the trace ends with the last complete frame.
    stopped_at_ = trace_.frames.back().frame;
    trace_.frames.pop_back();
    end_recording_before(trace_.recording, *stopped_at_);
    recording_ = false;
}

void TraceRecorder::begin_frame(int frame, std::span<const RigidBody> bodies, std::span<const MassProperties> mass) {
    recording_ = trace_.recording.records_frame(frame);
    if (!recording_) return;
    FrameRecord& record = trace_.frames.emplace_back();
    record.frame = frame;
    record.phase_order = trace_.scene.settings.phase_order;
    for (const RigidBody& body : bodies) record.bodies_before.push_back(state_of(body));
    for (const MassProperties& m : mass) record.inverse_inertia_world.push_back(m.inverse_inertia_world);
    count(frame_bytes + frame_body_bytes * bodies.size());
}

void TraceRecorder::contacts_prepared(const PreparedFrame& frame) {
    if (!recording_) return;
    FrameRecord& record = trace_.frames.back();
    record.contact_count = static_cast<int>(frame.detected.size());
    for (std::size_t i = 0; i < frame.detected.size(); ++i)
        if (trace_.recording.records_contact(static_cast<int>(i)))
            record.contacts.push_back(
                contact_preparation(static_cast<int>(i), frame.detected[i], frame.bodies, frame.mass, frame.settings));
    visits_.begin(frame);
    count(contact_bytes * record.contacts.size());
}

void TraceRecorder::position_visit(const PositionVisit& visit) {
    if (!recording_) return;
    std::vector<PositionIteration>& iterations = trace_.frames.back().position.iterations;
    PositionIteration& kept = iterations.emplace_back(visits_.position_iteration(visit));
    kept.iteration = static_cast<int>(iterations.size()) - 1;  // numbered from 0 in each phase
    if (!trace_.recording.records_contact(kept.contact)) kept.resolution.reset();
    if (trace_.recording.contacts) keep_recorded(kept.updates);
    count((kept.resolution ? position_iteration_bytes : iteration_line_bytes) +
          position_update_bytes * kept.updates.size());
}

void TraceRecorder::velocity_visit(const VelocityVisit& visit) {
    if (!recording_) return;
    std::vector<VelocityIteration>& iterations = trace_.frames.back().velocity.iterations;
    VelocityIteration& kept = iterations.emplace_back(visits_.velocity_iteration(visit));
    kept.iteration = static_cast<int>(iterations.size()) - 1;  // AVBD's body visits and dual updates count too
    if (!trace_.recording.records_contact(kept.contact)) kept.resolution.reset();
    if (trace_.recording.contacts) keep_recorded(kept.updates);
    // A full record's size is an average over the methods; a line is mostly its sweep fields, when it has them.
    const std::size_t line_bytes =
        iteration_line_bytes + (kept.sweep ? sweep_place_bytes : 0) + (kept.accumulated ? accumulated_bytes : 0);
    count((kept.resolution ? velocity_iteration_bytes : line_bytes) + velocity_update_bytes * kept.updates.size());
}

// With a contact filter, a body visit keeps the gathered contacts the recording keeps, and a dual update of a contact
// it leaves out is kept as a line (which contact, where in the sweeps).
void TraceRecorder::body_visit(const SweepPlace& place, const BodyVisitRecord& visit) {
    if (!recording_) return;
    std::vector<VelocityIteration>& iterations = trace_.frames.back().velocity.iterations;
    VelocityIteration& kept = iterations.emplace_back();
    kept.iteration = static_cast<int>(iterations.size()) - 1;
    // Every solved body has a contact (methods/avbd.cpp solves no other), so its first is its iteration's contact.
    kept.contact = visit.gathered.empty() ? 0 : visit.gathered.front().contact;
    kept.sweep = place;
    std::vector<AvbdContactRows>& gathered = kept.body_visit.emplace(visit).gathered;
    if (trace_.recording.contacts) keep_recorded(gathered);
    count(iteration_line_bytes + sweep_place_bytes + body_visit_bytes + gathered_bytes * gathered.size());
}

void TraceRecorder::dual_visit(const SweepPlace& place, const DualUpdateRecord& update) {
    if (!recording_) return;
    std::vector<VelocityIteration>& iterations = trace_.frames.back().velocity.iterations;
    VelocityIteration& kept = iterations.emplace_back();
    kept.iteration = static_cast<int>(iterations.size()) - 1;
    kept.contact = update.rows.contact;
    kept.sweep = place;
    if (trace_.recording.records_contact(update.rows.contact)) kept.dual_update = update;
    count(iteration_line_bytes + sweep_place_bytes + (kept.dual_update ? dual_update_bytes : 0));
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
