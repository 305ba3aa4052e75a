#include "resolver/settings.hpp"

#include <algorithm>
#include <array>

namespace impulse {

int position_iteration_limit(const ResolverSettings& settings, int contact_count) {
    return settings.iterations.position.value_or(settings.iterations.per_contact * contact_count);
}

int velocity_iteration_limit(const ResolverSettings& settings, int contact_count) {
    return settings.iterations.velocity.value_or(settings.iterations.per_contact * contact_count);
}

namespace {
constexpr std::array<std::string_view, 2> names{"book", "chapter"};
}

std::span<const std::string_view> preset_names() {
    return names;
}

std::optional<ResolverSettings> preset(std::string_view name) {
    ResolverSettings s;  // the defaults are the book preset
    if (name == "book") return s;
    if (name == "chapter") {
        s.preset = "chapter";
        s.phase_order = PhaseOrder::velocities_first;
        s.angular_limit = {AngularLimitPolicy::fixed, default_angular_limit_factor(AngularLimitPolicy::fixed)};
        s.refinements = {0.0, false, false};
        return s;
    }
    return std::nullopt;
}

}  // namespace impulse
