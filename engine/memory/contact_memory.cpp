#include "memory/contact_memory.hpp"

#include <cstdint>
#include <functional>

namespace impulse {

namespace {

std::size_t hash_of(const ContactKey& key) {
    std::size_t h = 0;
    const auto mix = [&h](int value) { h = h * 1000003u ^ std::hash<int>{}(value); };
    // (The table keeps the low bits: the final multiply and fold spread every input into them.)
    mix(key.bodies[0]);
    mix(key.bodies[1]);
    mix(static_cast<int>(key.origin.test));
    for (const Feature& f : key.origin.features) {
        mix(static_cast<int>(f.kind));
        mix(f.index);
    }
    const std::uint64_t spread = (h ^ (h >> 29)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(spread ^ (spread >> 32));
}

// Field by field (the defaulted comparison calls memcmp for the arrays).
bool same_key(const ContactKey& a, const ContactKey& b) {
    return a.bodies[0] == b.bodies[0] && a.bodies[1] == b.bodies[1] && a.origin.test == b.origin.test &&
           a.origin.features[0].kind == b.origin.features[0].kind &&
           a.origin.features[0].index == b.origin.features[0].index &&
           a.origin.features[1].kind == b.origin.features[1].kind &&
           a.origin.features[1].index == b.origin.features[1].index;
}

}  // namespace

std::ptrdiff_t ContactMemory::slot_of(const ContactKey& key, std::ptrdiff_t hint) const {
    if (hint >= 0 && static_cast<std::size_t>(hint) < keys_.size()) {
        const auto at = static_cast<std::size_t>(hint);
        if (keeps_key_[at] && same_key(keys_[at], key)) return hint;
    }
    if (index_.empty()) return -1;
    const std::size_t mask = index_.size() - 1;
    for (std::size_t at = hash_of(key) & mask;; at = (at + 1) & mask) {
        const std::int32_t entry = index_[at];
        if (entry < 0) return -1;
        if (same_key(keys_[static_cast<std::size_t>(entry)], key)) return entry;
    }
}

bool ContactMemory::holds_keys(std::span<const ContactKey> keys) const {
    if (index_.empty() || keys.size() != keys_.size()) return false;
    for (std::size_t k = 0; k < keys.size(); ++k)
        if (!same_key(keys_[k], keys[k])) return false;
    return true;
}

void ContactMemory::index_keys() {
    std::size_t size = 16;
    while (size < 2 * keys_.size()) size *= 2;
    index_.assign(size, -1);
    keeps_key_.assign(keys_.size(), 0);
    const std::size_t mask = size - 1;
    for (std::size_t e = 0; e < keys_.size(); ++e) {
        const ContactKey& key = keys_[e];
        std::size_t at = hash_of(key) & mask;
        while (index_[at] >= 0 && !same_key(keys_[static_cast<std::size_t>(index_[at])], key)) at = (at + 1) & mask;
        if (index_[at] < 0) {  // else the first with this key keeps it
            index_[at] = static_cast<std::int32_t>(e);
            keeps_key_[e] = 1;
        }
    }
}

void ContactMemory::clear() {
    keys_.clear();
    impulses_.clear();
    stiffness_.clear();
    index_.clear();
    keeps_key_.clear();
}

}  // namespace impulse
