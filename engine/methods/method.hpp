#pragma once
// One signature for every resolution method, as solver2d gives every solver one (s2Solve_X(world, context)):
// a method receives the frame (its bodies, its contacts prepared by steps 1-5, the settings, the forces, the
// recorder and the contact memory), does its work, stamps every visit's contact (FrameContext::touched),
// reports every visit to the recorder when it keeps the frame (record/visits.hpp) and says how the phase ended (the
// resolver tells the recorder: recorder.end_phase). Each method is one file in engine/methods/ defining one
// MethodFunction, declared beside its row of engine/methods/method_table.hpp, which maps each settings value to its
// function, its scope and the settings it reads. Nothing else names a method: adding one is its file, its
// enumerator in settings/settings.hpp, its declaration and row in the table, and its section in docs/methods.md.

#include "body/integrate.hpp"
#include "body/rigid_body.hpp"
#include "memory/contact_memory.hpp"
#include "preparation/prepared_contact.hpp"
#include "record/last_touch.hpp"
#include "record/recorder.hpp"
#include "settings/settings.hpp"

#include <atomic>
#include <memory_resource>
#include <span>
#include <vector>

namespace impulse {

// What acts on the bodies between contacts: only a method that owns the whole step (it integrates the bodies
// itself) uses it. `impulse-lab resolve` gives none: the bodies move by their velocities alone.
struct Forces {
    Vec3 gravity = Vec3::Zero();
    Damping damping{};
};

// One frame as a method sees it.
struct FrameContext {
    std::vector<RigidBody>& bodies;  // changed in place
    // Steps 1-5, and the bookkeeping the book's loops update: contact i's at i (contacts[i].contact == i).
    std::span<PreparedContact> contacts;
    std::span<const MassProperties> mass;  // per body, as the contacts were prepared with
    const ResolverSettings& settings;
    Recorder& recorder;
    bool keeping;           // the recorder keeps this frame: report every visit (recorder.*_visit), else none
    LastTouch* touch;       // stamped with every visit's contact (may be null)
    ContactMemory* memory;  // warm-starting methods' impulses from last frame, replaced at the end (may be null)
    Forces forces;
    // Where a method takes its buffers for the frame (memory/frame_arena.hpp; the heap when no world keeps one).
    std::pmr::memory_resource* scratch = std::pmr::new_delete_resource();
    // Set from outside (a program's Ctrl-C) to cut the frame short; null when nothing can. Each method's loop
    // looks at it every stop_check_visits visits or once a sweep: one relaxed load, so a frame of 1e8 iterations
    // still stops within milliseconds. A method that stops for it sets `cut_short`; the frame is then unfinished.
    const std::atomic<bool>* stop = nullptr;
    bool cut_short = false;

    bool stop_requested() {
        if (stop && stop->load(std::memory_order_relaxed)) cut_short = true;
        return cut_short;
    }

    // A visit of `contact`, for LastTouch.
    void touched(int contact) const {
        if (touch) touch->touched(contact);
    }
};

// How often (in visits) an iteration loop looks at FrameContext::stop.
inline constexpr int stop_check_visits = 256;

using MethodFunction = PhaseOutcome (*)(FrameContext& frame);

}  // namespace impulse
