#pragma once
// The numbers a visit of the accumulating rows runs on (methods/contact_rows.hpp): one double, a visit of one contact,
// or four floats, a wide record's four pairs side by side (methods/wide_records.hpp). The row functions are written
// once over them: a comparison gives a mask (a bool, or four lanes of all ones or zeros), `select` takes a value lane
// by lane, and `any` asks whether a lane still needs a branch. For a double each is the plain operation, so the
// one-contact visit compiles to what it was written as.

#include "math/products.hpp"

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace impulse {

using Float4 = float __attribute__((vector_size(16)));
using Mask4 = std::int32_t __attribute__((vector_size(16)));

template <typename Real>
struct Lanes;

template <>
struct Lanes<double> {
    using Mask = bool;
    static constexpr double projection_tolerance = 1e-13;  // |lambda_t| within limit (1 + this) ends Newton's steps
    static constexpr double singular_tolerance = 0.0;      // K_tt is singular when det <= this k_11 k_22
};

template <>
struct Lanes<Float4> {
    using Mask = Mask4;
    static constexpr float projection_tolerance = 1e-6f;
    static constexpr float singular_tolerance = 1e-6f;
};

template <typename Real>
using MaskOf = typename Lanes<Real>::Mask;

IMPULSE_KERNEL double select(bool m, double a, double b) {
    return m ? a : b;
}

IMPULSE_KERNEL Float4 select(Mask4 m, Float4 a, Float4 b) {
    return reinterpret_cast<Float4>((reinterpret_cast<Mask4>(a) & m) | (reinterpret_cast<Mask4>(b) & ~m));
}

IMPULSE_KERNEL bool any(bool m) {
    return m;
}

IMPULSE_KERNEL bool any(Mask4 m) {
    return (m[0] | m[1] | m[2] | m[3]) != 0;
}

IMPULSE_KERNEL bool both(bool a, bool b) {
    return a && b;
}

IMPULSE_KERNEL Mask4 both(Mask4 a, Mask4 b) {
    return a & b;
}

IMPULSE_KERNEL bool negated(bool m) {
    return !m;
}

IMPULSE_KERNEL Mask4 negated(Mask4 m) {
    return ~m;
}

IMPULSE_KERNEL double square_root(double v) {
    return std::sqrt(v);
}

// Each lane's correctly rounded square root: sqrtps, or four sqrtss where there is no SSE; the same bits.
IMPULSE_KERNEL Float4 square_root(Float4 v) {
#if defined(__SSE__)
    return __builtin_ia32_sqrtps(v);
#else
    return Float4{std::sqrt(v[0]), std::sqrt(v[1]), std::sqrt(v[2]), std::sqrt(v[3])};
#endif
}

// Four 3-vectors, one a lane: what Vec3 is to a double, with the same accessors, so the derivation's inline step
// functions (step 4's point velocity, step 7's velocity change) run on either.
struct Vec3x4 {
    Float4 v[3];
    Float4 x() const { return v[0]; }
    Float4 y() const { return v[1]; }
    Float4 z() const { return v[2]; }
};

// Four symmetric 3x3 matrices (an inverse inertia a lane), read as m(i, j).
struct SymmetricMat3x4 {
    Float4 e[6];  // xx, xy, xz, yy, yz, zz
    Float4 operator()(int i, int j) const {
        constexpr int at[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
        return e[at[i][j]];
    }
};

// Four 3x3 matrices (a contact's basis, a body's turn, K), by columns, read and written as m(i, j).
struct Mat3x4 {
    Vec3x4 column[3];
    Float4 operator()(int i, int j) const { return column[j].v[i]; }
    Float4& operator()(int i, int j) { return column[j].v[i]; }
};

// The products of math/products.hpp, lane by lane: the same templates, so the same order of sums.
IMPULSE_KERNEL Vec3x4 cross(const Vec3x4& a, const Vec3x4& b) {
    return cross_of(a, b);
}

IMPULSE_KERNEL Float4 dot(const Vec3x4& a, const Vec3x4& b) {
    return dot_of(a, b);
}

IMPULSE_KERNEL Vec3x4 times(const SymmetricMat3x4& m, const Vec3x4& v) {
    return times_of(m, v);
}

IMPULSE_KERNEL Vec3x4 times(const Mat3x4& m, const Vec3x4& v) {
    return times_of(m, v);
}

IMPULSE_KERNEL Vec3x4 transposed_times(const Mat3x4& m, const Vec3x4& v) {
    return transposed_times_of(m, v);
}

template <typename Real>
IMPULSE_KERNEL Real splat(double v) {
    if constexpr (std::is_same_v<Real, double>)
        return v;
    else
        return Float4{float(v), float(v), float(v), float(v)};
}

}  // namespace impulse
