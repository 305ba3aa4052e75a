#pragma once
// The check a step (and a single resolution) ends with: a NaN or an infinity in a body's state stops the run,
// and the error names the body and the last contact that moved it, found without the recorder.

#include "body/rigid_body.hpp"
#include "contact/contact.hpp"
#include "record/last_touch.hpp"

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

// The first body (in body order) whose state is not finite, if any, with no contact to blame.
std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies);

// The same, blamed on the last contact `touch` saw move that body.
std::optional<NonFiniteBody> first_non_finite(std::span<const RigidBody> bodies, const LastTouch& touch);

}  // namespace impulse
