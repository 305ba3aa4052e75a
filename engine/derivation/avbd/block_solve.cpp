#include "derivation/avbd/block_solve.hpp"

namespace impulse {

BlockSolution block_solve(const BodyBlock& block) {
    const Mat6& H = block.block_matrix;
    // H = L D L^T, column by column: D_j = H_jj - sum_k<j L_jk^2 D_k, L_ij = (H_ij - sum_k<j L_ik L_jk D_k) / D_j.
    double L[6][6] = {};
    BlockSolution s;
    for (int j = 0; j < 6; ++j) {
        double d = H(j, j);
        for (int k = 0; k < j; ++k) d -= L[j][k] * L[j][k] * s.pivots[k];
        s.pivots[j] = d;
        for (int i = j + 1; i < 6; ++i) {
            double l = H(i, j);
            for (int k = 0; k < j; ++k) l -= L[i][k] * L[j][k] * s.pivots[k];
            L[i][j] = l / d;
        }
    }
    // L z = f, then D y = z, then L^T x = y.
    double x[6];
    for (int i = 0; i < 6; ++i) {
        double z = block.block_force[i];
        for (int k = 0; k < i; ++k) z -= L[i][k] * x[k];
        x[i] = z;
    }
    for (int i = 0; i < 6; ++i) x[i] /= s.pivots[i];
    for (int i = 5; i >= 0; --i)
        for (int k = i + 1; k < 6; ++k) x[i] -= L[k][i] * x[k];
    s.position_change = {{x[0], x[1], x[2]}, {x[3], x[4], x[5]}};
    return s;
}

}  // namespace impulse
