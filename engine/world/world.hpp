#pragma once
// The world step, in the reference engine's demo order: integrate every body, detect contacts, resolve them.
// Each stage is timed for the profile (never for traces, which must be byte-identical run to run).

#include "world/non_finite_check.hpp"
#include "record/recorder.hpp"
#include "resolver/resolver.hpp"
#include "scene/scene.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

struct StageTimes {
    double integrate = 0.0;     // s
    double broad_phase = 0.0;   // s
    double narrow_phase = 0.0;  // s: the pair tests
    double resolve = 0.0;       // s
};

struct Detection {
    std::vector<Contact> contacts;  // ground contacts in body order, then pairs in (i, j) order
    int pairs_tested = 0;           // pairs the broad phase handed to the pair tests
};

// Every contact between shaped bodies and with the ground, with the materials combined. Bodies without a
// shape take part in no test, and two immovable bodies are never tested against each other.
Detection detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, StageTimes* times = nullptr);

struct StepReport {
    int frame = 0;
    int pairs_tested = 0;
    int contacts = 0;
    double deepest_penetration = 0.0;  // m, before resolution (0 without contacts)
    double kinetic_energy = 0.0;       // J, after the step
    ResolutionSummary resolution;
    StageTimes times;
    std::optional<NonFiniteBody> non_finite;  // set when the step left a body with a NaN or infinity
};

// The body that starts highest against gravity (the top of a stack): whose drift measures a stack's hold.
std::size_t highest_body(const Scene& scene);

// One frame of `scene.settings.duration` seconds: integrate -> detect -> resolve (soft step: detect -> soft step,
// which integrates the bodies in its sub-steps). `bodies` is the state,
// changed in place; the scene gives shapes, materials, the ground and the settings. `memory` keeps
// warm-starting solvers' impulses between frames; pass the same one every frame of a run. A body left with a
// NaN or infinity is reported in `non_finite` with the contact that last touched it; the caller must stop.
StepReport step(const Scene& scene, std::vector<RigidBody>& bodies, Recorder& recorder, int frame,
                ContactMemory* memory = nullptr);

}  // namespace impulse
