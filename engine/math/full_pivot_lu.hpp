#pragma once
// K x = b for a 3x3 K by Gaussian elimination with complete pivoting: the solve of the friction impulse
// (derivation/impulse.hpp), P K Q = L U with L unit lower triangular, U upper triangular, and P, Q the row
// and column exchanges that bring the largest remaining entry to the diagonal at every step.
//
// Why our own: the friction impulse used Eigen's FullPivLU, whose general-size code costs ~1200 instructions
// for one 3x3 factorisation and solve (a fifth of a book frame on a large scene). This does the same
// operations on the same numbers in the same order, written out for three rows, so every bit of every
// trace stays as it was: tests/engine/test_full_pivot_lu.cpp compares it with Eigen's, bit for bit, on
// random, singular, rank-deficient, tied and signed-zero matrices. Where Eigen's order is not the obvious
// one, the code says so.

#include "math/types.hpp"

#include <array>

namespace impulse {

class FullPivotLu3 {
public:
    explicit FullPivotLu3(const Mat3& k);

    // K has three pivots above the rounding threshold |largest pivot| x 3 epsilon (Eigen's default, from
    // Higham): a solution exists and is unique.
    bool invertible() const;

    // x with K x = b. Meaningful only when invertible().
    Vec3 solve(const Vec3& b) const;

    const Mat3& factors() const { return lu_; }  // L below the diagonal (its unit diagonal not stored), U on and above

private:
    Mat3 lu_;
    std::array<int, 3> row_of_{0, 1, 2};     // P: row i of L U is row row_of_[i] of K
    std::array<int, 3> column_of_{0, 1, 2};  // Q: column j of L U is column column_of_[j] of K
    int nonzero_pivots_ = 3;                 // steps done before the remaining corner was all zero
    double largest_pivot_ = 0.0;
};

}  // namespace impulse
