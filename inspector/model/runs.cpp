#include "model/runs.hpp"

#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "world/world.hpp"

namespace impulse::model {

namespace {

std::string contact_text(const Scene& scene, int contact, const std::array<int, 2>& bodies) {
    const auto name = [&scene](int body) {
        return body == world_body ? std::string(scene.ground ? "ground" : "world")
                                  : scene.body_names[static_cast<std::size_t>(body)];
    };
    return "contact " + std::to_string(contact) + ": " + name(bodies[0]) + " / " + name(bodies[1]);
}

}  // namespace

std::string broken_run_text(const Scene& scene, const BrokenRun& broken) {
    const NonFiniteBody& b = broken.body;
    return "frame " + std::to_string(broken.frame) + ": body \"" + scene.body_names[static_cast<std::size_t>(b.body)] +
           "\" has a non-finite " + b.quantity + " after resolution (" +
           (b.last_contact ? "last touched by " + contact_text(scene, *b.last_contact, b.last_contact_bodies)
                           : std::string("no contact touched it this frame")) +
           ")";
}

Trace resolve_once(const Scene& scene, const TraceFilter& recording, TraceBudget budget,
                   std::optional<BrokenRun>* broken) {
    Trace trace;
    trace.scene = scene;
    trace.recording = recording;
    std::vector<Contact> contacts;
    if (scene.contacts.empty()) {
        Detection detection = detect_contacts(scene, scene.bodies);
        if (detection.over_budget) throw formats::contact_budget_error(0);
        contacts = std::move(detection.contacts);
    } else {
        contacts = scene.contacts;
    }
    if (recording.contacts)
        for (int contact : *recording.contacts)
            if (contact >= static_cast<int>(contacts.size()))
                throw formats::InputError("--record", "there is no contact " + std::to_string(contact) +
                                                          " (this frame has " + std::to_string(contacts.size()) +
                                                          (contacts.size() == 1 ? " contact" : " contacts") +
                                                          ", numbered from 0)");
    std::vector<RigidBody> bodies = scene.bodies;
    TraceRecorder recorder(trace, budget.bytes);
    LastTouch touch(contacts);
    resolve_contacts(bodies, contacts, scene.settings, recorder, {.touch = &touch});
    if (budget.stopped_at) *budget.stopped_at = recorder.stopped_at();
    if (auto non_finite = first_non_finite(bodies, touch)) {
        end_trace_before(trace, 0);
        if (broken) *broken = BrokenRun{0, *non_finite};
    }
    return trace;
}

Trace run_frames(const Scene& scene, const TraceFilter& recording, int frames, TraceBudget budget,
                 std::optional<BrokenRun>* broken) {
    Trace trace;
    trace.scene = scene;
    trace.scene.contacts.clear();  // a run detects its own
    trace.scene.world.frames = frames;
    trace.recording = recording;
    World world(trace.scene);
    TraceRecorder recorder(trace, budget.bytes);
    for (int frame = 0; frame < frames; ++frame) {
        const StepReport report = world.step(recorder);
        if (report.over_contact_budget) throw formats::contact_budget_error(frame);
        if (report.non_finite) {
            end_trace_before(trace, frame);
            if (broken) *broken = BrokenRun{frame, *report.non_finite};
            break;
        }
        if (budget.stop_run && recorder.stopped_at()) {
            trace.scene.world.frames = *recorder.stopped_at();
            break;
        }
    }
    if (budget.stopped_at) *budget.stopped_at = recorder.stopped_at();
    return trace;
}

}  // namespace impulse::model
