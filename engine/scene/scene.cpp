#include "scene/scene.hpp"

#include <algorithm>
#include <cmath>

namespace impulse {

Material combine(const Material& a, const Material& b) {
    return {std::max(a.restitution, b.restitution), std::sqrt(a.friction * b.friction)};
}

}  // namespace impulse
