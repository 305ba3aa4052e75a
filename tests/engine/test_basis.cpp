// Step 1: the contact basis is orthonormal and right-handed for every unit normal, with the stated tangent
// construction.

#include "derivation/basis.hpp"
#include "support/approx.hpp"
#if IMPULSE_HAVE_RAPIDCHECK  // property tests need rapidcheck (not in the engine-only build)
#include "support/property.hpp"
#include "support/random_contacts.hpp"
#endif

#include <vector>

using namespace impulse;
using namespace impulse::test;

namespace {

void check_orthonormal_right_handed(const Basis& b) {
    const Mat3& c = b.contact_to_world;
    CHECK_CLOSE(Mat3(c.transpose() * c), Mat3::Identity(), 1e-14);
    CHECK(c.determinant() == doctest::Approx(1.0).epsilon(1e-14));
    CHECK_CLOSE(Vec3(c.col(0)), b.normal(), 0.0);
    CHECK_CLOSE(Vec3(c.col(1).cross(c.col(2))), b.normal(), 1e-14);
}

// The 26 directions to the faces, edges and corners of a cube: the axes and every 45-degree diagonal,
// where the seed choice |n.x| > |n.y| is tied or flips.
std::vector<Vec3> cube_directions() {
    std::vector<Vec3> directions;
    for (int x = -1; x <= 1; ++x)
        for (int y = -1; y <= 1; ++y)
            for (int z = -1; z <= 1; ++z)
                if (x != 0 || y != 0 || z != 0) directions.push_back(Vec3(x, y, z).normalized());
    return directions;
}

}  // namespace

TEST_CASE("the ground normal gets tangents (0, 0, 1) and (1, 0, 0), as in the reference engine") {
    const Basis b = basis({0, 1, 0});
    CHECK(b.seed == TangentSeed::world_x);
    CHECK_CLOSE(b.tangent1(), Vec3(0, 0, 1), 0.0);
    CHECK_CLOSE(b.tangent2(), Vec3(1, 0, 0), 0.0);
}

TEST_CASE("a normal leaning towards X is crossed with world Y, and tangent 2 is still perpendicular") {
    // The reference engine's tangent 2 is wrong in exactly this branch (|n.x| > |n.y| with n.y != 0).
    const Basis b = basis(Vec3(0.8, 0.6, 0.0));
    CHECK(b.seed == TangentSeed::world_y);
    CHECK(b.tangent2().dot(b.normal()) == doctest::Approx(0.0));
    check_orthonormal_right_handed(b);
}

TEST_CASE("a tie |n.x| = |n.y| is crossed with world X") {
    CHECK(basis(Vec3(1, 1, 0).normalized()).seed == TangentSeed::world_x);
    CHECK(basis(Vec3(-1, 1, 1).normalized()).seed == TangentSeed::world_x);
}

TEST_CASE("the basis is orthonormal and right-handed on the axes and every 45-degree direction") {
    for (const Vec3& n : cube_directions()) {
        CAPTURE(n.transpose());
        check_orthonormal_right_handed(basis(n));
    }
}

#if IMPULSE_HAVE_RAPIDCHECK
TEST_CASE("the basis is orthonormal and right-handed for random normals") {
    check_property("basis orthonormal", [] {
        const Vec3 n = any_unit_vector();
        const Basis b = basis(n);
        const Mat3& c = b.contact_to_world;
        RC_ASSERT((c.transpose() * c - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-14);
        RC_ASSERT(std::abs(c.determinant() - 1.0) < 1e-14);
        RC_ASSERT((Vec3(c.col(0)) - n).norm() == 0.0);
    });
}
#endif
