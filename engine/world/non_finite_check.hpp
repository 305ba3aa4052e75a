#pragma once
// The check a step (and a single resolution) ends with: a NaN or an infinity in a body's state stops the run,
// and the error names the body and the last contact that moved it, found without the recorder.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "record/recorder.hpp"

#include <array>
#include <optional>
#include <span>
#include <vector>

namespace impulse {

// A body whose state holds a NaN or an infinity once the step is over: the run cannot go on from it.
struct NonFiniteBody {
    int body = 0;
    const char* quantity = "";        // "position", "orientation", "velocity" or "angular velocity"
    std::optional<int> last_contact;  // the last contact in resolution order that moved it (none: no contact did)
    std::array<int, 2> last_contact_bodies{0, world_body};  // that contact's bodies, as detected

    bool operator==(const NonFiniteBody&) const = default;
};

// Passes every report on to the caller's recorder and remembers, per body, the last contact an iteration
// resolved (in resolution order, both phases): who to blame if the body ends the step non-finite. One store
// per iteration, or per contact of a sweeping method's last visits (contacts_visited), so the recorder-off
// path stays as fast.
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
    void contacts_visited(std::span<const int> contacts) override {
        for (const int c : contacts) touched(c);
        inner_.contacts_visited(contacts);
    }
    void end_phase(Phase phase, const PhaseOutcome& outcome) override { inner_.end_phase(phase, outcome); }
    void end_frame(std::span<const RigidBody> bodies) override { inner_.end_frame(bodies); }

    // The last contact that touched `body`, if any did, and that contact's bodies.
    std::optional<int> last_contact(int body) const {
        const int c = last_[static_cast<std::size_t>(body)];
        return c < 0 ? std::nullopt : std::optional<int>(c);
    }
    std::array<int, 2> bodies_of(int contact) const { return contacts_[static_cast<std::size_t>(contact)].bodies; }

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

// The first body (in body order) whose state is not finite, if any, with no contact to blame.
std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies);

// The same, blamed on the last contact `touch` saw move that body.
std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies, const LastTouch& touch);

}  // namespace impulse
