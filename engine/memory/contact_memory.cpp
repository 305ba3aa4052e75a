#include "memory/contact_memory.hpp"

#include <functional>

namespace impulse {

ContactKey key_of(const Contact& contact) {
    return {contact.bodies, contact.origin};
}

std::size_t ContactKeyHash::operator()(const ContactKey& key) const {
    std::size_t h = 0;
    const auto mix = [&h](int value) { h = h * 1000003u ^ std::hash<int>{}(value); };
    mix(key.bodies[0]);
    mix(key.bodies[1]);
    mix(static_cast<int>(key.origin.test));
    for (const Feature& f : key.origin.features) {
        mix(static_cast<int>(f.kind));
        mix(f.index);
    }
    return h;
}

std::optional<Vec3> ContactMemory::recall(const ContactKey& key) const {
    const auto found = impulses_.find(key);
    if (found == impulses_.end()) return std::nullopt;
    return found->second;
}

void ContactMemory::remember(const std::vector<std::pair<ContactKey, Vec3>>& impulses) {
    impulses_.clear();
    for (const auto& [key, impulse] : impulses) impulses_.emplace(key, impulse);
}

}  // namespace impulse
