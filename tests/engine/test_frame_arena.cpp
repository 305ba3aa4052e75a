// The frame arena (memory/frame_arena.hpp): a frame's buffers from one kept buffer, which grows to what a frame
// used, so a frame that uses no more than the last asks the system for nothing.

#include "memory/frame_arena.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <memory_resource>
#include <vector>

using namespace impulse;

namespace {

// A frame's use: `count` doubles in one vector and a second vector of half as many, both filled.
void use(FrameArena& arena, std::size_t count) {
    FrameArena::Frame frame(arena);
    std::pmr::vector<double> first(count, 1.0, frame.resource());
    std::pmr::vector<std::int64_t> second(count / 2, 2, frame.resource());
    CHECK(first.back() == 1.0);
    if (!second.empty()) CHECK(second.back() == 2);
}

}  // namespace

TEST_CASE("the frame arena grows to what a frame used and then serves a like frame from its buffer") {
    FrameArena arena;
    CHECK(arena.capacity() == 0);
    use(arena, 1000);  // served by the system, counted
    const std::size_t grown = arena.capacity();
    CHECK(grown >= 1000 * sizeof(double) + 500 * sizeof(std::int64_t));
    for (int frame = 0; frame < 5; ++frame) use(arena, 1000);
    CHECK(arena.capacity() == grown);  // no frame overflowed: nothing asked of the system
    use(arena, 900);
    CHECK(arena.capacity() == grown);  // smaller frames keep the buffer
    use(arena, 4000);
    CHECK(arena.capacity() >= 4000 * sizeof(double) + 2000 * sizeof(std::int64_t));
    CHECK(arena.capacity() > grown);
}

TEST_CASE("a frame's memory is handed out in order from the buffer and is all given back when the frame ends") {
    FrameArena arena;
    use(arena, 100);
    const auto first_address = [&] {
        FrameArena::Frame frame(arena);
        std::pmr::vector<double> v(10, 0.0, frame.resource());
        const double* first = v.data();  // the arena's memory, not the stack's (said apart for clang's warning)
        return reinterpret_cast<std::uintptr_t>(first);
    };
    const std::uintptr_t a = first_address();
    CHECK(first_address() == a);  // the second frame starts where the first did: nothing kept between frames
}

TEST_CASE("a copied arena is an empty cache of the same size") {
    FrameArena arena;
    use(arena, 2000);
    const FrameArena copy = arena;
    CHECK(copy.capacity() == arena.capacity());
    FrameArena assigned;
    assigned = arena;
    CHECK(assigned.capacity() == arena.capacity());
    FrameArena& same = assigned;
    assigned = same;  // self-assignment keeps it
    CHECK(assigned.capacity() == arena.capacity());
    use(assigned, 2000);
    CHECK(assigned.capacity() == arena.capacity());
}
