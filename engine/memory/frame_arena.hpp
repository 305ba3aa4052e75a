#pragma once
// Memory for what a frame builds and throws away (the contacts' rows, a method's solver bodies and totals),
// handed out from blocks that the world keeps from frame to frame: Box2D's arena allocator, Jolt's
// TempAllocator. Allocating is moving a pointer, freeing is nothing, and the whole frame's memory is given back
// at once when it ends; a frame that needs more than the blocks hold takes one more block from the system, and
// keeps it, so once a scene has settled a step asks the system for no memory at all. (From the heap instead, a
// frame's buffers of half a megabyte were freed at its end, the allocator gave their pages back to the system, and
// the next frame faulted them in again: 4 % of a soft step frame on pyramid_20. Grown by one new buffer of what the
// frame used, as this arena first was, the first frame's pages were given back and the second frame's faulted in
// afresh: 0.08 s of the first three frames of Box3D's large pyramid, docs/bench.md.)

#include <cstddef>
#include <memory_resource>
#include <vector>

namespace impulse {

class FrameArena {
public:
    FrameArena() = default;
    // The arena is a cache, not part of a world's state: a copy (a world copied to run on from the same
    // point) starts with as much memory, in one block, and nothing in it. Never copied during a frame.
    FrameArena(const FrameArena& other);
    FrameArena& operator=(const FrameArena& other);
    ~FrameArena();

    // One frame's use of the arena: `resource()` serves the frame's buffers until the Frame ends, and every
    // buffer taken from it must be gone by then.
    class Frame {
    public:
        explicit Frame(FrameArena& arena);
        ~Frame();
        Frame(const Frame&) = delete;
        Frame& operator=(const Frame&) = delete;
        std::pmr::memory_resource* resource() { return &arena_.blocks_; }

    private:
        FrameArena& arena_;
    };

    std::size_t capacity() const;  // bytes the next frame gets without asking the system

private:
    // The blocks, in the order a frame fills them: each request from the first block with room after the one in
    // use; when none has room, a new block, at least twice the last one, is added at the end.
    class Blocks final : public std::pmr::memory_resource {
    public:
        Blocks() = default;
        Blocks(const Blocks&) = delete;  // the blocks are owned once (FrameArena's copy takes blocks of its own)
        Blocks& operator=(const Blocks&) = delete;
        struct Block {
            std::byte* bytes;
            std::size_t size;
        };
        std::vector<Block> blocks;
        std::size_t current = 0;  // the block in use
        std::size_t used = 0;     // bytes of it handed out
        bool open = false;        // a Frame is using them

        void add(std::size_t size);
        void release();

    private:
        void* do_allocate(std::size_t size, std::size_t alignment) override;
        void do_deallocate(void*, std::size_t, std::size_t) override {}  // given back all at once, at the frame's end
        bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
    };

    Blocks blocks_;
};

}  // namespace impulse
