// The friction impulse's 3x3 solve against Eigen's FullPivLU, which it replaces: the same factors, the same
// invertibility verdict and the same solution, bit for bit (signed zeros included), on matrices chosen to
// hit every branch: random, integer with many ties and zeros, singular, rank one, zero, non-finite, and the
// delta velocity matrices of random contacts.

#include "derivation/impulse.hpp"
#include "math/full_pivot_lu.hpp"
#include "preparation/prepared_contact.hpp"
#if IMPULSE_HAVE_RAPIDCHECK  // property tests need rapidcheck (not in the engine-only build)
#include "support/random_contacts.hpp"
#endif

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <random>

using namespace impulse;

namespace {

bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

bool same_bits(const Mat3& a, const Mat3& b) {
    for (int i = 0; i < 9; ++i)
        if (!same_bits(a.data()[i], b.data()[i])) return false;
    return true;
}

bool same_bits(const Vec3& a, const Vec3& b) {
    return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}

// Eigen's FullPivLU at either alignment of its matrix (Eigen's vector kernels take a different path on a
// 16-byte boundary; the results must not depend on it).
static_assert(alignof(Eigen::FullPivLU<Mat3>) <= 8, "the offset-8 copy below must be properly aligned");

template <std::size_t Offset>
struct EigenLu {
    alignas(16) unsigned char storage[sizeof(Eigen::FullPivLU<Mat3>) + 16];
    Eigen::FullPivLU<Mat3>& lu;
    explicit EigenLu(const Mat3& k) : lu(*new (storage + Offset) Eigen::FullPivLU<Mat3>(k)) {}
    ~EigenLu() { lu.~FullPivLU(); }
    EigenLu(const EigenLu&) = delete;
    EigenLu& operator=(const EigenLu&) = delete;
};

// Checks one matrix with a few right-hand sides; returns whether everything agreed.
template <std::size_t Offset>
bool agrees_with_eigen_at(const Mat3& k, const std::vector<Vec3>& targets) {
    const EigenLu<Offset> eigen(k);
    const FullPivotLu3 ours(k);
    CAPTURE(k);
    CHECK(same_bits(ours.factors(), eigen.lu.matrixLU()));
    CHECK(ours.invertible() == eigen.lu.isInvertible());
    if (!same_bits(ours.factors(), eigen.lu.matrixLU()) || ours.invertible() != eigen.lu.isInvertible()) return false;
    if (!ours.invertible()) return true;
    for (const Vec3& b : targets) {
        const Vec3 expected = eigen.lu.solve(b);
        const Vec3 x = ours.solve(b);
        CAPTURE(b);
        CHECK(same_bits(x, expected));
        if (!same_bits(x, expected)) return false;
    }
    return true;
}

bool agrees_with_eigen(const Mat3& k, const std::vector<Vec3>& targets) {
    return agrees_with_eigen_at<0>(k, targets) && agrees_with_eigen_at<8>(k, targets);
}

std::vector<Vec3> some_targets(std::mt19937& random) {
    std::uniform_real_distribution<double> any(-3.0, 3.0);
    return {Vec3(any(random), any(random), any(random)), Vec3(1.0, 0.0, -0.0), Vec3(-0.0, -0.0, 2.5),
            Vec3(0.0, 0.0, 0.0), Vec3(any(random), 0.0, -0.0)};
}

}  // namespace

TEST_CASE("the 3x3 full-pivot solve matches Eigen's FullPivLU bit for bit on random matrices") {
    std::mt19937 random(2024);
    std::uniform_real_distribution<double> any(-10.0, 10.0);
    int agreed = 0;
    for (int n = 0; n < 20000; ++n) {
        Mat3 k;
        for (int i = 0; i < 9; ++i) k.data()[i] = any(random);
        if (n % 2 == 0) k = (k * k.transpose()).eval();  // symmetric positive semi-definite, like K
        agreed += agrees_with_eigen(k, some_targets(random));
    }
    CHECK(agreed == 20000);
}

TEST_CASE("the 3x3 full-pivot solve matches Eigen's FullPivLU on ties, zeros of both signs and singular matrices") {
    // Entries from {-2, -1, -0, +0, 1, 2}: pivots tie often (the first in column order must win), whole
    // corners vanish (rank 0, 1, 2), and products of signed zeros decide the sign of zeros in U.
    std::mt19937 random(99);
    const double levels[] = {-2.0, -1.0, -0.0, 0.0, 1.0, 2.0};
    int agreed = 0, invertible = 0;
    const int count = 40000;
    for (int n = 0; n < count; ++n) {
        Mat3 k;
        for (int i = 0; i < 9; ++i) k.data()[i] = levels[random() % 6];
        agreed += agrees_with_eigen(k, some_targets(random));
        invertible += FullPivotLu3(k).invertible();
    }
    CHECK(agreed == count);
    CHECK(invertible > count / 10);  // both outcomes are exercised
    CHECK(invertible < count - count / 10);
}

TEST_CASE("the 3x3 full-pivot solve matches Eigen's FullPivLU on nearly singular and non-finite matrices") {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    std::mt19937 random(5);
    const std::vector<Mat3> special = [&] {
        std::vector<Mat3> m;
        Mat3 a;
        a << 1, 2, 3, 2, 4, 6, 1, 1, 1;  // rank 2
        m.push_back(a);
        a << 1, 2, 3, 2, 4, 6 + 1e-15, 1, 1, 1;  // rank 3 only by rounding: below the threshold
        m.push_back(a);
        a << 1e-300, 0, 0, 0, 1e300, 0, 0, 0, 1;  // pivots 300 orders apart
        m.push_back(a);
        m.push_back(Mat3::Zero());
        m.push_back(-Mat3::Zero());
        a << nan, 1, 2, 3, 4, 5, 6, 7, 8;  // a NaN where the first pivot search starts
        m.push_back(a);
        a << 1, 2, 3, 4, nan, 5, 6, 7, 8;
        m.push_back(a);
        a << inf, 1, 2, 3, 4, 5, 6, 7, 8;
        m.push_back(a);
        a << 1, 2, 3, 4, 5, 6, 7, 8, -inf;
        m.push_back(a);
        return m;
    }();
    for (const Mat3& k : special) CHECK(agrees_with_eigen(k, some_targets(random)));
}

#if IMPULSE_HAVE_RAPIDCHECK
TEST_CASE("the 3x3 full-pivot solve matches Eigen's FullPivLU on the delta velocity matrices of random contacts") {
    std::mt19937 random(11);
    rc::check([&random] {
        const test::RandomContact r = test::any_contact();
        const std::vector<MassProperties> mass = mass_properties(r.bodies);
        std::pmr::vector<PreparedContact> one;
        prepare_contacts({&r.contact, 1}, r.bodies, mass, ResolverSettings{}, one);
        const PreparedContact& p = one.front();
        const Mat3 k = delta_velocity_matrix(p.basis, p.relative_position, contact_mass(p, mass));
        RC_ASSERT(agrees_with_eigen(k, some_targets(random)));
    });
}
#endif
