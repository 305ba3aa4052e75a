#pragma once
// The world: a scene's bodies, shapes, materials, ground, gravity and settings, and the contact memory that
// carries warm-starting solvers' impulses from frame to frame, in one object that steps a frame at a time
// (Box2D v3's b2World_Step, Jolt's PhysicsSystem::Update): create it from a scene, step it, read it. Every
// caller that simulates frames (`run`, the inspector's runs, the bench, the world bench, the tests) steps a
// World, so the frame's order exists once and no caller can forget the memory and silently start cold.
//
// A step, in the reference engine's demo order: integrate every body, detect contacts, resolve them (a method
// that owns the whole step, soft step, integrates in its own sub-steps: detect, then resolve). Each stage is
// timed for the profile (StageTimes, resolver/resolver.hpp; never for traces, which must be byte-identical run to
// run).

#include "memory/contact_memory.hpp"
#include "memory/contact_recycling.hpp"
#include "memory/frame_arena.hpp"
#include "record/recorder.hpp"
#include "resolver/resolver.hpp"
#include "scene/scene.hpp"
#include "world/non_finite_check.hpp"

#include <atomic>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// The most contacts one frame resolves. A box's pair test gives at most 8 contacts, a sphere's 1, so contacts per
// pair are bounded by the shapes; the number of pairs is not: 3000 spheres at one point are 4.5 million pairs,
// whose contacts took gigabytes before the resolver saw the first. 250,000 is 60 times the 1000-box grid's
// 4000; a frame past it is not resolved (Detection::over_budget, StepReport::over_contact_budget).
inline constexpr std::size_t max_contacts_per_frame = 250'000;

struct Detection {
    std::vector<Contact> contacts;  // ground contacts in body order, then pairs in (i, j) order
    int pairs_tested = 0;           // pairs the broad phase handed to the pair tests
    int pairs_recycled = 0;         // pairs whose kept contacts were used instead of a test (contact recycling)
    bool over_budget = false;       // the pair tests stopped past max_contacts_per_frame contacts
};

// Every contact between shaped bodies and with the ground, with the materials combined. Bodies without a
// shape take part in no test, and two immovable bodies are never tested against each other. The world's
// step calls it; the bench's accuracy metrics and `resolve` (a scene without written contacts) call it alone.
Detection detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, StageTimes* times = nullptr);
// The same into `detection`, whose list keeps its room (a world detects every frame). With `recycling` (a world's,
// when its settings switch recycling on), a pair kept from earlier frames that has moved little since is not
// tested: its kept contacts are used, brought up to date (memory/contact_recycling.hpp). `materials`: each body's,
// as body_materials gives them, from a caller that detects every frame (a world); empty: looked up here.
void detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, Detection& detection,
                     StageTimes* times = nullptr, ContactRecycling* recycling = nullptr,
                     std::span<const Material> materials = {});

// Each body's material, looked up by the name the scene gives it.
std::vector<Material> body_materials(const Scene& scene);

// What one step did.
struct StepReport {
    int frame = 0;  // the frame stepped, from 0
    int pairs_tested = 0;
    int pairs_recycled = 0;  // of them and of the kept pairs, those whose kept contacts were used (recycling)
    int contacts = 0;
    double deepest_penetration = 0.0;  // m, before resolution (0 without contacts)
    double kinetic_energy = 0.0;       // J, after the step
    ResolutionSummary resolution;
    StageTimes times;
    std::optional<NonFiniteBody> non_finite;  // set when the step left a body with a NaN or infinity
    bool over_contact_budget = false;         // detection passed max_contacts_per_frame: nothing was resolved, and
                                              // the caller must not step again
};

// The body that starts highest against gravity (the top of a stack): whose drift measures a stack's hold.
std::size_t highest_body(const Scene& scene);

class World {
public:
    // The scene's bodies at their start (frame 0, time 0) and an empty contact memory. Contacts written in the
    // scene (a case's, for `resolve`) are not used: a world detects its own.
    explicit World(Scene scene);

    // One frame of settings.duration seconds: integrate -> detect -> resolve, the recorder seeing the
    // resolution (begin_frame .. end_frame) of frame frame(). The bodies and the contact memory change in
    // place and frame() counts one more. A step that leaves a body with a NaN or infinity reports it in
    // `non_finite`, with the contact that last touched it: the caller must not step again (the state cannot
    // go on), but may still read it.
    StepReport step(Recorder& recorder);
    StepReport step();  // with nobody listening

    // Back to the scene's start: its bodies, an empty memory (impulses and recycled contacts), frame 0.
    void reset();

    // A flag that, once set (from a signal handler, say), cuts the step in progress short: its report says
    // resolution.cut_short, and its bodies are as far as the resolution got. Null (the default): nothing can.
    void set_stop_flag(const std::atomic<bool>* stop) { stop_ = stop; }

    const Scene& scene() const { return scene_; }  // as created: shapes, materials, settings, bodies at the start
    const ResolverSettings& settings() const { return scene_.settings; }
    const std::vector<RigidBody>& bodies() const { return bodies_; }          // now: after frame() frames
    const ContactMemory& contact_memory() const { return memory_; }           // last step's impulses, by contact key
    const ContactRecycling& contact_recycling() const { return recycling_; }  // the pairs' kept contacts
    int frame() const { return frame_; }  // frames stepped so far: the number of the next one
    double time() const { return frame_ * scene_.settings.duration; }  // s since the start

private:
    Scene scene_;
    std::vector<RigidBody> bodies_;
    ContactMemory memory_;
    ContactRecycling recycling_;  // used when settings.recycling is on
    int frame_ = 0;
    std::vector<PrincipalInertia> principal_;  // per body, for the step report's kinetic energy
    FrameArena arena_;                         // the resolution's buffers, kept from frame to frame
    const std::atomic<bool>* stop_ = nullptr;  // set_stop_flag
    std::vector<Material> materials_;          // per body, looked up by name once (detection needs them every frame)
    Detection detection_;  // the last step's contacts; their list's room is kept from frame to frame
};

}  // namespace impulse
