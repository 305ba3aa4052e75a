#pragma once
// AVBD's dual variables, per contact: lambda (N, contact coordinates, this project's sign: lambda_n >= 0 pushes)
// and the stiffness k (N/m, one for the normal row, one for the frictional pair).
//
// After every sweep over the bodies (AVBD's primal update), each contact's dual update (Eqs. 11, 16):
//   lambda <- F, the force its rows exert at the bodies' new positions (derivation/avbd/contact_force.hpp):
//             lambda_n <- max(lambda_n - k_n C*_n, 0), lambda_t <- lambda_t - k_t C*_t kept in |lambda_t| <= mu
//             lambda_n
//   k      <- min(k + beta |C*|, k_max), for a row whose lambda is strictly inside its bounds (a normal row that
//             pushes, a frictional pair that sticks): a constraint that is still violated grows stiffer, so the
//             next sweep enforces it harder; a bounded row's force is fixed by its bound, and stiffening it would
//             only slow the bodies down.
// The pair's |C*_t| is the length of its tangential part, so k_t does not depend on the tangents' direction.
//
// Across frames (Eq. 19), a contact found again in the contact memory starts from what it ended with:
//   lambda <- alpha gamma lambda,  k <- clamp(gamma k, k_min, k_max)
// gamma < 1 lets a stiffness that is no longer needed decay, and alpha takes out the share of lambda that held the
// penetration the stabilisation leaves. With post-stabilisation lambda is kept whole. A new contact
// starts at lambda = 0, k = k_min.
// beta, k_min and k_max are the contact's own: the settings' per-kilogram numbers times the mass of the lighter body
// it holds (derivation/avbd/mass_scaled_penalty.hpp).

#include "derivation/avbd/avbd_settings.hpp"
#include "derivation/avbd/contact_force.hpp"
#include "derivation/avbd/mass_scaled_penalty.hpp"

#include <optional>

namespace impulse {

struct DualVariables {
    Vec3 lambda = Vec3::Zero();  // contact coordinates (N)
    Stiffness stiffness;         // k_n, k_t (N/m)

    bool operator==(const DualVariables&) const = default;
};

// Eqs. 11 and 16, from the contact's force at the bodies' new positions and its constraint there.
DualVariables dual_update(const ContactForce& force, const Stiffness& stiffness, const Vec3& constraint,
                          const PenaltyParameters& penalty);

// What a contact remembered from last frame: its lambda already in this frame's contact coordinates, its stiffness.
struct RememberedDual {
    Vec3 lambda;
    Stiffness stiffness;
};

// Eq. 19: the frame's starting lambda and k (a new contact: `remembered` empty). The remembered lambda is first put
// back inside its bounds (a turned basis may have moved it out): lambda_n >= 0, |lambda_t| <= mu lambda_n. `settings`
// gives alpha, gamma and post_stabilize, `penalty` the contact's k_min and k_max.
DualVariables warm_start(const std::optional<RememberedDual>& remembered, double friction, const AvbdSettings& settings,
                         const PenaltyParameters& penalty);

}  // namespace impulse
