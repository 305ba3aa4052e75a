#include "model/runs.hpp"

#include "io/input_error.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "world/world.hpp"

namespace impulse::inspect {

Trace resolve_once(const Scene& scene, const TraceFilter& recording, TraceBudget budget) {
    Trace trace;
    trace.scene = scene;
    trace.recording = recording;
    const std::vector<Contact> contacts =
        scene.contacts.empty() ? detect_contacts(scene, scene.bodies).contacts : scene.contacts;
    if (recording.contacts)
        for (int contact : *recording.contacts)
            if (contact >= static_cast<int>(contacts.size()))
                throw io::InputError("--record", "there is no contact " + std::to_string(contact) +
                                                     " (this frame has " + std::to_string(contacts.size()) +
                                                     (contacts.size() == 1 ? " contact" : " contacts") +
                                                     ", numbered from 0)");
    std::vector<RigidBody> bodies = scene.bodies;
    TraceRecorder recorder(trace, budget.bytes);
    resolve_contacts(bodies, contacts, scene.settings, recorder);
    if (budget.stopped_at) *budget.stopped_at = recorder.stopped_at();
    return trace;
}

Trace run_frames(const Scene& scene, const TraceFilter& recording, int frames, TraceBudget budget) {
    Trace trace;
    trace.scene = scene;
    trace.scene.contacts.clear();  // a run detects its own
    trace.scene.world.frames = frames;
    trace.recording = recording;
    std::vector<RigidBody> bodies = scene.bodies;
    TraceRecorder recorder(trace, budget.bytes);
    ContactMemory memory;
    for (int frame = 0; frame < frames; ++frame) step(trace.scene, bodies, recorder, frame, &memory);
    if (budget.stopped_at) *budget.stopped_at = recorder.stopped_at();
    return trace;
}

}  // namespace impulse::inspect
