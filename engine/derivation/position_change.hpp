#pragma once
// Step 8, interpenetration by nonlinear projection (the chapter's "Implementing Nonlinear Projection"):
// how much of a penetration each body removes by moving and by turning, and the moves that do it.
//
//   linear_inertia, angular_inertia, penetration_inertia  ->  linear_move, angular_move  ->  angular_limit
//   ->  linear_change (a translation) and angular_change (a rotation vector) per body.

#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "math/rotation.hpp"
#include "math/types.hpp"

namespace impulse {

struct PenetrationInertia {
    PerBody<double> linear_inertia;   // m^-1
    PerBody<double> angular_inertia;  // ((I^-1 (q_rel x n)) x q_rel) . n
    double penetration_inertia;       // sum of both over both bodies

    bool operator==(const PenetrationInertia&) const = default;
};

// "To resolve penetration we use exactly the same sequence of equations": the inertia along the normal is
// the per-unit-impulse chain of step 3, read as how readily each body gives way linearly and angularly.
PenetrationInertia penetration_inertia(const UnitImpulseChain& chain);

struct MoveSplit {
    PerBody<double> linear_move;   // distance the contact point moves along the normal by translation
    PerBody<double> angular_move;  // ... by rotation; body 1's moves are negative (it moves along -n)

    bool operator==(const MoveSplit&) const = default;
};

// Each body removes a share of the penetration in proportion to its linear and angular inertia:
// linear_move = +-penetration (m^-1 / total), angular_move = +-penetration (angular / total).
MoveSplit move_split(double penetration, const PenetrationInertia& inertia);

enum class AngularLimitPolicy {
    none,       // no limit
    fixed,      // |angular_move| <= factor (metres); the text's example is 0.5
    lever_arm,  // |angular_move| <= factor x the lever arm |q_rel - (q_rel . n) n|; reference engine: 0.2
    angle,      // the body turns through at most `factor` degrees (default 45), exactly
};

struct AngularLimitSettings {
    AngularLimitPolicy policy = AngularLimitPolicy::lever_arm;
    double factor = 0.2;  // meaning depends on the policy, see above

    bool operator==(const AngularLimitSettings&) const = default;
};

double default_angular_limit_factor(AngularLimitPolicy policy);

struct AngularLimit {
    AngularLimitPolicy policy;
    double factor;
    PerBody<double> maximum;  // largest |angular_move| allowed per body (empty with `none`)
    PerBody<bool> applied;    // the body's angular move was cut back to the maximum
    MoveSplit before;         // the moves before the limit

    bool operator==(const AngularLimit&) const = default;
};

// The moves after the angular limit, and the limit's record.
struct LimitedMoves {
    MoveSplit moves;
    AngularLimit limit;
};

// Cuts back any angular move of `moves` beyond its maximum and gives the excess to the same body's linear move,
// so each body's total move along the normal is kept and only its split changes ("we can transfer some of the
// burden from them onto the corresponding linearMove component"). A body that cannot translate (inverse mass
// 0, e.g. a pivot) takes no linear move: its excess is dropped, and the contact keeps that much penetration
// for a later iteration. (The reference engine would translate such an "infinitely heavy" body.)
LimitedMoves angular_limit(const MoveSplit& moves, const AngularLimitSettings& settings, const Vec3& normal,
                           const PerBody<Vec3>& relative_position, const UnitImpulseChain& chain,
                           OrientationUpdate orientation_update);

struct PositionChange {
    PerBody<Vec3> linear_change;   // n x linear_move: the translation applied
    PerBody<Vec3> angular_change;  // I^-1 (q_rel x n) x angular_move / angular_inertia: the rotation vector applied

    bool operator==(const PositionChange&) const = default;
};

// The rotation per unit move is the rotation per unit impulse divided by the angular inertia (the
// chapter's rotationPerMove); its (angular_change x q_rel) . n equals angular_move exactly.
PositionChange position_change(const MoveSplit& moves, const Vec3& normal, const UnitImpulseChain& chain);

}  // namespace impulse
