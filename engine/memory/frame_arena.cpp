#include "memory/frame_arena.hpp"

#include <cassert>
#include <new>

namespace impulse {

namespace {

// A buffer left uninitialised: std::make_unique_for_overwrite, which the web build's libc++ 13 does not have yet.
std::unique_ptr<std::byte[]> uninitialised_bytes(std::size_t size) {
    return std::unique_ptr<std::byte[]>(new std::byte[size]);
}

}  // namespace

void* FrameArena::Overflow::do_allocate(std::size_t size, std::size_t alignment) {
    bytes += size;
    return ::operator new(size, std::align_val_t(alignment));
}

// (The unsized delete: clang does not declare the sized one without -fsized-deallocation.)
void FrameArena::Overflow::do_deallocate(void* p, std::size_t, std::size_t alignment) {
    ::operator delete(p, std::align_val_t(alignment));
}

FrameArena::FrameArena(const FrameArena& other)
    : buffer_(other.size_ > 0 ? uninitialised_bytes(other.size_) : nullptr), size_(other.size_) {
    assert(!other.frame_ && "not copied during a frame");
}

FrameArena& FrameArena::operator=(const FrameArena& other) {
    assert(!frame_ && !other.frame_ && "not copied during a frame");
    if (this != &other && size_ != other.size_) {
        buffer_ = other.size_ > 0 ? uninitialised_bytes(other.size_) : nullptr;
        size_ = other.size_;
    }
    return *this;
}

FrameArena::Frame::Frame(FrameArena& arena) : arena_(arena) {
    assert(!arena_.frame_ && "one frame at a time");
    arena_.overflow_.bytes = 0;
    if (arena_.size_ > 0)
        arena_.frame_.emplace(arena_.buffer_.get(), arena_.size_, &arena_.overflow_);
    else
        arena_.frame_.emplace(&arena_.overflow_);
}

FrameArena::Frame::~Frame() {
    arena_.frame_.reset();  // gives back what the overflow served
    if (arena_.overflow_.bytes == 0) return;
    // Next frame, everything in one buffer: what this one used, with room to spare for a growing scene.
    const std::size_t used = arena_.size_ + arena_.overflow_.bytes;
    arena_.size_ = used + used / 4;
    arena_.buffer_ = uninitialised_bytes(arena_.size_);
}

}  // namespace impulse
