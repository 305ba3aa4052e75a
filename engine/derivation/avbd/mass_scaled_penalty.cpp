#include "derivation/avbd/mass_scaled_penalty.hpp"

#include <algorithm>

namespace impulse {

PenaltyParameters mass_scaled_penalty(const AvbdSettings& settings, const std::array<double, 2>& mass) {
    // The lighter of the bodies that translate: one massless side (the world, a static body) is left out.
    const double lighter = mass[0] > 0.0 && mass[1] > 0.0 ? std::min(mass[0], mass[1]) : std::max(mass[0], mass[1]);
    // Neither translates (a body that only turns, on the world): no mass to scale by, the settings as they are.
    const double m = lighter > 0.0 ? lighter : 1.0;
    // A 1 kg body gives m = 1 exactly, so its contacts keep the settings' numbers to the bit.
    return {m, m * settings.beta, m * settings.stiffness_min, m * settings.stiffness_max};
}

}  // namespace impulse
