#pragma once
// The velocity-level position correction shared by Baumgarte stabilisation and the split impulse: instead of
// moving the bodies, ask the contact to separate at a speed that would close a share of the penetration
// within one frame. Baumgarte (1972) for constraint drift; in games Catto's sequential impulses and Bullet.
//
//   position_bias = beta x max(penetration - slop, 0) / h
//
// beta (`factor`) is the share removed per frame, the slop the penetration left alone so resting contacts do
// not jitter between touching and separating, h the frame duration.

#include "settings/settings.hpp"

#include <algorithm>

namespace impulse {

inline double position_bias(double penetration, const PositionBiasSettings& bias, double duration) {
    return bias.factor * std::max(penetration - bias.slop, 0.0) / duration;
}

}  // namespace impulse
