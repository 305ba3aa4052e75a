#pragma once
// Asks for memory a loop will read a few turns on, before it reads it. The prepared contacts are 272 bytes each,
// 16 MB a frame on Box3D's large pyramid: a row solver's passes over them, in detection's order, find each one long
// gone from the cache, and the hardware does not fetch ahead for a stride this long.

#include <cstddef>

namespace impulse {

// Every cache line of `object`; of the members from `first` to `last`, inclusive, of one object.
template <typename Object>
inline void fetch_ahead(const Object& object) {
    const char* bytes = reinterpret_cast<const char*>(&object);
    for (std::size_t at = 0; at < sizeof(Object); at += 64) __builtin_prefetch(bytes + at);
    __builtin_prefetch(bytes + sizeof(Object) - 1);
}
template <typename First, typename Last>
inline void fetch_ahead(const First& first, const Last& last) {
    const char* from = reinterpret_cast<const char*>(&first);
    const char* to = reinterpret_cast<const char*>(&last) + sizeof(Last) - 1;
    for (const char* at = from; at < to; at += 64) __builtin_prefetch(at);
    __builtin_prefetch(to);
}

}  // namespace impulse
