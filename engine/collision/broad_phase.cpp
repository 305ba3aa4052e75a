#include "collision/broad_phase.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace impulse {

Bounds world_bounds(const Shape& shape, const Vec3& position, const Mat3& rotation) {
    Vec3 extent;
    if (const auto* sphere = std::get_if<Sphere>(&shape))
        extent = Vec3::Constant(sphere->radius);
    else  // a box's half-extents along the world axes: |R| h
        extent = rotation.cwiseAbs() * std::get<Box>(shape).half_size;
    return {position - extent, position + extent};
}

namespace {

using Cell = std::array<std::uint32_t, 3>;

// Cell coordinates take 21 bits each. Coordinates past the last cell are clamped to it: a body far from the rest
// shares the last cell with any other there, which costs tests, never pairs.
constexpr int cell_bits = 21;
constexpr double last_cell = double((1u << cell_bits) - 1);

// The same comparisons as the sweep made (faces touching overlap), on every axis both ways.
bool overlap(const Bounds& a, const Bounds& b) {
    return a.low.x() <= b.high.x() && b.low.x() <= a.high.x() && a.low.y() <= b.high.y() && b.low.y() <= a.high.y() &&
           a.low.z() <= b.high.z() && b.low.z() <= a.high.z();
}

// A body is "large" when its largest side exceeds both four times the median body's and the side that only
// about sqrt(n) bodies exceed: large bodies are tested against every body, so there are at most about sqrt(n) of
// them (n^1.5 tests at most), and the cells follow the bodies that fill the scene.
double large_side(std::vector<double> sides) {
    const std::size_t n = sides.size();
    const auto median = sides.begin() + static_cast<std::ptrdiff_t>(n / 2);
    std::nth_element(sides.begin(), median, sides.end());
    const double four_medians = 4.0 * *median;
    const auto rank = static_cast<std::size_t>(std::ceil(std::sqrt(double(n))));
    const auto few_exceed = sides.begin() + static_cast<std::ptrdiff_t>(n - std::min(rank, n));
    std::nth_element(sides.begin(), few_exceed, sides.end());
    return std::max(four_medians, *few_exceed);
}

enum class Role : std::uint8_t { none, grid, large };

// The grid over the bodies that are not large, each listed in the one cell that holds its low corner. Cell
// (c0, c1, c2) covers [origin_a + c_a size_a, origin_a + (c_a + 1) size_a) along each axis a, a sixteenth longer
// than the longest side along it. The cell of v is floor((v - origin) / size), computed as a product with the
// rounded inverse: every step is monotone in v, so for two bodies whose bounds overlap along an axis,
// cell(low_b) <= cell(high_a) <= cell(low_a) + 1, and the same the other way: their low corners' cells differ by at
// most one along each axis, and each body finds every body it overlaps in the 3 x 3 x 3 cells around its own. The
// constructor makes that hold: a body whose high corner is more than one cell past its low one (which the cell
// size allows only through rounding, or for sides beyond any double's reach) is made large instead. The cells are
// counted into groups (one counting sort, bodies in index order within each): the cells themselves, numbered x
// fastest, when the box around the bodies has few enough of them; else a hash of the cell.
class Grid {
public:
    Grid(std::span<const std::optional<Bounds>> bounds, std::vector<Role>& roles) : bounds_(bounds) {
        Vec3 longest = Vec3::Zero();
        origin_ = Vec3::Constant(std::numeric_limits<double>::infinity());
        for (std::size_t k = 0; k < bounds.size(); ++k)
            if (roles[k] == Role::grid) {
                origin_ = origin_.cwiseMin(bounds[k]->low);
                longest = longest.cwiseMax(bounds[k]->high - bounds[k]->low);
            }
        for (int a = 0; a < 3; ++a) inverse_size_[a] = 1.0 / std::clamp(longest[a] * (17.0 / 16.0), 1e-200, 1e200);
        cells_.resize(bounds.size());
        std::size_t listed = 0;
        for (std::size_t k = 0; k < bounds.size(); ++k) {
            if (roles[k] != Role::grid) continue;
            const Cell low = cell_of(bounds[k]->low), high = cell_of(bounds[k]->high);
            if (high[0] > low[0] + 1 || high[1] > low[1] + 1 || high[2] > low[2] + 1) {
                roles[k] = Role::large;
                continue;
            }
            cells_[k] = low;
            for (int a = 0; a < 3; ++a) extent_[a] = std::max(extent_[a], low[a] + 1);
            ++listed;
        }
        list(roles, listed);
    }

    // The bodies after `body` in index order whose bounds overlap its own, appended to `out`.
    void overlapping_after(int body, std::vector<int>& out) const {
        const auto k = static_cast<std::size_t>(body);
        const Cell& cell = cells_[k];
        const Bounds& a = *bounds_[k];
        const auto range = [&](int axis) {  // the cells next to the body's own along an axis, within the grid
            return std::pair{cell[axis] == 0 ? 0u : cell[axis] - 1, std::min(cell[axis] + 1, extent_[axis] - 1)};
        };
        const auto [x0, x1] = range(0);
        const auto [y0, y1] = range(1);
        const auto [z0, z1] = range(2);
        const auto test = [&](std::uint32_t begin, std::uint32_t end, auto in_cell) {
            for (std::uint32_t e = begin; e < end; ++e) {
                const int other = entries_[e];
                if (other > body && in_cell(other) && overlap(a, *bounds_[static_cast<std::size_t>(other)]))
                    out.push_back(other);
            }
        };
        for (std::uint32_t z = z0; z <= z1; ++z)
            for (std::uint32_t y = y0; y <= y1; ++y) {
                if (dense_) {  // the row's cells x0..x1 are one run of groups
                    const std::size_t row = extent_[0] * (y + std::size_t{extent_[1]} * z);
                    test(starts_[row + x0], starts_[row + x1 + 1], [](int) { return true; });
                    continue;
                }
                for (std::uint32_t x = x0; x <= x1; ++x) {
                    const std::size_t group = hash_of({x, y, z});
                    test(starts_[group], starts_[group + 1], [&](int other) {
                        return cells_[static_cast<std::size_t>(other)] == Cell{x, y, z};
                    });
                }
            }
    }

private:
    Cell cell_of(const Vec3& point) const {
        Cell cell;
        for (int a = 0; a < 3; ++a)  // point >= origin, so the product is >= 0 (or +inf, clamped)
            cell[a] = static_cast<std::uint32_t>(std::min((point[a] - origin_[a]) * inverse_size_[a], last_cell));
        return cell;
    }

    std::size_t hash_of(const Cell& cell) const {
        std::uint64_t key =
            std::uint64_t(cell[0]) | std::uint64_t(cell[1]) << cell_bits | std::uint64_t(cell[2]) << (2 * cell_bits);
        key ^= key >> 33;  // MurmurHash3's finalizer: every bit of the cell moves the group
        key *= 0xff51afd7ed558ccdull;
        key ^= key >> 33;
        key *= 0xc4ceb9fe1a85ec53ull;
        key ^= key >> 33;
        return static_cast<std::size_t>(key & (groups_ - 1));
    }

    std::size_t group_of(const Cell& cell) const {
        return dense_ ? cell[0] + extent_[0] * (cell[1] + std::size_t{extent_[1]} * cell[2]) : hash_of(cell);
    }

    // One counting sort of the grid's bodies by group, in index order within each group.
    void list(const std::vector<Role>& roles, std::size_t listed) {
        const double cells = double(extent_[0]) * extent_[1] * extent_[2];
        dense_ = cells <= 4.0 * double(listed) + 64.0;
        groups_ = 16;
        while (groups_ < 2 * listed) groups_ *= 2;
        if (dense_) groups_ = static_cast<std::size_t>(cells);
        starts_.assign(groups_ + 1, 0);
        for (std::size_t k = 0; k < roles.size(); ++k)
            if (roles[k] == Role::grid) ++starts_[group_of(cells_[k]) + 1];
        for (std::size_t g = 1; g < starts_.size(); ++g) starts_[g] += starts_[g - 1];
        entries_.resize(listed);
        std::vector<std::uint32_t> next(starts_.begin(), starts_.end() - 1);
        for (std::size_t k = 0; k < roles.size(); ++k)
            if (roles[k] == Role::grid) entries_[next[group_of(cells_[k])]++] = static_cast<int>(k);
    }

    std::span<const std::optional<Bounds>> bounds_;
    Vec3 origin_;
    Vec3 inverse_size_;
    std::vector<Cell> cells_;            // by body: the cell holding its bounds' low corner (grid bodies)
    Cell extent_{0, 0, 0};               // cells along each axis, from the origin to the last low corner's
    bool dense_ = true;                  // the groups are the cells themselves (else hashes of them)
    std::size_t groups_ = 0;             // a power of two when hashed
    std::vector<std::uint32_t> starts_;  // group g lists entries_[starts_[g], starts_[g + 1])
    std::vector<int> entries_;           // the grid's bodies, by group, then by index
};

// Sorts the few bodies found for one body (a handful: insertion sort) and appends them as pairs.
void append_in_order(int body, std::vector<int>& found, std::vector<std::pair<int, int>>& out) {
    if (found.size() > 16) {
        std::sort(found.begin(), found.end());
    } else {
        for (std::size_t s = 1; s < found.size(); ++s)
            for (std::size_t t = s; t > 0 && found[t - 1] > found[t]; --t) std::swap(found[t - 1], found[t]);
    }
    for (const int other : found) out.emplace_back(body, other);
    found.clear();
}

}  // namespace

std::vector<std::pair<int, int>> overlapping_bounds(std::span<const std::optional<Bounds>> bounds) {
    std::vector<Role> roles(bounds.size(), Role::none);
    std::vector<double> sides;
    sides.reserve(bounds.size());
    for (std::size_t k = 0; k < bounds.size(); ++k)
        if (const auto& b = bounds[k]; b && b->low.allFinite() && b->high.allFinite()) {
            roles[k] = Role::grid;
            sides.push_back((b->high - b->low).maxCoeff());
        }
    if (sides.size() < 2) return {};
    const double large = large_side(sides);
    for (std::size_t k = 0, s = 0; k < bounds.size(); ++k)
        if (roles[k] == Role::grid && sides[s++] > large) roles[k] = Role::large;
    const Grid grid(bounds, roles);  // may make more bodies large
    std::vector<int> large_bodies;
    for (std::size_t k = 0; k < bounds.size(); ++k)
        if (roles[k] == Role::large) large_bodies.push_back(static_cast<int>(k));

    // Body by body in index order, the bodies after it that overlap it, in order: the pairs come out sorted.
    std::vector<std::pair<int, int>> pairs;
    pairs.reserve(4 * bounds.size());  // a box resting among boxes touches about six: half of them after it
    std::vector<int> found;
    for (int i = 0; i < static_cast<int>(bounds.size()); ++i) {
        const Role role = roles[static_cast<std::size_t>(i)];
        if (role == Role::none) continue;
        const Bounds& a = *bounds[static_cast<std::size_t>(i)];
        if (role == Role::grid) {
            grid.overlapping_after(i, found);
            for (const int j : large_bodies)
                if (j > i && overlap(a, *bounds[static_cast<std::size_t>(j)])) found.push_back(j);
        } else {  // a large body against every body after it
            for (int j = i + 1; j < static_cast<int>(bounds.size()); ++j)
                if (roles[static_cast<std::size_t>(j)] != Role::none &&
                    overlap(a, *bounds[static_cast<std::size_t>(j)]))
                    found.push_back(j);
        }
        append_in_order(i, found, pairs);
    }
    return pairs;
}

}  // namespace impulse
