#include "world/world.hpp"

#include "collision/broad_phase.hpp"
#include "collision/collision.hpp"
#include "methods/soft_step.hpp"
#include "world/integrate.hpp"

#include <algorithm>
#include <chrono>

namespace impulse {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

Placement placement_of(const RigidBody& body) {
    return {body.position, body.orientation.toRotationMatrix()};
}

// Gives the contacts a pair test just appended (from `first` on) the combined material of the two surfaces.
void stamp_material(std::vector<Contact>& contacts, std::size_t first, const Scene& scene, const std::string& a,
                    const std::string& b) {
    const Material m = combine(scene.materials.at(a), scene.materials.at(b));
    for (std::size_t k = first; k < contacts.size(); ++k) {
        contacts[k].restitution = m.restitution;
        contacts[k].friction = m.friction;
    }
}

// Passes every report on to the caller's recorder and remembers, per body, the last contact an iteration
// resolved (in resolution order, both phases): who to blame if the body ends the step non-finite. One store
// per iteration, so the recorder-off path stays as fast.
class LastTouch final : public Recorder {
public:
    LastTouch(Recorder& inner, std::span<const Contact> contacts, std::size_t body_count)
        : inner_(inner), contacts_(contacts), last_(body_count, -1) {}

    bool wants_updates() const override { return inner_.wants_updates(); }
    void begin_frame(int frame, std::span<const RigidBody> bodies, std::span<const MassProperties> mass) override {
        inner_.begin_frame(frame, bodies, mass);
    }
    void contacts_prepared(std::span<const PreparedContact> contacts) override { inner_.contacts_prepared(contacts); }
    void position_iteration(const PositionIteration& iteration) override {
        touched(iteration.contact);
        inner_.position_iteration(iteration);
    }
    void velocity_iteration(const VelocityIteration& iteration) override {
        touched(iteration.contact);
        inner_.velocity_iteration(iteration);
    }
    void end_phase(Phase phase, const PhaseOutcome& outcome) override { inner_.end_phase(phase, outcome); }
    void end_frame(std::span<const RigidBody> bodies) override { inner_.end_frame(bodies); }

    // The last contact that touched `body`, if any did.
    std::optional<int> last_contact(int body) const {
        const int c = last_[static_cast<std::size_t>(body)];
        return c < 0 ? std::nullopt : std::optional<int>(c);
    }

private:
    void touched(int contact) {
        if (contact < 0 || contact >= static_cast<int>(contacts_.size())) return;
        for (int b : contacts_[static_cast<std::size_t>(contact)].bodies)
            if (b != world_body) last_[static_cast<std::size_t>(b)] = contact;
    }

    Recorder& inner_;
    std::span<const Contact> contacts_;
    std::vector<int> last_;
};

const char* non_finite_quantity(const RigidBody& body) {
    if (!body.position.allFinite()) return "position";
    if (!body.orientation.coeffs().allFinite()) return "orientation";
    if (!body.velocity.allFinite()) return "velocity";
    if (!body.angular_velocity.allFinite()) return "angular velocity";
    return nullptr;
}

}  // namespace

std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies) {
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (const char* quantity = non_finite_quantity(bodies[i]))
            return NonFiniteBody{.body = static_cast<int>(i),
                                 .quantity = quantity,
                                 .last_contact = std::nullopt,
                                 .last_contact_bodies = {0, world_body}};
    return std::nullopt;
}

Detection detect_contacts(const Scene& scene, std::span<const RigidBody> bodies, StageTimes* times) {
    Detection detection;
    std::vector<Contact>& out = detection.contacts;
    const auto start = Clock::now();

    std::vector<Placement> placements;
    placements.reserve(bodies.size());
    for (const RigidBody& body : bodies) placements.push_back(placement_of(body));

    if (scene.ground) {
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            if (!scene.shapes[i] || is_immovable(bodies[i])) continue;
            const std::size_t first = out.size();
            collide_with_ground(*scene.shapes[i], placements[i], static_cast<int>(i), scene.ground->plane, out);
            stamp_material(out, first, scene, scene.body_materials[i], scene.ground->material);
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

    for (const auto& [i, j] : pairs) {
        const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
        const std::size_t first = out.size();
        collide(*scene.shapes[ui], placements[ui], i, *scene.shapes[uj], placements[uj], j, out);
        stamp_material(out, first, scene, scene.body_materials[ui], scene.body_materials[uj]);
    }
    if (times) {
        times->broad_phase += broad;
        times->narrow_phase += seconds_since(start) - broad;
    }
    return detection;
}

std::size_t highest_body(const Scene& scene) {
    const Vec3 up = scene.world.gravity.norm() > 0.0 ? Vec3(-scene.world.gravity.normalized()) : Vec3::UnitY();
    std::size_t top = 0;
    for (std::size_t i = 1; i < scene.bodies.size(); ++i)
        if (scene.bodies[i].position.dot(up) > scene.bodies[top].position.dot(up)) top = i;
    return top;
}

StepReport step(const Scene& scene, std::vector<RigidBody>& bodies, Recorder& recorder, int frame,
                ContactMemory* memory) {
    StepReport report;
    report.frame = frame;
    const double dt = scene.settings.duration;

    // Soft step integrates the bodies itself, sub-step by sub-step: it takes the contacts at the current positions
    // and the forces, and its integration counts as resolution time.
    const bool soft_step = scene.settings.velocity_method == VelocityMethod::soft_step;
    auto start = Clock::now();
    const Damping damping{scene.world.linear_damping, scene.world.angular_damping};
    if (!soft_step)
        for (RigidBody& body : bodies)
            integrate(body, scene.world.gravity, dt, damping, scene.settings.orientation_update);
    report.times.integrate = seconds_since(start);

    const Detection detection = detect_contacts(scene, bodies, &report.times);
    report.pairs_tested = detection.pairs_tested;
    report.contacts = static_cast<int>(detection.contacts.size());
    for (const Contact& c : detection.contacts)
        report.deepest_penetration = std::max(report.deepest_penetration, c.penetration);

    start = Clock::now();
    LastTouch touch(recorder, detection.contacts, bodies.size());
    report.resolution = soft_step ? solve_soft_step(bodies, detection.contacts, scene.settings,
                                                    {scene.world.gravity, damping}, touch, frame, memory)
                                  : resolve_contacts(bodies, detection.contacts, scene.settings, touch, frame, memory);
    report.times.resolve = seconds_since(start);

    report.non_finite = first_non_finite(bodies);
    if (report.non_finite) {
        report.non_finite->last_contact = touch.last_contact(report.non_finite->body);
        if (report.non_finite->last_contact)
            report.non_finite->last_contact_bodies =
                detection.contacts[static_cast<std::size_t>(*report.non_finite->last_contact)].bodies;
    }

    for (const RigidBody& body : bodies) report.kinetic_energy += kinetic_energy(body);
    return report;
}

}  // namespace impulse
