#pragma once
// Everything that chooses how contacts are resolved, in one struct that travels with each run (no global
// toggles). Presets fill it; a case file or flag may then change single fields.

#include "derivation/desired_delta_velocity.hpp"
#include "derivation/position_change.hpp"
#include "math/rotation.hpp"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace impulse {

enum class PhaseOrder { positions_first, velocities_first };

enum class PositionMethod {
    linear_projection,     // move the bodies apart along the normal only, in proportion to inverse mass
    nonlinear_projection,  // move and turn them, in proportion to linear and angular inertia (the book)
    velocity_based,        // move them back along their paths, then project whatever remains
    relaxation,            // nonlinear projection of a fraction of each contact's penetration per pass
};

enum class VelocityMethod {
    worst_first,  // the book: resolve the contact with the largest desired delta v, update the others
};

struct RelaxationSettings {
    double fraction = 0.5;  // share of a contact's current penetration removed when it is visited
    int passes = 4;         // each pass visits every contact above the epsilon once, worst first

    bool operator==(const RelaxationSettings&) const = default;
};

struct IterationLimits {
    int per_contact = 4;          // limit = per_contact x number of contacts, when no fixed limit is set
    std::optional<int> position;  // a fixed limit for the position phase
    std::optional<int> velocity;  // a fixed limit for the velocity phase

    bool operator==(const IterationLimits&) const = default;
};

struct ResolverSettings {
    std::string preset = "book";
    PhaseOrder phase_order = PhaseOrder::positions_first;
    PositionMethod position_method = PositionMethod::nonlinear_projection;
    VelocityMethod velocity_method = VelocityMethod::worst_first;
    AngularLimitSettings angular_limit{};
    RelaxationSettings relaxation{};
    double position_epsilon = 0.01;  // m: penetrations at or below this are left alone
    double velocity_epsilon = 0.01;  // m/s: desired velocity changes at or below this are left alone
    IterationLimits iterations{};
    VelocityRefinements refinements{};
    OrientationUpdate orientation_update = OrientationUpdate::first_order;
    double duration = 1.0 / 60.0;  // s: the frame the contacts come from (for the acceleration terms)

    bool operator==(const ResolverSettings&) const = default;
};

int position_iteration_limit(const ResolverSettings& settings, int contact_count);
int velocity_iteration_limit(const ResolverSettings& settings, int contact_count);

// The named presets:
//   book     the reference engine: positions then velocities, worst-first, epsilons 0.01, lever-arm limit
//            0.2, iterations 4 x contacts per phase, restitution cut-off 0.25 m/s, both acceleration
//            refinements, first-order orientation update then normalise.
//   chapter  the chapter's text as written: velocities then positions, delta v = -(1 + c) v_s with no
//            chapter-15 refinements, the text's fixed angular limit of 0.5; otherwise as book.
std::span<const std::string_view> preset_names();
std::optional<ResolverSettings> preset(std::string_view name);

}  // namespace impulse
