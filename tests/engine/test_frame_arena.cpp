// The frame arena (memory/frame_arena.hpp): a frame's buffers from blocks it keeps, which grow by what a frame
// needed, so a frame that uses no more than the last asks the system for nothing.

#include "memory/frame_arena.hpp"

#include <doctest/doctest.h>

#include <array>
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

TEST_CASE("the frame arena grows by what a frame needed and then serves a like frame from its blocks") {
    FrameArena arena;
    CHECK(arena.capacity() == 0);
    use(arena, 1000);  // served by the system, counted
    const std::size_t grown = arena.capacity();
    CHECK(grown >= 1000 * sizeof(double) + 500 * sizeof(std::int64_t));
    for (int frame = 0; frame < 5; ++frame) use(arena, 1000);
    CHECK(arena.capacity() == grown);  // no frame overflowed: nothing asked of the system
    use(arena, 900);
    CHECK(arena.capacity() == grown);  // smaller frames keep the buffer
    use(arena, 20000);                 // more than the first block (64 KiB) holds
    CHECK(arena.capacity() >= 20000 * sizeof(double) + 10000 * sizeof(std::int64_t));
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

TEST_CASE("the memory a frame took from the system is kept: a like frame's buffers lie where the first frame's did") {
    FrameArena arena;
    const auto addresses = [&] {
        FrameArena::Frame frame(arena);
        std::pmr::vector<double> small(1000, 0.0, frame.resource());
        std::pmr::vector<double> large(400000, 1.0, frame.resource());  // more than the first block holds
        const double* at[2] = {small.data(), large.data()};
        return std::array<std::uintptr_t, 2>{reinterpret_cast<std::uintptr_t>(at[0]),
                                             reinterpret_cast<std::uintptr_t>(at[1])};
    };
    const std::array<std::uintptr_t, 2> first = addresses();  // the first frame's from blocks it added
    const std::size_t grown = arena.capacity();
    CHECK(grown >= 401000 * sizeof(double));
    CHECK(addresses() == first);  // not a new buffer: the same pages, already the process's
    CHECK(arena.capacity() == grown);
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
