#pragma once
// The snake_case names of the settings' enumerations: the same words in case files, traces, the command
// line and the inspector. One table per enumeration, read both ways.

#include "contact/contact.hpp"
#include "derivation/basis.hpp"
#include "derivation/impulse.hpp"
#include "methods/method_table.hpp"
#include "record/iteration_records.hpp"
#include "settings/settings.hpp"

#include <array>
#include <optional>
#include <string_view>
#include <utility>

namespace impulse::formats {

template <typename Enum, std::size_t N>
using NameTable = std::array<std::pair<Enum, std::string_view>, N>;

inline constexpr NameTable<PhaseOrder, 2> phase_order_names{{
    {PhaseOrder::positions_first, "positions_first"},
    {PhaseOrder::velocities_first, "velocities_first"},
}};
// The methods' names live in their table (methods/method_table.hpp), once.
template <typename Id, std::size_t N>
constexpr NameTable<Id, N> names_of_methods(const std::array<MethodRow<Id>, N>& rows) {
    NameTable<Id, N> names{};
    for (std::size_t i = 0; i < N; ++i) names[i] = {rows[i].id, rows[i].name};
    return names;
}
inline constexpr auto position_method_names = names_of_methods(position_methods);
inline constexpr auto velocity_method_names = names_of_methods(velocity_methods);
inline constexpr NameTable<WorstFirstSearch, 2> worst_first_search_names{{
    {WorstFirstSearch::priority_queue, "priority_queue"},
    {WorstFirstSearch::full_scan, "full_scan"},
}};
inline constexpr NameTable<SlidingFriction, 2> sliding_friction_names{{
    {SlidingFriction::reference, "reference"},
    {SlidingFriction::against_slip, "against_slip"},
}};
inline constexpr NameTable<SolveOrder, 3> solve_order_names{{
    {SolveOrder::contacts, "contacts"},
    {SolveOrder::colours, "colours"},
    {SolveOrder::wide, "wide"},
}};
inline constexpr NameTable<AngularLimitPolicy, 4> angular_limit_policy_names{{
    {AngularLimitPolicy::none, "none"},
    {AngularLimitPolicy::fixed, "fixed"},
    {AngularLimitPolicy::lever_arm, "lever_arm"},
    {AngularLimitPolicy::angle, "angle"},
}};
inline constexpr NameTable<OrientationUpdate, 2> orientation_update_names{{
    {OrientationUpdate::first_order, "first_order"},
    {OrientationUpdate::exact, "exact"},
}};
inline constexpr NameTable<TangentSeed, 2> tangent_seed_names{{
    {TangentSeed::world_x, "world_x"},
    {TangentSeed::world_y, "world_y"},
}};
inline constexpr NameTable<ImpulseModel, 3> impulse_model_names{{
    {ImpulseModel::frictionless, "frictionless"},
    {ImpulseModel::static_friction, "static"},
    {ImpulseModel::sliding_friction, "sliding"},
}};

inline constexpr NameTable<ImpulseClamp, 4> impulse_clamp_names{{
    {ImpulseClamp::none, "none"},
    {ImpulseClamp::push_only, "push_only"},
    {ImpulseClamp::friction, "friction"},
    {ImpulseClamp::both, "both"},
}};
inline constexpr NameTable<SolverStage, 7> solver_stage_names{{
    {SolverStage::warm_start, "warm_start"},
    {SolverStage::solve, "solve"},
    {SolverStage::relax, "relax"},
    {SolverStage::restitution, "restitution"},
    {SolverStage::push, "push"},
    {SolverStage::stabilize, "stabilize"},
    {SolverStage::dual, "dual"},
}};

inline constexpr NameTable<CollisionTest, 6> collision_test_names{{
    {CollisionTest::explicit_contact, "explicit"},
    {CollisionTest::sphere_sphere, "sphere_sphere"},
    {CollisionTest::sphere_half_space, "sphere_half_space"},
    {CollisionTest::box_half_space, "box_half_space"},
    {CollisionTest::box_sphere, "box_sphere"},
    {CollisionTest::box_box, "box_box"},
}};
inline constexpr NameTable<FeatureKind, 6> feature_kind_names{{
    {FeatureKind::none, "none"},
    {FeatureKind::face, "face"},
    {FeatureKind::edge, "edge"},
    {FeatureKind::vertex, "vertex"},
    {FeatureKind::sphere, "sphere"},
    {FeatureKind::plane, "plane"},
}};

template <typename Enum, std::size_t N>
constexpr std::string_view name_of(const NameTable<Enum, N>& table, Enum value) {
    for (const auto& [e, n] : table)
        if (e == value) return n;
    return "?";
}

template <typename Enum, std::size_t N>
constexpr std::optional<Enum> value_of(const NameTable<Enum, N>& table, std::string_view name) {
    for (const auto& [e, n] : table)
        if (n == name) return e;
    return std::nullopt;
}

}  // namespace impulse::formats
