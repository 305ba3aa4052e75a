#include "settings/settings.hpp"

#include <algorithm>
#include <array>

namespace impulse {

namespace {
constexpr std::array<std::string_view, 10> names{
    "book",           "chapter", "sweep", "pgs", "pgs_split", "soft_step", "soft_step_recycled", "soft_step_coloured",
    "soft_step_wide", "avbd"};
}

std::span<const std::string_view> preset_names() {
    return names;
}

std::string preset_list_text() {
    std::string text;
    for (const std::string_view name : names) text += (text.empty() ? "\"" : ", \"") + std::string(name) + "\"";
    return text;
}

std::optional<ResolverSettings> preset(std::string_view name) {
    ResolverSettings s;  // the defaults are the book preset
    if (name == "book") return s;
    if (name == "chapter") {
        s.preset = "chapter";
        s.phase_order = PhaseOrder::velocities_first;
        s.angular_limit = {AngularLimitPolicy::fixed, default_angular_limit_factor(AngularLimitPolicy::fixed)};
        s.restitution_cutoff = 0.0;
        s.velocity_from_acceleration = false;
        s.tangential_acceleration_velocity = false;
        return s;
    }
    s.preset = std::string(name);
    if (name == "sweep") {
        s.velocity_method = VelocityMethod::sequential_sweep;
        return s;
    }
    if (name == "pgs" || name == "pgs_split") {
        s.velocity_method = VelocityMethod::projected_gauss_seidel;
        s.position_method = name == "pgs" ? PositionMethod::none : PositionMethod::split_impulse;
        s.baumgarte = name == "pgs";
        // Bullet: ERP 0.2 for Baumgarte; its split impulse pushes with ERP2 0.8 on the pseudo-velocities.
        s.position_bias.factor = name == "pgs" ? 0.2 : 0.8;
        return s;
    }
    if (name == "soft_step" || name == "soft_step_recycled" || name == "soft_step_coloured" ||
        name == "soft_step_wide") {
        s.velocity_method = VelocityMethod::soft_step;
        s.position_method = PositionMethod::none;  // the soft contact carries its own push (see SoftStepSettings)
        s.sweeps = 1;
        if (name != "soft_step") {
            // Box3D's B3_CONTACT_RECYCLE_DISTANCE, 10 linear slops of 5 mm; its angle, 10 degrees, is the default.
            s.recycling.distance = 0.05;
            // Box3D's 30 Hz and damping ratio 10 both scaled by 1.2: the push-out rate omega / (2 zeta + h omega)
            // is the same from 3 sub-steps (overlap_recovery leaves as slowly), but each visit applies more of the
            // rigid impulse, mass_scale = a2 / (1 + a2) with a2 = h omega (2 zeta + h omega) 1.44 times larger, so
            // a tall stack leans less on its springs: stack_20 within 5 cm sideways at N = 4 and 8, where 30 Hz
            // leans 6.1 and 5.3 cm. A measured choice (docs/bench.md, "Contact recycling"), not Box3D's.
            s.soft_step.contact_hertz = 36.0;
            s.soft_step.damping_ratio = 12.0;
            // Box2D v3's and Box3D's speculative distance, 4 linear slops of 5 mm: a box-box face contact keeps its
            // clipped points up to 2 cm outside as speculative points, so a face landing on a slight tilt is stopped
            // on all its corners, not spun about the edge that touched first. Measured over the default matrix it
            // gains verdicts here and loses none; plain soft_step, detecting afresh each frame, loses three with it
            // (friction_static and brick_wall at N = 4), so it keeps 0 (docs/bench.md, "box_stack_40").
            s.speculative_margin = 0.02;
        }
        // soft_step_recycled solved colour by colour (Box3D's constraint graph): no direction through the scene
        // favoured, so the large pyramid's top stays within 5 cm sideways; a chain's support then climbs two links a
        // sweep, not all of them, and stacks settle slower at N = 4 (docs/bench.md, "Solve order").
        if (name == "soft_step_coloured") s.soft_step.order = SolveOrder::colours;
        // And four pairs of a colour at a time in single precision (Box3D's wide constraints): the large pyramid's run
        // in about three quarters of colours' time, held as in colours (docs/bench.md, "Four pairs at a time").
        if (name == "soft_step_wide") s.soft_step.order = SolveOrder::wide;
        return s;
    }
    if (name == "avbd") {
        s.velocity_method = VelocityMethod::avbd;
        s.position_method = PositionMethod::none;  // the contacts are constraints on positions (see AvbdSettings)
        return s;
    }
    return std::nullopt;
}

}  // namespace impulse
