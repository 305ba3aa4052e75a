#pragma once
// The resolver: prepare every contact (steps 1-5), then run the position and velocity phases in the order
// the settings give (the book: positions first). Stateless: all it needs travels in its arguments.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "memory/contact_memory.hpp"
#include "methods/method.hpp"
#include "record/recorder.hpp"
#include "settings/settings.hpp"

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

// Resolves `contacts` between `bodies` once (one frame), changing the bodies' positions, orientations and
// velocities: prepares them (steps 1-5), then runs the position and velocity methods the settings name
// (methods/method_table.hpp). Contacts must name bodies inside the list, body 0 and body 1 different, unit
// normals. `memory` carries warm-starting solvers' impulses from frame to frame (nothing = start cold every
// frame). A velocity method that owns the whole step integrates the bodies itself under `forces` (none: they
// move by their velocities over settings.duration while it resolves the contacts). The frame's buffers come
// from `scratch` (a world's FrameArena; the heap by default). `stop`, when set while it runs, cuts the frame
// short (FrameContext::stop): the phase after is not run.
ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings, Recorder& recorder, int frame = 0,
                                   ContactMemory* memory = nullptr, const Forces& forces = {},
                                   std::pmr::memory_resource* scratch = std::pmr::new_delete_resource(),
                                   const std::atomic<bool>* stop = nullptr);

// The same with nobody listening.
ResolutionSummary resolve_contacts(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                   const ResolverSettings& settings);

}  // namespace impulse
