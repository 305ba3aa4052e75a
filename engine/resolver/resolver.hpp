#pragma once
// The resolver: prepare every contact (steps 1-5), then run the position and velocity phases in the order
// the settings give (the book: positions first). Stateless: all it needs travels in its arguments.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "memory/contact_memory.hpp"
#include "methods/method.hpp"
#include "record/last_touch.hpp"
#include "record/recorder.hpp"
#include "settings/settings.hpp"

#include <atomic>
#include <chrono>
#include <memory_resource>
#include <span>
#include <vector>

namespace impulse {

struct ResolutionSummary {
    PhaseOutcome position;
    PhaseOutcome velocity;
    bool cut_short = false;  // `stop` was set and a method stopped for it: the frame is unfinished

    bool operator==(const ResolutionSummary&) const = default;
};

// Where a frame's time goes, stage by stage: the world's step integrates, detects (broad phase, then the pair
// tests of the narrow phase) and resolves (prepare, then the position and velocity phases). The same words are
// the profile's rows (`impulse-lab run`, impulse-bench-world) and, for the last three, the trace's.
struct StageTimes {
    double integrate = 0.0;     // s
    double broad_phase = 0.0;   // s
    double narrow_phase = 0.0;  // s: the pair tests
    double prepare = 0.0;       // s: steps 1-5 of every contact
    double position = 0.0;      // s: the position phase
    double velocity = 0.0;      // s: the velocity phase (a method that owns the whole step: all of it)

    double resolve() const { return prepare + position + velocity; }
    double total() const { return integrate + broad_phase + narrow_phase + resolve(); }
};

// The seconds since `start`, as the stages are timed.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What else a frame's resolution may be given: everything has a default.
struct FrameSetup {
    int frame = 0;                    // the frame's number, for the recorder
    ContactMemory* memory = nullptr;  // warm-starting solvers' impulses from frame to frame (none: start cold)
    Forces forces{};                  // what a method that owns the whole step integrates the bodies under
    LastTouch* touch = nullptr;       // stamped with the contact of every visit (world/non_finite_check.hpp)
    StageTimes* times = nullptr;      // given: prepare, position and velocity are added to it
    // The frame's buffers (a world's FrameArena; the heap by default).
    std::pmr::memory_resource* scratch = std::pmr::new_delete_resource();
    const std::atomic<bool>* stop = nullptr;  // set from outside to cut the frame short (FrameContext::stop)
};

// Resolves `contacts` between `bodies` once (one frame), changing the bodies' positions, orientations and
// velocities: prepares them (steps 1-5), then runs the position and velocity methods the settings name
// (methods/method_table.hpp). Contacts must name bodies inside the list, body 0 and body 1 different, unit
// normals. A velocity method that owns the whole step integrates the bodies itself under setup.forces (none:
// they move by their velocities over settings.duration while it resolves the contacts). setup.stop, when set
// while it runs, cuts the frame short (FrameContext::stop): the phase after is not run.
ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, const FrameSetup& setup = {});

// The same with nobody listening.
ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings);

}  // namespace impulse
