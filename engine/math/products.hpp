#pragma once
// The vector and matrix products of the derivation steps, in plain doubles, inline: the kernel every method and
// the recorder compute through (derivation/*.hpp), so a hot loop keeps its values in registers (Eigen's packed
// arithmetic on 3-vectors mixes 16- and 8-byte loads and stores of the same values, which stalls a loop) and
// every build computes the same bits, vectorised or not.
//
// Each sums its products in the order Eigen 3.4 evaluates the same expression in its scalar code (the engine is
// built with EIGEN_DONT_VECTORIZE, engine/CMakeLists.txt), so the book's traces keep every bit whether a step is
// written with Eigen's expressions or with these (checked on every shipped scene and case: the order decides the
// last bit, and which zero a sum of zeros gives). Eigen sums three products by halves, the first alone and the
// last two together: a0 b0 + (a1 b1 + a2 b2), for a dot product and for every entry of a matrix product.

#include "math/types.hpp"

#include <type_traits>

// Always inlined: they are a few multiplications each, and called in every visit of the solvers' loops (GCC and
// clang would otherwise keep some out of line at -O2, and a 3x3 matrix would go through memory).
#define IMPULSE_KERNEL [[gnu::always_inline]] inline

namespace impulse {

// Each product is written once over its vector type V (x(), y(), z(), built from three numbers) and matrix type M
// (m(i, j), read and written): a Vec3 and a Mat3 here, or four of each side by side (math/lanes.hpp: a wide record's
// lanes), so every lane sums in the order a double does.

// a x b
template <typename V>
IMPULSE_KERNEL V cross_of(const V& a, const V& b) {
    return {a.y() * b.z() - a.z() * b.y(), a.z() * b.x() - a.x() * b.z(), a.x() * b.y() - a.y() * b.x()};
}

// a . b = a0 b0 + (a1 b1 + a2 b2)
template <typename V>
IMPULSE_KERNEL auto dot_of(const V& a, const V& b) {
    return a.x() * b.x() + (a.y() * b.y() + a.z() * b.z());
}

// m v
template <typename M, typename V>
IMPULSE_KERNEL V times_of(const M& m, const V& v) {
    return {m(0, 0) * v.x() + (m(0, 1) * v.y() + m(0, 2) * v.z()),
            m(1, 0) * v.x() + (m(1, 1) * v.y() + m(1, 2) * v.z()),
            m(2, 0) * v.x() + (m(2, 1) * v.y() + m(2, 2) * v.z())};
}

// m^T v: each column of m dotted with v
template <typename M, typename V>
IMPULSE_KERNEL V transposed_times_of(const M& m, const V& v) {
    return {m(0, 0) * v.x() + (m(1, 0) * v.y() + m(2, 0) * v.z()),
            m(0, 1) * v.x() + (m(1, 1) * v.y() + m(2, 1) * v.z()),
            m(0, 2) * v.x() + (m(1, 2) * v.y() + m(2, 2) * v.z())};
}

// [r]x, the matrix with [r]x g = r x g.
template <typename M, typename V>
IMPULSE_KERNEL M skew_of(const V& r) {
    const auto zero = std::remove_cvref_t<decltype(r.x())>{};
    M m;
    m(0, 0) = zero, m(0, 1) = -r.z(), m(0, 2) = r.y();
    m(1, 0) = r.z(), m(1, 1) = zero, m(1, 2) = -r.x();
    m(2, 0) = -r.y(), m(2, 1) = r.x(), m(2, 2) = zero;
    return m;
}

// a b (written entry by entry: a loop over the entries is not unrolled at -O2, and costs three times as much)
template <typename M, typename A, typename B>
IMPULSE_KERNEL M product_of(const A& a, const B& b) {
    const auto entry = [&](int i, int j) { return a(i, 0) * b(0, j) + (a(i, 1) * b(1, j) + a(i, 2) * b(2, j)); };
    M c;
    c(0, 0) = entry(0, 0), c(1, 0) = entry(1, 0), c(2, 0) = entry(2, 0);
    c(0, 1) = entry(0, 1), c(1, 1) = entry(1, 1), c(2, 1) = entry(2, 1);
    c(0, 2) = entry(0, 2), c(1, 2) = entry(1, 2), c(2, 2) = entry(2, 2);
    return c;
}

// a^T b
template <typename M, typename A, typename B>
IMPULSE_KERNEL M transposed_product_of(const A& a, const B& b) {
    const auto entry = [&](int i, int j) { return a(0, i) * b(0, j) + (a(1, i) * b(1, j) + a(2, i) * b(2, j)); };
    M c;
    c(0, 0) = entry(0, 0), c(1, 0) = entry(1, 0), c(2, 0) = entry(2, 0);
    c(0, 1) = entry(0, 1), c(1, 1) = entry(1, 1), c(2, 1) = entry(2, 1);
    c(0, 2) = entry(0, 2), c(1, 2) = entry(1, 2), c(2, 2) = entry(2, 2);
    return c;
}

IMPULSE_KERNEL Vec3 cross(const Vec3& a, const Vec3& b) {
    return cross_of(a, b);
}

IMPULSE_KERNEL Mat3 skew(const Vec3& r) {
    return skew_of<Mat3>(r);
}

IMPULSE_KERNEL double dot(const Vec3& a, const Vec3& b) {
    return dot_of(a, b);
}

IMPULSE_KERNEL Vec3 times(const Mat3& m, const Vec3& v) {
    return times_of(m, v);
}

IMPULSE_KERNEL Vec3 transposed_times(const Mat3& m, const Vec3& v) {
    return transposed_times_of(m, v);
}

IMPULSE_KERNEL Mat3 product(const Mat3& a, const Mat3& b) {
    return product_of<Mat3>(a, b);
}

IMPULSE_KERNEL Mat3 transposed_product(const Mat3& a, const Mat3& b) {
    return transposed_product_of<Mat3>(a, b);
}

}  // namespace impulse
