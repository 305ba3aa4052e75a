#pragma once
// The table of resolution methods: for each value of `velocity_method` and `position_method`, its name (the
// word in scene files, traces, the command line and the inspector), what it owns, the function that runs it
// (methods/method.hpp), the settings it reads and one line saying what it does. The resolver, the world step,
// the trace writer, the bench and the inspector's settings panel read this table; none of them names a
// method. docs/methods.md describes each method and how to add one.

#include "methods/method.hpp"
#include "settings/settings.hpp"

#include <array>
#include <span>
#include <string_view>

namespace impulse {

// What a method is responsible for in a frame.
enum class MethodScope {
    position_phase,  // the resolver's position phase: moves the bodies apart
    velocity_phase,  // the resolver's velocity phase: changes the velocities
    whole_step,      // the frame after detection: it integrates the bodies itself (sub-steps), so the world
                     // step does not integrate first and no position phase runs (recorded empty, `none`)
};

template <typename Id>
struct MethodRow {
    Id id;
    std::string_view name;
    MethodScope scope;
    MethodFunction solve;
    // The settings the method reads (keys as in scene files), beyond those every frame reads (duration,
    // orientation_update, the restitution cut-off and the acceleration refinements of steps 4 and 5).
    std::span<const std::string_view> reads;
    std::string_view description;
    // Velocity methods: the setting `impulse-lab bench`'s iteration count N is written to, and how.
    std::string_view iteration_setting = {};
    void (*set_iterations)(ResolverSettings& settings, int n) = nullptr;
    // Position methods that work in passes: what one pass is called ("relaxation pass", "push sweep").
    std::string_view pass_name = {};
    // What of steps 4 and 5 it reads (preparation/prepared_contact.hpp).
    Preparation preparation = Preparation::steps_1_to_5;
};

namespace method_reads {
inline constexpr std::array<std::string_view, 8> worst_first{
    "velocity_epsilon", "iterations_per_contact", "velocity_iterations", "worst_first_search", "sliding_friction",
    "baumgarte",        "position_bias.factor",   "position_bias.slop"};
inline constexpr std::array<std::string_view, 6> sequential_sweep{
    "velocity_epsilon", "sweeps", "sliding_friction", "baumgarte", "position_bias.factor", "position_bias.slop"};
inline constexpr std::array<std::string_view, 6> projected_gauss_seidel{
    "velocity_epsilon", "sweeps", "warm_start", "baumgarte", "position_bias.factor", "position_bias.slop"};
inline constexpr std::array<std::string_view, 7> soft_step{"sweeps",
                                                           "warm_start",
                                                           "soft_step.substeps",
                                                           "soft_step.contact_hertz",
                                                           "soft_step.damping_ratio",
                                                           "soft_step.max_push_velocity",
                                                           "soft_step.order"};
inline constexpr std::array<std::string_view, 9> avbd{"warm_start",         "avbd.iterations", "avbd.alpha",
                                                      "avbd.beta",          "avbd.gamma",      "avbd.stiffness_min",
                                                      "avbd.stiffness_max", "avbd.slop",       "avbd.post_stabilize"};
inline constexpr std::array<std::string_view, 4> linear_projection{"position_epsilon", "iterations_per_contact",
                                                                   "position_iterations", "worst_first_search"};
inline constexpr std::array<std::string_view, 6> nonlinear_projection{"position_epsilon",     "iterations_per_contact",
                                                                      "position_iterations",  "worst_first_search",
                                                                      "angular_limit.policy", "angular_limit.factor"};
inline constexpr std::array<std::string_view, 7> relaxation{
    "position_epsilon",     "iterations_per_contact", "position_iterations", "angular_limit.policy",
    "angular_limit.factor", "relaxation.fraction",    "relaxation.passes"};
inline constexpr std::array<std::string_view, 4> split_impulse{"velocity_epsilon", "sweeps", "position_bias.factor",
                                                               "position_bias.slop"};
}  // namespace method_reads

// Each method's function (methods/method.hpp), in its own file of engine/methods/.
PhaseOutcome worst_first_velocities(FrameContext& frame);             // worst_first.cpp
PhaseOutcome sequential_sweep_velocities(FrameContext& frame);        // sequential_sweep.cpp
PhaseOutcome projected_gauss_seidel_velocities(FrameContext& frame);  // projected_gauss_seidel.cpp
PhaseOutcome soft_step(FrameContext& frame);                          // soft_step.cpp
PhaseOutcome avbd_step(FrameContext& frame);                          // avbd.cpp

// One row per enumerator, in the enumerators' order (checked in method_table.cpp).
template <typename Id>
using MethodRows = std::array<MethodRow<Id>, static_cast<std::size_t>(Id::count)>;

inline constexpr MethodRows<VelocityMethod> velocity_methods{{
    {VelocityMethod::worst_first, "worst_first", MethodScope::velocity_phase, worst_first_velocities,
     method_reads::worst_first,
     "the book: resolve the contact with the largest desired delta v, update the others, repeat",
     "iterations_per_contact", [](ResolverSettings& s, int n) { s.iterations_per_contact = n; }},
    {VelocityMethod::sequential_sweep, "sequential_sweep", MethodScope::velocity_phase, sequential_sweep_velocities,
     method_reads::sequential_sweep, "the book's impulse on every contact in index order, `sweeps` times", "sweeps",
     [](ResolverSettings& s, int n) { s.sweeps = n; }},
    {VelocityMethod::projected_gauss_seidel, "projected_gauss_seidel", MethodScope::velocity_phase,
     projected_gauss_seidel_velocities, method_reads::projected_gauss_seidel,
     "sequential impulses: accumulated impulses clamped to push only and to the friction cone, warm started", "sweeps",
     [](ResolverSettings& s, int n) { s.sweeps = n; }},
    {VelocityMethod::soft_step,
     "soft_step",
     MethodScope::whole_step,
     soft_step,
     method_reads::soft_step,
     "Box2D v3: sub-steps of soft contacts, relax, restitution; it integrates the bodies itself",
     "soft_step.substeps",
     [](ResolverSettings& s, int n) {
         s.soft_step.substeps = n;
         s.sweeps = 1;
     },
     {},
     Preparation::steps_1_to_4},
    {VelocityMethod::avbd, "avbd", MethodScope::whole_step, avbd_step, method_reads::avbd,
     "augmented vertex block descent: each body's 6x6 block against its contacts' augmented-Lagrangian forces; it "
     "integrates the bodies itself",
     "avbd.iterations", [](ResolverSettings& s, int n) { s.avbd.iterations = n; }},
}};

PhaseOutcome linear_projection_positions(FrameContext& frame);     // linear_projection.cpp
PhaseOutcome nonlinear_projection_positions(FrameContext& frame);  // nonlinear_projection.cpp
PhaseOutcome velocity_based_positions(FrameContext& frame);        // velocity_based.cpp
PhaseOutcome relaxation_positions(FrameContext& frame);            // relaxation.cpp
PhaseOutcome split_impulse_positions(FrameContext& frame);         // split_impulse.cpp
PhaseOutcome no_positions(FrameContext& frame);                    // no_position_phase.cpp

inline constexpr MethodRows<PositionMethod> position_methods{{
    {PositionMethod::linear_projection, "linear_projection", MethodScope::position_phase, linear_projection_positions,
     method_reads::linear_projection, "worst first: move the bodies apart along the normal, by inverse mass"},
    {PositionMethod::nonlinear_projection, "nonlinear_projection", MethodScope::position_phase,
     nonlinear_projection_positions, method_reads::nonlinear_projection,
     "the book, worst first: move and turn the bodies by their linear and angular inertia"},
    {PositionMethod::velocity_based, "velocity_based", MethodScope::position_phase, velocity_based_positions,
     method_reads::nonlinear_projection,
     "worst first: move the bodies back along their paths, then project what remains"},
    {PositionMethod::relaxation,
     "relaxation",
     MethodScope::position_phase,
     relaxation_positions,
     method_reads::relaxation,
     "passes, deepest first: remove a fraction of each contact's penetration per visit",
     {},
     nullptr,
     "relaxation pass"},
    {PositionMethod::split_impulse,
     "split_impulse",
     MethodScope::position_phase,
     split_impulse_positions,
     method_reads::split_impulse,
     "a push solve on pseudo-velocities that move the bodies and are then discarded",
     {},
     nullptr,
     "push sweep"},
    {PositionMethod::none,
     "none",
     MethodScope::position_phase,
     no_positions,
     {},
     "no position phase: only velocities (Baumgarte's step-5 bias, a soft contact) separate the bodies",
     {},
     nullptr,
     {},
     Preparation::steps_1_to_4},
}};

// The row of a settings value: the rows stand in enumerator order (checked in method_table.cpp).
constexpr const MethodRow<VelocityMethod>& method_row(VelocityMethod id) {
    return velocity_methods[static_cast<std::size_t>(id)];
}
constexpr const MethodRow<PositionMethod>& method_row(PositionMethod id) {
    return position_methods[static_cast<std::size_t>(id)];
}

// The position method that runs with these settings: none when the velocity method owns the whole step.
constexpr PositionMethod position_method_in_effect(const ResolverSettings& settings) {
    return method_row(settings.velocity_method).scope == MethodScope::whole_step ? PositionMethod::none
                                                                                 : settings.position_method;
}

// Whether a setting is read by the methods these settings run (the panel shows only those).
bool reads_setting(const ResolverSettings& settings, std::string_view key);

}  // namespace impulse
