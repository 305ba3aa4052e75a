#include "coursework/step_keys.hpp"

#include "explain/annotations.hpp"

#include <array>
#include <optional>

namespace impulse::coursework {

namespace {

constexpr ItemKind C = ItemKind::contact;
constexpr ItemKind P = ItemKind::position_iteration;
constexpr ItemKind V = ItemKind::velocity_iteration;
constexpr Role given = Role::given;
constexpr Role setting = Role::setting;
constexpr Role computed = Role::computed;
constexpr Role context = Role::context;
constexpr bool each_body = true;
constexpr bool whole = false;

// The trace's item keys in the order the trace writes them (docs/trace-format.md), each with the step of
// explain/derivation_table.cpp whose table shows it.
constexpr std::array keys{
    // --- a prepared contact: steps 1-5 --------------------------------------------------------------------
    StepKey{C, "contact", given, "", whole, "", "", "index into the frame's contacts", "which contact this is"},
    StepKey{C, "bodies", given, "", whole, "", "", "[body0, body1], null = the world",
            "the bodies it joins (after any swap)"},
    StepKey{C, "swapped", given, "", whole, "", "", "world given as body 0",
            "bodies exchanged and normal reversed when read"},
    StepKey{C, "inert", given, "", whole, "", "", "both inverse masses 0", "never resolved: nothing can move"},
    StepKey{C, "point", given, "", whole, "", "m", "q, from collision detection", "the contact point, world"},
    StepKey{C, "normal", given, "", whole},
    StepKey{C, "penetration", given, "", whole},
    StepKey{C, "restitution", given, "", whole},
    StepKey{C, "friction", given, "", whole, "", "", "μ", "friction coefficient (0: frictionless)"},
    StepKey{C, "origin.test", context, "", whole},
    StepKey{C, "origin.features[].kind", context, "", whole},
    StepKey{C, "origin.features[].index", context, "", whole},
    StepKey{C, "basis", computed, "basis", whole},
    StepKey{C, "tangent_seed", computed, "basis", whole},
    StepKey{C, "relative_position", computed, "relative_position", each_body},
    StepKey{C, "torque_per_unit_impulse", computed, "velocity_per_unit_impulse", each_body},
    StepKey{C, "rotation_per_unit_impulse", computed, "velocity_per_unit_impulse", each_body},
    StepKey{C, "velocity_per_unit_impulse", computed, "velocity_per_unit_impulse", each_body},
    StepKey{C, "angular_component", computed, "velocity_per_unit_impulse", each_body},
    StepKey{C, "linear_component", computed, "velocity_per_unit_impulse", each_body},
    StepKey{C, "delta_velocity_per_unit_impulse", computed, "velocity_per_unit_impulse", whole},
    StepKey{C, "point_velocity", computed, "contact_velocity", each_body},
    StepKey{C, "tangential_acceleration_velocity", computed, "contact_velocity", each_body},
    StepKey{C, "contact_velocity", computed, "contact_velocity", whole},
    StepKey{C, "separating_velocity", computed, "desired_delta_velocity", whole},
    StepKey{C, "restitution_cutoff", setting, "desired_delta_velocity", whole},
    StepKey{C, "restitution_cutoff_applied", computed, "desired_delta_velocity", whole, "", "", "|v_s| < cut-off",
            "whether the cut-off set c to 0"},
    StepKey{C, "restitution_used", computed, "desired_delta_velocity", whole},
    StepKey{C, "velocity_from_acceleration_applied", setting, "desired_delta_velocity", whole, "", "",
            "setting velocity_from_acceleration", "last frame's acceleration is taken out of the bounce"},
    StepKey{C, "velocity_from_acceleration", computed, "desired_delta_velocity", whole},
    StepKey{C, "desired_delta_velocity", computed, "desired_delta_velocity", whole},

    // --- a position iteration: the choice, then step 8 ---------------------------------------------------
    StepKey{P, "iteration", given, "", whole, "", "", "counts from 0 within the phase", "which iteration"},
    StepKey{P, "contact", given, "", whole, "", "", "argmax of penetration above ε",
            "the contact this iteration resolves (the deepest)"},
    StepKey{P, "penetration", computed, "choice", whole},
    StepKey{P, "epsilon", given, "", whole, "", "m", "setting position_epsilon",
            "penetrations at or below it are left alone"},
    StepKey{P, "pass", given, "", whole, "", "", "relaxation only", "which pass over the contacts"},
    StepKey{P, "method", setting, "penetration_inertia", whole, "", "", "setting position_method",
            "how the penetration is removed"},
    StepKey{P, "amount", computed, "penetration_inertia", whole},
    StepKey{P, "rewind.closing_velocity", computed, "rewind", whole},
    StepKey{P, "rewind.time", computed, "rewind", whole, "rewind_time"},
    StepKey{P, "rewind.time_limit", setting, "rewind", whole, "", "s", "Δt, the frame's duration",
            "the bodies go back at most to the start of the frame"},
    StepKey{P, "rewind.removed_penetration", computed, "rewind", whole},
    StepKey{P, "rewind.linear_change", computed, "rewind", each_body, "rewind_linear_change"},
    StepKey{P, "rewind.angular_change", computed, "rewind", each_body, "rewind_angular_change"},
    StepKey{P, "linear_inertia", computed, "penetration_inertia", each_body},
    StepKey{P, "angular_inertia", computed, "penetration_inertia", each_body},
    StepKey{P, "total_inertia", computed, "penetration_inertia", whole},
    StepKey{P, "angular_limit.policy", setting, "move_split", whole, "", "", "setting angular_limit.policy",
            "how the largest turn is set: none, fixed, lever_arm, angle"},
    StepKey{P, "angular_limit.factor", setting, "move_split", whole, "", "", "setting angular_limit.factor",
            "the limit's scale"},
    StepKey{P, "angular_limit.maximum", computed, "move_split", each_body, "angular_limit"},
    StepKey{P, "angular_limit.applied", computed, "move_split", each_body, "", "", "|angular_move_before| > maximum",
            "whether the limit cut the angular move back"},
    StepKey{P, "angular_limit.linear_move_before", computed, "move_split", each_body, "linear_move_before"},
    StepKey{P, "angular_limit.angular_move_before", computed, "move_split", each_body, "angular_move_before"},
    StepKey{P, "linear_move", computed, "move_split", each_body},
    StepKey{P, "angular_move", computed, "move_split", each_body},
    StepKey{P, "linear_change", computed, "position_change", each_body},
    StepKey{P, "angular_change", computed, "position_change", each_body},
    StepKey{P, "updates[].contact", given, "updates", whole, "", "", "shares a moved body",
            "a contact whose penetration this move changes"},
    StepKey{P, "updates[].body", given, "updates", whole, "", "", "index into the scene's bodies",
            "the moved body it shares"},
    StepKey{P, "updates[].slot", given, "updates", whole, "", "", "0 or 1", "which of that contact's bodies it is"},
    StepKey{P, "updates[].before", given, "updates", whole, "", "m", "its penetration before",
            "as earlier iterations left it"},
    StepKey{P, "updates[].delta", computed, "updates", whole, "", "m", "∓(linear_change + angular_change × q_rel) · n",
            "change of its penetration (− for its body 0, + for its body 1)"},
    StepKey{P, "updates[].after", computed, "updates", whole, "", "m", "before + delta", "its penetration now"},

    // --- a velocity iteration: the choice, then steps 4-7 ------------------------------------------------
    StepKey{V, "iteration", given, "", whole, "", "", "counts from 0 within the phase", "which iteration"},
    StepKey{V, "contact", given, "", whole, "", "", "argmax of desired_delta_velocity above ε",
            "the contact this iteration resolves (the worst)"},
    StepKey{V, "epsilon", given, "", whole, "", "m/s", "setting velocity_epsilon",
            "desired velocity changes at or below it are left alone"},
    StepKey{V, "contact_velocity", computed, "contact_velocity", whole},
    StepKey{V, "separating_velocity", computed, "desired_delta_velocity", whole},
    StepKey{V, "restitution", setting, "desired_delta_velocity", whole},
    StepKey{V, "restitution_cutoff", setting, "desired_delta_velocity", whole},
    StepKey{V, "restitution_cutoff_applied", computed, "desired_delta_velocity", whole, "", "", "|v_s| < cut-off",
            "whether the cut-off set c to 0"},
    StepKey{V, "restitution_used", computed, "desired_delta_velocity", whole},
    StepKey{V, "velocity_from_acceleration_applied", setting, "desired_delta_velocity", whole, "", "",
            "setting velocity_from_acceleration", "last frame's acceleration is taken out of the bounce"},
    StepKey{V, "velocity_from_acceleration", computed, "desired_delta_velocity", whole},
    StepKey{V, "desired_delta_velocity", computed, "desired_delta_velocity", whole},
    StepKey{V, "impulse_model", computed, "impulse", whole},
    StepKey{V, "friction_solve.delta_velocity_matrix", computed, "impulse", whole},
    StepKey{V, "friction_solve.target_delta_velocity", computed, "impulse", whole},
    StepKey{V, "friction_solve.solvable", computed, "impulse", whole, "", "", "K invertible, response > 0",
            "whether the friction solve could be used"},
    StepKey{V, "friction_solve.static_impulse", computed, "impulse", whole},
    StepKey{V, "friction_solve.tangential_impulse", computed, "impulse", whole},
    StepKey{V, "friction_solve.cone_limit", computed, "impulse", whole},
    StepKey{V, "friction_solve.sliding_direction", computed, "impulse", whole},
    StepKey{V, "friction_solve.sliding_normal_response", computed, "impulse", whole},
    StepKey{V, "impulse_contact", computed, "impulse", whole},
    StepKey{V, "impulse_world", computed, "impulse", whole},
    StepKey{V, "impulsive_torque", computed, "velocity_change", each_body},
    StepKey{V, "velocity_change", computed, "velocity_change", each_body},
    StepKey{V, "rotation_change", computed, "velocity_change", each_body},
    StepKey{V, "updates[].contact", given, "updates", whole, "", "", "shares a changed body",
            "a contact whose velocity this impulse changes"},
    StepKey{V, "updates[].body", given, "updates", whole, "", "", "index into the scene's bodies",
            "the body it shares"},
    StepKey{V, "updates[].slot", given, "updates", whole, "", "", "0 or 1", "which of that contact's bodies it is"},
    StepKey{V, "updates[].before", given, "updates", whole, "", "m/s", "its contact_velocity before",
            "as earlier iterations left it, contact coordinates"},
    StepKey{V, "updates[].desired_delta_velocity_before", given, "updates", whole, "", "m/s",
            "its desired_delta_velocity before", "as earlier iterations left it"},
    StepKey{V, "updates[].delta", computed, "updates", whole, "", "m/s",
            "±Cᵀ(velocity_change + rotation_change × q_rel)",
            "change of its contact velocity (+ for its body 0, − for its body 1)"},
    StepKey{V, "updates[].after", computed, "updates", whole, "", "m/s", "before + delta", "its contact velocity now"},
    StepKey{V, "updates[].desired_delta_velocity_after", computed, "updates", whole, "", "m/s",
            "step 5 on the new contact_velocity", "its desired velocity change now"},
};

constexpr std::array outside{
    OutsideKey{"scene_bodies", "inverse_mass", true, true, true, "1/kg", "m⁻¹", "the body's inverse mass"},
    OutsideKey{"bodies_before", "inverse_inertia_world", true, true, true, "1/(kg·m²)", "R I⁻¹ Rᵀ",
               "inverse inertia tensor in world coordinates, for the whole frame"},
    OutsideKey{"bodies_before", "position", true, false, false, "m", "p", "the body's centre"},
    OutsideKey{"bodies_before", "velocity", true, false, false, "m/s", "ṗ", "the body's velocity"},
    OutsideKey{"bodies_before", "angular_velocity", true, false, false, "rad/s", "θ̇", "the body's angular velocity"},
    OutsideKey{"contact", "bodies", false, true, true},
    OutsideKey{"contact", "normal", false, true, false},
    OutsideKey{"contact", "basis", false, false, true},
    OutsideKey{"contact", "relative_position", false, true, true},
    OutsideKey{"contact", "friction", false, false, true, "", "μ", "friction coefficient (0: frictionless)"},
    OutsideKey{"contact", "delta_velocity_per_unit_impulse", false, false, true},
};

std::string last_part(std::string_view key) {
    const std::size_t dot = key.rfind('.');
    return std::string(dot == std::string_view::npos ? key : key.substr(dot + 1));
}

Described from_annotation(const explain::Annotation& a) {
    return {std::string(a.quantity), std::string(a.unit), std::string(a.formula), std::string(a.equation),
            std::string(a.meaning)};
}

}  // namespace

std::span<const StepKey> step_keys() {
    return keys;
}

std::span<const OutsideKey> outside_keys() {
    return outside;
}

const StepKey* find_step_key(ItemKind item, std::string_view key) {
    for (const StepKey& k : keys)
        if (k.item == item && k.key == key) return &k;
    return nullptr;
}

Described describe_key(const StepKey& key) {
    const std::string name = key.annotation.empty() ? last_part(key.key) : std::string(key.annotation);
    if (const explain::Annotation* a = explain::find_annotation(name); a && key.meaning.empty())
        return from_annotation(*a);
    return {std::string(key.key), std::string(key.unit), std::string(key.formula), "", std::string(key.meaning)};
}

Described describe_outside(const OutsideKey& key) {
    if (key.where == "contact")
        if (const StepKey* k = find_step_key(ItemKind::contact, key.key)) return describe_key(*k);
    return {std::string(key.key), std::string(key.unit), std::string(key.formula), "", std::string(key.meaning)};
}

Described describe_path(const io::json& document, const std::vector<PathToken>& path) {
    const auto key_is = [&path](std::size_t i, std::string_view key) {
        const auto* k = i < path.size() ? std::get_if<std::string>(&path[i]) : nullptr;
        return k && *k == key;
    };
    const auto index_at = [&path](std::size_t i) {
        return i < path.size() && std::holds_alternative<std::size_t>(path[i]);
    };

    // Inside an item: frames[f].contacts[k].… or frames[f].phases[p].iterations[i].…
    std::optional<ItemKind> item;
    std::size_t rest = 0;
    if (key_is(0, "frames") && index_at(1) && key_is(2, "contacts") && index_at(3)) {
        item = ItemKind::contact;
        rest = 4;
    } else if (key_is(0, "frames") && index_at(1) && key_is(2, "phases") && index_at(3) && key_is(4, "iterations") &&
               index_at(5)) {
        const io::json* phase = value_at(document, {path.begin(), path.begin() + 4});
        if (phase && phase->is_object() && phase->contains("phase"))
            item = (*phase)["phase"] == "position" ? ItemKind::position_iteration : ItemKind::velocity_iteration;
        rest = 6;
    }
    if (item && rest < path.size()) {
        // The key pattern: nested keys joined by '.', "[]" after updates and features; other indices (a body,
        // a component) dropped.
        std::string key;
        for (std::size_t i = rest; i < path.size(); ++i) {
            if (const auto* k = std::get_if<std::string>(&path[i])) {
                if (!key.empty()) key += '.';
                key += *k;
            } else if (key == "updates" || key.ends_with(".features")) {
                key += "[]";
            }
        }
        if (const StepKey* k = find_step_key(*item, key)) return describe_key(*k);
    }
    // Elsewhere: the last key that is a vocabulary name.
    for (auto it = path.rbegin(); it != path.rend(); ++it)
        if (const auto* k = std::get_if<std::string>(&*it))
            if (const explain::Annotation* a = explain::find_annotation(*k)) return from_annotation(*a);
    return {};
}

}  // namespace impulse::coursework
