// The contact memory (memory/contact_memory.hpp): last frame's totals found again by their contacts' keys, the
// first of two contacts with one key keeping it, whether a frame brings last frame's keys in last frame's order
// (the memory then keeps its index) or not.

#include "memory/contact_memory.hpp"

#include <doctest/doctest.h>

#include <vector>

using namespace impulse;

namespace {

ContactKey key_of(int body, int vertex) {
    return {{body, world_body}, {CollisionTest::box_half_space, {Feature{FeatureKind::vertex, vertex}, Feature{}}}};
}

// Remembers the keys with the impulse (k + 1 + offset, 0, 0) for the k-th.
void remember(ContactMemory& memory, const std::vector<ContactKey>& keys, double offset) {
    memory.remember(keys, [&](std::size_t k) { return Vec3(double(k) + 1.0 + offset, 0.0, 0.0); });
}

// The impulse found for `key`, or -1 when none is.
double found(const ContactMemory& memory, const ContactKey& key) {
    const std::ptrdiff_t slot = memory.slot_of(key);
    return slot < 0 ? -1.0 : memory.impulse_at(slot).x();
}

}  // namespace

TEST_CASE("the contact memory finds each key's total again, frame after frame, in whatever order the keys come") {
    std::vector<ContactKey> keys;
    for (int body = 0; body < 40; ++body)
        for (int vertex = 0; vertex < 4; ++vertex) keys.push_back(key_of(body, vertex));
    keys.push_back(keys[13]);  // a second contact with key 13's key: the first keeps it
    ContactMemory memory;
    remember(memory, keys, 0.0);
    CHECK(found(memory, keys[0]) == 1.0);
    CHECK(found(memory, keys[13]) == 14.0);
    CHECK(found(memory, keys[159]) == 160.0);
    CHECK(found(memory, key_of(40, 0)) == -1.0);

    SUBCASE("the same keys in the same order: new totals, found where they were, the first still keeping its key") {
        remember(memory, keys, 100.0);
        for (std::size_t k = 0; k + 1 < keys.size(); ++k) CHECK(found(memory, keys[k]) == double(k) + 101.0);
        CHECK(found(memory, keys.back()) == 114.0);
        CHECK(memory.slot_of(keys[13], 13) == 13);   // the hint is taken
        CHECK(memory.slot_of(keys[13], 160) == 13);  // the last entry's key is kept by entry 13
    }
    SUBCASE("the keys in another order, one gone and one new: each found at its new place") {
        std::vector<ContactKey> moved(keys.rbegin(), keys.rend() - 1);  // reversed, without keys[0]
        moved.push_back(key_of(41, 1));
        remember(memory, moved, 100.0);
        CHECK(found(memory, keys[0]) == -1.0);
        CHECK(found(memory, key_of(41, 1)) == double(moved.size()) + 100.0);
        CHECK(found(memory, keys[159]) == 102.0);  // second in the new order
        CHECK(found(memory, keys[13]) == 101.0);   // its duplicate is first now, and keeps the key
        CHECK(found(memory, keys[1]) == double(moved.size()) - 1.0 + 100.0);
    }
    SUBCASE("cleared, then the same keys again: found as at first") {
        memory.clear();
        CHECK(found(memory, keys[0]) == -1.0);
        remember(memory, keys, 0.0);
        CHECK(found(memory, keys[0]) == 1.0);
        CHECK(found(memory, keys.back()) == 14.0);
    }
}
