#pragma once
// Memory for what a frame builds and throws away (the contacts' rows, a method's solver bodies and totals),
// handed out from one buffer that the world keeps from frame to frame: Box2D's arena allocator, Jolt's
// TempAllocator. Allocating is moving a pointer, freeing is nothing, and the whole frame's memory is given back
// at once when it ends; the buffer then grows to what the frame used, so once a scene has settled a step asks
// the system for no memory at all. (From the heap instead, a frame's buffers of half a megabyte were freed at
// its end, the allocator gave their pages back to the system, and the next frame faulted them in again: 4 % of
// a soft step frame on pyramid_20.)

#include <cstddef>
#include <memory>
#include <memory_resource>
#include <optional>

namespace impulse {

class FrameArena {
public:
    FrameArena() = default;
    // The arena is a cache, not part of a world's state: a copy (a world copied to run on from the same
    // point) starts with a buffer of the same size and nothing in it. Never copied during a frame.
    FrameArena(const FrameArena& other);
    FrameArena& operator=(const FrameArena& other);

    // One frame's use of the arena: `resource()` serves the frame's buffers until the Frame ends, and every
    // buffer taken from it must be gone by then.
    class Frame {
    public:
        explicit Frame(FrameArena& arena);
        ~Frame();
        Frame(const Frame&) = delete;
        Frame& operator=(const Frame&) = delete;
        std::pmr::memory_resource* resource() { return &*arena_.frame_; }

    private:
        FrameArena& arena_;
    };

    std::size_t capacity() const { return size_; }  // bytes the next frame gets without asking the system

private:
    // Serves what the buffer cannot hold from the heap, and counts it, so the buffer can grow for the next frame.
    class Overflow final : public std::pmr::memory_resource {
    public:
        std::size_t bytes = 0;

    private:
        void* do_allocate(std::size_t size, std::size_t alignment) override;
        void do_deallocate(void* p, std::size_t size, std::size_t alignment) override;
        bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override { return this == &other; }
    };

    std::unique_ptr<std::byte[]> buffer_;
    std::size_t size_ = 0;
    Overflow overflow_;
    std::optional<std::pmr::monotonic_buffer_resource> frame_;
};

}  // namespace impulse
