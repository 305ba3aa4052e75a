#include "methods/graph_colouring.hpp"

#include <array>

namespace impulse {

namespace {

constexpr int colour_count = 24;                       // Box3D's B3_GRAPH_COLOR_COUNT, its overflow the last
constexpr int overflow = colour_count - 1;             // no colour was free
constexpr int moving_pair_colours = colour_count - 4;  // pairs of two moving bodies keep to colours 0 to 19

using Pair = std::array<int, 2>;

bool is_static(const Pair& pair, int side, std::span<const SolverBody> bodies) {
    const int b = pair[side];
    if (b < 0) return true;  // the world
    const MassProperties& m = bodies[static_cast<std::size_t>(b)].mass;
    return m.inverse_mass == 0.0 && m.inverse_inertia_world.isZero(0.0);
}

// The colour of a pair, marking its moving bodies as taken in it (one bit per colour per body in `taken`).
int colour_of_pair(const Pair& pair, std::span<const SolverBody> bodies, std::pmr::vector<std::uint32_t>& taken) {
    const bool static0 = is_static(pair, 0, bodies), static1 = is_static(pair, 1, bodies);
    if (static0 && static1) return overflow;  // nothing to move (not listed: such rows are never active)
    if (!static0 && !static1) {
        std::uint32_t& a = taken[static_cast<std::size_t>(pair[0])];
        std::uint32_t& b = taken[static_cast<std::size_t>(pair[1])];
        for (int c = 0; c < moving_pair_colours; ++c) {
            const std::uint32_t bit = 1u << c;
            if ((a | b) & bit) continue;
            a |= bit;
            b |= bit;
            return c;
        }
        return overflow;
    }
    std::uint32_t& moving = taken[static_cast<std::size_t>(pair[static0 ? 1 : 0])];
    for (int c = overflow - 1; c >= 1; --c) {
        const std::uint32_t bit = 1u << c;
        if (moving & bit) continue;
        moving |= bit;
        return c;
    }
    return overflow;
}

}  // namespace

std::pmr::vector<int> pair_colours(std::span<const Pair> pairs, std::span<const SolverBody> bodies,
                                   std::pmr::memory_resource* scratch) {
    std::pmr::vector<std::uint32_t> taken(bodies.size(), 0u, scratch);
    std::pmr::vector<int> colours(pairs.size(), overflow, scratch);
    for (std::size_t r = 0; r < pairs.size(); ++r) {
        // A pair's points are listed together: the first one colours the pair.
        if (r > 0 && pairs[r - 1] == pairs[r])
            colours[r] = colours[r - 1];
        else
            colours[r] = colour_of_pair(pairs[r], bodies, taken);
    }
    for (int& c : colours)
        if (c == overflow) c = -1;
    return colours;
}

std::pmr::vector<std::uint32_t> colour_slots(std::span<const Pair> pairs, std::span<const SolverBody> bodies,
                                             std::pmr::memory_resource* scratch) {
    return slots_of_colours(pair_colours(pairs, bodies, scratch), scratch);
}

std::pmr::vector<std::uint32_t> slots_of_colours(std::span<const int> colours, std::pmr::memory_resource* scratch) {
    // A counting sort by colour, the overflow (-1) first: stable, so detection's order stays within a colour.
    std::array<std::uint32_t, colour_count + 1> start{};
    for (const int c : colours) ++start[static_cast<std::size_t>(c + 2)];
    for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
    std::pmr::vector<std::uint32_t> slots(colours.size(), 0u, scratch);
    for (std::size_t r = 0; r < colours.size(); ++r) slots[r] = start[static_cast<std::size_t>(colours[r] + 1)]++;
    return slots;
}

}  // namespace impulse
