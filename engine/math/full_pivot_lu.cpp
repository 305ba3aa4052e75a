#include "math/full_pivot_lu.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace impulse {

namespace {

// Step p of the elimination on `a` (row-major working copy); false when the corner from (p, p) on is all zero.
// A template so each step's loops have fixed bounds and unroll: the three steps are the whole cost.
template <int p>
bool eliminate(double (&a)[3][3], std::array<int, 3>& row_of, std::array<int, 3>& column_of, double& largest_pivot) {
    // The pivot: the largest |entry| of the corner below and right of (p, p), searched column by column,
    // top to bottom, the first one kept on a tie (a NaN at (p, p) stays the pivot: nothing compares above it).
    int pivot_row = p, pivot_column = p;
    double biggest = std::abs(a[p][p]);
    for (int c = p; c < 3; ++c)
        for (int r = p; r < 3; ++r)
            if (std::abs(a[r][c]) > biggest) {
                biggest = std::abs(a[r][c]);
                pivot_row = r;
                pivot_column = c;
            }
    if (biggest == 0.0) return false;
    if (biggest > largest_pivot) largest_pivot = biggest;
    std::swap(row_of[p], row_of[static_cast<std::size_t>(pivot_row)]);
    std::swap(column_of[p], column_of[static_cast<std::size_t>(pivot_column)]);
    if (pivot_row != p)
        for (int c = 0; c < 3; ++c) std::swap(a[p][c], a[pivot_row][c]);
    if (pivot_column != p)
        for (int r = 0; r < 3; ++r) std::swap(a[r][p], a[r][pivot_column]);

    // Eliminate below the pivot: the multipliers l_rp = k_rp / k_pp (a division, not a product with the
    // reciprocal), then k_rc -= l_rp k_pc on the remaining corner.
    for (int r = p + 1; r < 3; ++r) a[r][p] /= a[p][p];
    for (int r = p + 1; r < 3; ++r)
        for (int c = p + 1; c < 3; ++c) a[r][c] -= a[r][p] * a[p][c];
    return true;
}

}  // namespace

FullPivotLu3::FullPivotLu3(const Mat3& k) {
    double a[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) a[r][c] = k(r, c);
    nonzero_pivots_ = !eliminate<0>(a, row_of_, column_of_, largest_pivot_)   ? 0
                      : !eliminate<1>(a, row_of_, column_of_, largest_pivot_) ? 1
                      : !eliminate<2>(a, row_of_, column_of_, largest_pivot_) ? 2
                                                                              : 3;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) lu_(r, c) = a[r][c];
}

bool FullPivotLu3::invertible() const {
    const double threshold = std::abs(largest_pivot_) * (std::numeric_limits<double>::epsilon() * 3.0);
    int rank = 0;
    for (int i = 0; i < nonzero_pivots_; ++i) rank += std::abs(lu_(i, i)) > threshold;
    return rank == 3;
}

Vec3 FullPivotLu3::solve(const Vec3& b) const {
    // P b: b's entries in the order of the rows of L U.
    double c0 = b[row_of_[0]], c1 = b[row_of_[1]], c2 = b[row_of_[2]];
    // L y = P b, column by column; a zero entry contributes nothing and is skipped (as Eigen does, which keeps
    // the sign of a zero and a 0 x infinity out of the sum).
    if (c0 != 0.0) {
        c1 -= c0 * lu_(1, 0);
        c2 -= c0 * lu_(2, 0);
    }
    if (c1 != 0.0) c2 -= c1 * lu_(2, 1);
    // U z = y, from the last row up, column by column.
    if (c2 != 0.0) {
        c2 /= lu_(2, 2);
        c0 -= c2 * lu_(0, 2);
        c1 -= c2 * lu_(1, 2);
    }
    if (c1 != 0.0) {
        c1 /= lu_(1, 1);
        c0 -= c1 * lu_(0, 1);
    }
    if (c0 != 0.0) c0 /= lu_(0, 0);
    // x = Q z: z's entries back in the order of K's columns.
    Vec3 x;
    x[column_of_[0]] = c0;
    x[column_of_[1]] = c1;
    x[column_of_[2]] = c2;
    return x;
}

}  // namespace impulse
