#pragma once
// The block solve (AVBD, Eq. 4): body i moves by delta x_i = H_i^-1 f_i, one Newton step on its part of the
// implicit-Euler energy (derivation/avbd/body_block.hpp). H_i is symmetric positive definite by construction, so
// it factors as L D L^T with L unit lower triangular and every pivot in D positive, without pivoting (the
// reference demo's LDL^T, here on six coordinates: Chen's post on VBD for rigid bodies solves the same 6x6 system
// through the Schur complement of its 3x3 blocks, which is the same elimination grouped in threes).
// The contact's energy is quadratic in x_i while no bound changes, so the step lands on the minimum of G_i.

#include "derivation/avbd/body_block.hpp"
#include "derivation/avbd/implicit_euler.hpp"

namespace impulse {

struct BlockSolution {
    Vec6 pivots;                   // D of H = L D L^T: all positive
    Displacement position_change;  // delta x = H^-1 f: the move (m) and turn (rad) of this visit
};

BlockSolution block_solve(const BodyBlock& block);

}  // namespace impulse
