#include "world/world.hpp"

#include "collision/broad_phase.hpp"
#include "collision/collision.hpp"
#include "methods/method_table.hpp"
#include "body/integrate.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <utility>

namespace impulse {

namespace {

using Clock = std::chrono::steady_clock;

// Gives the contacts a pair test just appended (from `first` on) the combined material of the two surfaces.
void stamp_material(std::vector<Contact>& contacts, std::size_t first, const Material& a, const Material& b) {
    if (first == contacts.size()) return;  // no contact: nothing to combine
    const Material m = combine(a, b);
    for (std::size_t k = first; k < contacts.size(); ++k) {
        contacts[k].restitution = m.restitution;
        contacts[k].friction = m.friction;
    }
}

}  // namespace

Detection detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, StageTimes* times) {
    Detection detection;
    detect_contacts(scene, bodies, detection, times);
    return detection;
}

std::vector<Material> body_materials(const Scene& scene) {
    std::vector<Material> materials;
    materials.reserve(scene.body_materials.size());
    for (const std::string& name : scene.body_materials) materials.push_back(scene.materials.at(name));
    return materials;
}

void detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, Detection& detection, StageTimes* times,
                     ContactRecycling* recycling, std::span<const Material> materials) {
    std::vector<Contact>& out = detection.contacts;
    out.clear();
    detection.pairs_recycled = 0;
    if (recycling) recycling->begin_frame(scene.settings.recycling, bodies, scene.shapes);
    const auto start = Clock::now();

    std::vector<Placement> placements;
    placements.reserve(bodies.size());
    for (const RigidBody& body : bodies) placements.push_back({body.position, body.orientation.toRotationMatrix()});
    // Each body's material looked up by name once, not once per pair tested (a world looks them up once for all its
    // frames and hands them in).
    std::vector<Material> looked_up;
    if (materials.empty()) {
        looked_up = body_materials(scene);
        materials = looked_up;
    }
    assert(materials.size() >= bodies.size());
    // Room for four contacts a body on the ground (a box resting on a face), so the list rarely regrows.
    out.reserve(4 * bodies.size());

    if (scene.ground) {
        const Material& ground = scene.materials.at(scene.ground->material);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (!scene.shapes[i] || is_immovable(bodies[i])) continue;
            const BodyPair pair{static_cast<int>(i), world_body};
            if (recycling && recycling->recycle(pair, out)) continue;
            const std::size_t first = out.size();
            collide_with_ground(*scene.shapes[i], placements[i], static_cast<int>(i), scene.ground->plane, out);
            stamp_material(out, first, materials[i], ground);
            if (recycling) recycling->keep(pair, std::span<const Contact>(out).subspan(first));
        }
    }

    std::vector<std::optional<Bounds>> bounds(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (scene.shapes[i]) bounds[i] = world_bounds(*scene.shapes[i], placements[i].position, placements[i].rotation);
    const auto both_immovable = [&bodies](int i, int j) {
        return is_immovable(bodies[static_cast<std::size_t>(i)]) && is_immovable(bodies[static_cast<std::size_t>(j)]);
    };
    const auto broad_start = Clock::now();
    const std::vector<std::pair<int, int>> pairs =
        overlapping_pairs(std::span<const std::optional<Bounds>>(bounds), both_immovable);
    const double broad = seconds_since(broad_start);
    detection.pairs_tested = static_cast<int>(pairs.size());
    // Room for four contacts a pair (box_and_box's most), so the list does not regrow, copying, as the tests fill it
    // (the large pyramid's first frame: 59,800 contacts, 8 MB); never past the budget.
    out.reserve(std::min(out.size() + 4 * pairs.size(), max_contacts_per_frame));
    if (recycling) recycling->expect(pairs.size(), 4 * pairs.size());

    for (const auto& [i, j] : pairs) {
        if (out.size() > max_contacts_per_frame) break;  // the frame will not be resolved: stop adding to it
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
        if (recycling && recycling->recycle({i, j}, out)) continue;
        const std::size_t first = out.size();
        collide(*scene.shapes[ui], placements[ui], i, *scene.shapes[uj], placements[uj], j, out,
                scene.settings.speculative_margin);
        stamp_material(out, first, materials[ui], materials[uj]);
        if (recycling) recycling->keep({i, j}, std::span<const Contact>(out).subspan(first));
    }
    if (recycling) {
        recycling->end_frame(out);
        detection.pairs_recycled = recycling->recycled_pairs();
    }
    detection.over_budget = out.size() > max_contacts_per_frame;
    if (recycling && detection.over_budget) recycling->clear();  // the frame will not be resolved
    if (times) {
        times->broad_phase += broad;
        times->narrow_phase += seconds_since(start) - broad;
    }
}

std::size_t highest_body(const Scene& scene) {
    const Vec3 up = scene.world.gravity.norm() > 0.0 ? Vec3(-scene.world.gravity.normalized()) : Vec3::UnitY();
    std::size_t top = 0;
    for (std::size_t i = 1; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].position.dot(up) > scene.bodies[top].position.dot(up)) top = i;
    return top;
}

World::World(Scene scene) : scene_(std::move(scene)), bodies_(scene_.bodies), materials_(body_materials(scene_)) {
    principal_.reserve(bodies_.size());
    for (const RigidBody& body : bodies_) principal_.push_back(principal_inertia(body));
}

void World::reset() {
    bodies_ = scene_.bodies;
    memory_.clear();
    recycling_.clear();
    frame_ = 0;
}

StepReport World::step() {
    Recorder nobody;
    return step(nobody);
}

StepReport World::step(Recorder& recorder) {
    StepReport report;
    report.frame = frame_;
    const double dt = scene_.settings.duration;

    // A method that owns the whole step (soft step) integrates the bodies itself, sub-step by sub-step: it takes
    // the contacts at the current positions and the forces, and its integration counts as resolution time.
    const bool integrates_itself = method_row(scene_.settings.velocity_method).scope == MethodScope::whole_step;
    auto start = Clock::now();
    const Damping damping{scene_.world.linear_damping, scene_.world.angular_damping};
    if (!integrates_itself)
        for (RigidBody& body : bodies_)
            integrate(body, scene_.world.gravity, dt, damping, scene_.settings.orientation_update);
    report.times.integrate = seconds_since(start);

    detect_contacts(scene_, bodies_, detection_, &report.times, scene_.settings.recycling.on() ? &recycling_ : nullptr,
                    materials_);
    const Detection& detection = detection_;
    report.pairs_tested = detection.pairs_tested;
    report.pairs_recycled = detection.pairs_recycled;
    report.contacts = static_cast<int>(detection.contacts.size());
    for (const Contact& c : detection.contacts)
        report.deepest_penetration = std::max(report.deepest_penetration, c.penetration);
    if (detection.over_budget) {
        report.over_contact_budget = true;
        return report;
    }

    // The memory is the world's own: every step of a run recalls the last one's impulses, so warm starting is
    // on whenever the settings ask for it.
    LastTouch touch(detection.contacts);
    FrameArena::Frame scratch(arena_);
    report.resolution = resolve_contacts(bodies_, detection.contacts, scene_.settings, recorder,
                                         {.frame = frame_,
                                          .memory = &memory_,
                                          .forces = Forces{scene_.world.gravity, damping},
                                          .touch = &touch,
                                          .times = &report.times,
                                          .scratch = scratch.resource(),
                                          .stop = stop_});

    report.non_finite = first_non_finite(bodies_, touch);

    for (std::size_t b = 0; b < bodies_.size(); ++b) report.kinetic_energy += kinetic_energy(bodies_[b], principal_[b]);
    ++frame_;
    return report;
}

}  // namespace impulse
