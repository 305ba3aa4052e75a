#include "derivation/position_change.hpp"

#include <cmath>
#include <optional>
#include <numbers>

namespace impulse {

PenetrationInertia penetration_inertia(const UnitImpulseChain& chain) {
    PenetrationInertia inertia;
    inertia.penetration_inertia = 0.0;
    for (int i = 0; i < 2; ++i) {
        if (!chain.bodies[i]) continue;
        inertia.linear_inertia[i] = chain.bodies[i]->linear_component;
        inertia.angular_inertia[i] = chain.bodies[i]->angular_component;
        inertia.penetration_inertia += *inertia.linear_inertia[i] + *inertia.angular_inertia[i];
    }
    return inertia;
}

MoveSplit move_split(double penetration, const PenetrationInertia& inertia) {
    MoveSplit moves;
    for (int i = 0; i < 2; ++i) {
        if (!inertia.linear_inertia[i]) continue;
        const double signed_penetration = body_sign(i) * penetration;
        // penetration x (share / total), as the reference engine groups it (the chapter multiplies by
        // 1/total; the two differ in the last bit).
        moves.linear_move[i] = signed_penetration * (*inertia.linear_inertia[i] / inertia.penetration_inertia);
        moves.angular_move[i] = signed_penetration * (*inertia.angular_inertia[i] / inertia.penetration_inertia);
    }
    return moves;
}

double default_angular_limit_factor(AngularLimitPolicy policy) {
    constexpr double factors[] = {0.0, 0.5, 0.2, 45.0};  // in the policies' order (see AngularLimitPolicy)
    return factors[static_cast<int>(policy)];
}

namespace {

// The largest |angular_move| the policy allows for one body; empty when the policy sets no limit.
std::optional<double> maximum_angular_move(const AngularLimitSettings& settings, const Vec3& normal, const Vec3& q_rel,
                                           const UnitImpulseResponse& response, OrientationUpdate orientation_update) {
    switch (settings.policy) {
        case AngularLimitPolicy::none:
            return std::nullopt;
        case AngularLimitPolicy::fixed:
            return settings.factor;
        case AngularLimitPolicy::lever_arm: {
            // The component of q_rel perpendicular to the normal is the lever arm the rotation works
            // through; a head-on contact has none, so all of its move becomes linear.
            const Vec3 lever_arm = q_rel - q_rel.dot(normal) * normal;
            return settings.factor * lever_arm.norm();
        }
        case AngularLimitPolicy::angle: {
            // The rotation vector is (I^-1 (q_rel x n)) angular_move / angular_inertia; its length must
            // not exceed the length that turns the body through `factor` degrees under the orientation
            // update in use, so |angular_move| <= that length x angular_inertia / |I^-1 (q_rel x n)|.
            // A body that cannot turn about this axis has no angular move to limit.
            const double per_unit_move = response.rotation_per_unit_impulse.norm();
            if (per_unit_move == 0.0) return 0.0;
            const double max_rotation =
                rotation_magnitude_for_angle(settings.factor * std::numbers::pi / 180.0, orientation_update);
            return max_rotation * std::abs(response.angular_component) / per_unit_move;
        }
    }
    return std::nullopt;
}

}  // namespace

LimitedMoves angular_limit(const MoveSplit& moves, const AngularLimitSettings& settings, const Vec3& normal,
                           const PerBody<Vec3>& relative_position, const UnitImpulseChain& chain,
                           OrientationUpdate orientation_update) {
    LimitedMoves out{moves, {settings.policy, settings.factor, {}, {}, moves}};
    AngularLimit& limit = out.limit;
    for (int i = 0; i < 2; ++i) {
        if (!moves.angular_move[i]) continue;
        limit.maximum[i] =
            maximum_angular_move(settings, normal, *relative_position[i], *chain.bodies[i], orientation_update);
        const double angular = *moves.angular_move[i];
        limit.applied[i] = limit.maximum[i] && std::abs(angular) > *limit.maximum[i];
        if (*limit.applied[i]) {
            const double total_move = *moves.linear_move[i] + angular;
            out.moves.angular_move[i] = std::copysign(*limit.maximum[i], angular);
            if (chain.bodies[i]->linear_component > 0.0)
                out.moves.linear_move[i] = total_move - *out.moves.angular_move[i];
        }
    }
    return out;
}

PositionChange position_change(const MoveSplit& moves, const Vec3& normal, const UnitImpulseChain& chain) {
    const std::array<bool, 2> bodies = present(moves.linear_move);
    return {.linear_change = per_body(bodies, [&](int i) -> Vec3 { return normal * *moves.linear_move[i]; }),
            .angular_change = per_body(bodies, [&](int i) -> Vec3 {
                const double angular_move = *moves.angular_move[i];
                const UnitImpulseResponse& response = *chain.bodies[i];
                // Zero when there is nothing to turn (also guards the division for a body that cannot rotate).
                return angular_move == 0.0
                           ? Vec3::Zero()
                           : Vec3(response.rotation_per_unit_impulse * (angular_move / response.angular_component));
            })};
}

}  // namespace impulse
