#pragma once
// What a warm-started solver carries from one frame to the next: each contact's accumulated impulse, found
// again next frame by the bodies and the features that made the contact (Box2D's and Bullet's contact
// persistence). The resolver itself stays stateless: the memory travels in its arguments.

#include "contact/contact.hpp"
#include "math/types.hpp"

#include <cstddef>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace impulse {

// A contact's identity across frames: its bodies as detected and the test and features that made it.
struct ContactKey {
    std::array<int, 2> bodies{};
    ContactOrigin origin{};

    bool operator==(const ContactKey&) const = default;
};

ContactKey key_of(const Contact& contact);

struct ContactKeyHash {
    std::size_t operator()(const ContactKey& key) const;
};

class ContactMemory {
public:
    // Last frame's accumulated impulse of the contact with this key (world coordinates, so a basis that
    // turned a little between frames still receives the same push), or nothing for a new contact.
    std::optional<Vec3> recall(const ContactKey& key) const;

    // Replaces what was remembered with this frame's totals. When two contacts share a key (explicit contacts
    // written by hand carry no features), the first keeps it, so recall stays deterministic.
    void remember(const std::vector<std::pair<ContactKey, Vec3>>& impulses);

    std::size_t size() const { return impulses_.size(); }
    void clear() { impulses_.clear(); }

private:
    std::unordered_map<ContactKey, Vec3, ContactKeyHash> impulses_;
};

}  // namespace impulse
