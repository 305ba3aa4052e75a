#include "derivation/avbd/dual_update.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

DualVariables dual_update(const ContactForce& force, const Stiffness& stiffness, const Vec3& constraint,
                          const PenaltyParameters& penalty) {
    DualVariables d{force.force, stiffness};  // lambda <- F  (Eq. 11)
    // k <- min(k + beta |C*|, k_max) inside the bounds  (Eq. 16)
    if (force.pushing)
        d.stiffness.normal =
            std::min(stiffness.normal + penalty.beta * std::abs(constraint.x()), penalty.stiffness_max);
    if (force.pushing && !force.sliding && force.block_stiffness.tangential > 0.0)
        d.stiffness.tangential =
            std::min(stiffness.tangential +
                         penalty.beta * std::sqrt(constraint.y() * constraint.y() + constraint.z() * constraint.z()),
                     penalty.stiffness_max);
    return d;
}

DualVariables warm_start(const std::optional<RememberedDual>& remembered, double friction, const AvbdSettings& settings,
                         const PenaltyParameters& penalty) {
    DualVariables d;
    d.stiffness = {penalty.stiffness_min, penalty.stiffness_min};
    if (!remembered) return d;
    const double keep = settings.post_stabilize ? 1.0 : settings.alpha * settings.gamma;  // (Eq. 19)
    Vec3 lambda = keep * remembered->lambda;
    // +0 for a remembered -0 too: std::max(-0.0, 0.0) is -0.0 by C++'s rule, and the WebAssembly build gave +0.0 there
    // (the determinism test); this form gives +0.0 on both.
    lambda.x() = lambda.x() > 0.0 ? lambda.x() : 0.0;
    const double bound = friction * lambda.x();
    const double size = std::sqrt(lambda.y() * lambda.y() + lambda.z() * lambda.z());
    if (size > bound) {
        const double scale = size > 0.0 ? bound / size : 0.0;
        lambda.y() *= scale;
        lambda.z() *= scale;
    }
    d.lambda = lambda;
    const auto decayed = [&](double k) {
        return std::clamp(settings.gamma * k, penalty.stiffness_min, penalty.stiffness_max);
    };
    d.stiffness = {decayed(remembered->stiffness.normal), decayed(remembered->stiffness.tangential)};
    return d;
}

}  // namespace impulse
