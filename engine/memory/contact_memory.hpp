#pragma once
// What a warm-started solver carries from one frame to the next: each contact's accumulated impulse, found
// again next frame by the bodies and the features that made the contact (Box2D's and Bullet's contact
// persistence). The resolver itself stays stateless: the memory travels in its arguments.

#include "contact/contact.hpp"
#include "math/types.hpp"

#include <cstddef>
#include <cstdint>
#include <array>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace impulse {

// A contact's identity across frames: its bodies as detected and the test and features that made it.
struct ContactKey {
    std::array<int, 2> bodies{};
    ContactOrigin origin{};

    bool operator==(const ContactKey&) const = default;
};

class ContactMemory {
public:
    // Where last frame's accumulated impulse of the contact with this key is: an index into what was remembered
    // (below size()), or -1 for a new contact. A solver that must warm start each remembered impulse once can mark
    // the ones it took. `hint` is tried first: a solver that looks its contacts up in the order it remembered them
    // (the detection's order, which changes little from frame to frame) passes the slot after the last one it
    // found, and most lookups read the next entry instead of a scattered index slot and entry.
    std::ptrdiff_t slot_of(const ContactKey& key, std::ptrdiff_t hint = -1) const;
    // The impulse remembered at `slot` (world coordinates, so a basis that turned a little between frames still
    // receives the same push).
    const Vec3& impulse_at(std::ptrdiff_t slot) const { return impulses_[static_cast<std::size_t>(slot)]; }

    // Replaces what was remembered with this frame's totals, impulse(k) for the contact with keys[k]. When two
    // contacts share a key (explicit contacts written by hand carry no features), the first keeps it, so recall
    // stays deterministic. The memory keeps its buffers: once they have grown, remembering allocates nothing.
    template <typename Impulse>
    void remember(std::span<const ContactKey> keys, Impulse impulse) {
        // The index depends on the keys alone: a frame with last frame's contacts in last frame's order (most frames
        // of a settled scene, its contacts recycled) keeps last frame's keys and index, and writes only the impulses.
        if (!holds_keys(keys)) {
            keys_.assign(keys.begin(), keys.end());
            index_keys();
        }
        stiffness_.clear();
        impulses_.resize(keys.size());
        for (std::size_t k = 0; k < keys.size(); ++k) impulses_[k] = impulse(k);
    }
    // The same, with a stiffness per contact beside its impulse, stiffness(k) = {normal, tangential} (AVBD keeps its
    // penalty k from frame to frame: derivation/avbd/dual_update.hpp).
    template <typename Impulse, typename Stiffness>
    void remember(std::span<const ContactKey> keys, Impulse impulse, Stiffness stiffness) {
        remember(keys, impulse);
        for (std::size_t k = 0; k < keys.size(); ++k) stiffness_.push_back(stiffness(k));
    }
    // The stiffness remembered at `slot`, when the method that remembered kept one.
    std::optional<std::array<double, 2>> stiffness_at(std::ptrdiff_t slot) const {
        if (stiffness_.empty()) return std::nullopt;
        return stiffness_[static_cast<std::size_t>(slot)];
    }

    std::size_t size() const { return keys_.size(); }
    void clear();

private:
    // Whether the entries, indexed, have these keys in this order.
    bool holds_keys(std::span<const ContactKey> keys) const;
    void index_keys();

    // The entries, keys and totals as given (apart: a frame whose keys are last frame's rewrites only the totals),
    // and an open-addressing index over the keys (linear probing, at most half full, -1 = empty): a frame's
    // remembering writes 4 bytes per slot and allocates nothing once the index has grown.
    std::vector<ContactKey> keys_;
    std::vector<Vec3> impulses_;
    std::vector<std::int32_t> index_;
    std::vector<char> keeps_key_;                   // per entry: the first with its key, the one slot_of finds
    std::vector<std::array<double, 2>> stiffness_;  // per entry when remembered with one, else empty
};

}  // namespace impulse
