// The broad phase's grid against the definition it must meet: every pair (i < j) of usable bounds that overlap,
// faces touching included, in (i, j) order, checked against all n^2/2 pairs on random scenes built to reach each
// of its paths (cells listed directly and hashed, large bodies, clamped far cells, bounds of zero size).

#include "collision/broad_phase.hpp"

#include <cmath>
#include <limits>
#include <random>

using namespace impulse;

namespace {

using Pairs = std::vector<std::pair<int, int>>;

bool usable(const std::optional<Bounds>& b) {
    return b && b->low.allFinite() && b->high.allFinite();
}

// The definition, pair by pair.
template <typename Skip>
Pairs every_overlapping_pair(const std::vector<std::optional<Bounds>>& bounds, Skip skip) {
    Pairs pairs;
    for (std::size_t i = 0; i < bounds.size(); ++i)
        for (std::size_t j = i + 1; j < bounds.size(); ++j) {
            const auto& a = bounds[i];
            const auto& b = bounds[j];
            if (usable(a) && usable(b) && (a->low.array() <= b->high.array()).all() &&
                (b->low.array() <= a->high.array()).all() && !skip(int(i), int(j)))
                pairs.emplace_back(int(i), int(j));
        }
    return pairs;
}

Pairs grid_pairs(const std::vector<std::optional<Bounds>>& bounds) {
    return overlapping_pairs(std::span<const std::optional<Bounds>>(bounds), [](int, int) { return false; });
}

// A random scene of one kind: the bodies' bounds, with some bodies shapeless and some not finite.
class Scenes {
public:
    explicit Scenes(std::uint64_t seed) : random_(seed) {}

    std::vector<std::optional<Bounds>> scene(int kind) {
        std::vector<std::optional<Bounds>> bounds;
        const int count = integer(0, 150);
        for (int k = 0; k < count; ++k) bounds.push_back(body(kind));
        for (auto& b : bounds) {  // spoil a few: no shape, a NaN, an infinity
            const int spoil = integer(0, 40);
            if (spoil == 0) b.reset();
            if (spoil == 1 && b) b->low[integer(0, 2)] = std::numeric_limits<double>::quiet_NaN();
            if (spoil == 2 && b) b->high[integer(0, 2)] = std::numeric_limits<double>::infinity();
        }
        return bounds;
    }

    static constexpr int kinds = 7;

private:
    std::optional<Bounds> body(int kind) {
        switch (kind) {
            case 0:  // boxes and spheres of mixed sizes in a 6 m cube, turned any way
                return shaped(uniform(0.05, 1.0), 3.0);
            case 1: {  // unit cubes on a lattice: faces touch exactly, and many sit on the cells' walls
                const Vec3 corner(integer(0, 5), integer(0, 5), integer(0, 2));
                return Bounds{corner, corner + Vec3::Ones()};
            }
            case 2:  // small bodies with a long plank, a ground slab and a wall among them (large bodies)
                switch (integer(0, 12)) {
                    case 0:
                        return world_bounds(Box{Vec3(10.0, 0.1, 0.5)}, position(3.0), rotation());
                    case 1:
                        return Bounds{Vec3(-50.0, -1.0, -50.0), Vec3(50.0, 0.0, 50.0)};
                    case 2:
                        return Bounds{Vec3(-3.0, -3.0, 2.0), Vec3(3.0, 3.0, 2.5)};
                    default:
                        return shaped(uniform(0.05, 0.6), 3.0);
                }
            case 3:  // small bodies spread over a kilometre: too many cells to list, so they are hashed
                return shaped(uniform(0.05, 2.0), integer(0, 1) == 0 ? 500.0 : 2.0);
            case 4: {  // all at a few spots, some of them bounds of no size
                const Vec3 spot(integer(0, 2), 0.0, 0.0);
                if (integer(0, 3) == 0) return Bounds{spot, spot};
                return world_bounds(Sphere{uniform(0.1, 1.0)}, spot, Mat3::Identity());
            }
            case 5: {  // points and flat tiles: sides of zero along some axes
                const Vec3 low = position(2.0);
                Vec3 high = low;
                for (int a = 0; a < 3; ++a)
                    if (integer(0, 1) == 0) high[a] += uniform(0.0, 1.0);
                return Bounds{low, high};
            }
            default:  // a cluster, and a body far off (1e12 m, 1e300 m): cells clamped to the last one
                if (integer(0, 20) == 0) return shaped(1.0, integer(0, 1) == 0 ? 1e12 : 1e300);
                return shaped(uniform(0.1, 1.0), 4.0);
        }
    }

    Bounds shaped(double size, double spread) {
        const Shape shape = integer(0, 1) == 0 ? Shape(Sphere{size})
                                               : Shape(Box{Vec3(size, uniform(0.05, 1.0) * size, uniform(0.2, 1.0))});
        return world_bounds(shape, position(spread), rotation());
    }

    Vec3 position(double spread) {
        return Vec3(uniform(-spread, spread), uniform(-spread, spread), uniform(-spread, spread));
    }

    Mat3 rotation() {
        Quat q(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
        if (q.norm() < 1e-3) return Mat3::Identity();
        return q.normalized().toRotationMatrix();
    }

    double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(random_); }
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(random_); }

    std::mt19937_64 random_;
};

}  // namespace

TEST_CASE("the broad phase finds exactly the pairs whose bounds overlap, in order, on random scenes of every kind") {
    Scenes scenes(20261127);
    for (int round = 0; round < 60; ++round)
        for (int kind = 0; kind < Scenes::kinds; ++kind) {
            const auto bounds = scenes.scene(kind);
            CAPTURE(round);
            CAPTURE(kind);
            REQUIRE(grid_pairs(bounds) == every_overlapping_pair(bounds, [](int, int) { return false; }));
        }
}

TEST_CASE("the broad phase leaves out the pairs the caller skips, and keeps the rest in order") {
    Scenes scenes(7);
    const auto skip = [](int i, int j) { return i % 3 == 0 && j % 2 == 0; };
    for (int kind = 0; kind < Scenes::kinds; ++kind) {
        const auto bounds = scenes.scene(kind);
        CAPTURE(kind);
        CHECK(overlapping_pairs(std::span<const std::optional<Bounds>>(bounds), skip) ==
              every_overlapping_pair(bounds, skip));
    }
}

TEST_CASE("boxes stacked in a pyramid touch their neighbours face to face and nothing else") {
    // Rows of unit cubes, each row half a cube along from the one below (Box3D's large pyramid, 10 rows): a cube
    // touches the one or two beside it, the two below it and the two above it, and no cube two rows away.
    std::vector<std::optional<Bounds>> bounds;
    for (int row = 0; row < 10; ++row)
        for (int k = 0; k < 10 - row; ++k) {
            const Vec3 low(0.5 * row + k, row, 0.0);
            bounds.push_back(Bounds{low, low + Vec3::Ones()});
        }
    const Pairs pairs = grid_pairs(bounds);
    CHECK(pairs == every_overlapping_pair(bounds, [](int, int) { return false; }));
    // Beside: 9 + 8 + ... + 1 + 0 = 45. Below and above: each cube above the first row sits on two: 2 (9 + ... + 1).
    CHECK(pairs.size() == 45 + 90);
}
