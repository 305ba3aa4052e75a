#include "memory/frame_arena.hpp"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <new>

namespace impulse {

namespace {

// Every block starts on a cache line: no request is aligned more strictly than that.
constexpr std::size_t block_alignment = 64;
constexpr std::size_t smallest_block = std::size_t{64} << 10;

}  // namespace

// Left uninitialised: the system's pages are faulted in when first written, by the frame that uses them.
void FrameArena::Blocks::add(std::size_t size) {
    blocks.push_back({static_cast<std::byte*>(::operator new(size, std::align_val_t(block_alignment))), size});
}

void FrameArena::Blocks::release() {
    for (const Block& block : blocks) ::operator delete(block.bytes, std::align_val_t(block_alignment));
    blocks.clear();
}

void* FrameArena::Blocks::do_allocate(std::size_t size, std::size_t alignment) {
    assert(alignment <= block_alignment && "no request aligned beyond a cache line");
    const auto fits = [&](std::size_t b, std::size_t from) -> void* {
        const Block& block = blocks[b];
        const std::size_t start = (from + alignment - 1) / alignment * alignment;
        if (start > block.size || block.size - start < size) return nullptr;
        current = b;
        used = start + size;
        return block.bytes + start;
    };
    if (!blocks.empty())
        for (std::size_t b = current; b < blocks.size(); ++b)
            if (void* p = fits(b, b == current ? used : 0)) return p;
    add(std::max({size, smallest_block, blocks.empty() ? std::size_t{0} : 2 * blocks.back().size}));
    return fits(blocks.size() - 1, 0);
}

FrameArena::FrameArena(const FrameArena& other) {
    assert(!other.blocks_.open && "not copied during a frame");
    if (const std::size_t size = other.capacity(); size > 0) blocks_.add(size);
}

FrameArena& FrameArena::operator=(const FrameArena& other) {
    assert(!blocks_.open && !other.blocks_.open && "not copied during a frame");
    if (this != &other && capacity() != other.capacity()) {
        const std::size_t size = other.capacity();
        blocks_.release();
        if (size > 0) blocks_.add(size);
    }
    return *this;
}

FrameArena::~FrameArena() {
    blocks_.release();
}

std::size_t FrameArena::capacity() const {
    std::size_t size = 0;
    for (const Blocks::Block& block : blocks_.blocks) size += block.size;
    return size;
}

FrameArena::Frame::Frame(FrameArena& arena) : arena_(arena) {
    assert(!arena_.blocks_.open && "one frame at a time");
    arena_.blocks_.open = true;
}

FrameArena::Frame::~Frame() {
    arena_.blocks_.current = 0;  // everything given back: the next frame starts at the first block's start
    arena_.blocks_.used = 0;
    arena_.blocks_.open = false;
}

}  // namespace impulse
