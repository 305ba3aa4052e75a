#include "explain/annotations.hpp"

#include <algorithm>
#include <cassert>
#include <set>
#include <unordered_map>

namespace impulse::explain {

namespace {

// One row per quantity, in the order the derivation computes them. `inputs` name other rows; a test checks
// that every input is a row, that the inputs never loop, that every row has a step and that every table row
// the inspector shows is a row here.
const std::vector<Annotation> rows{
    // What a body brings: its state before the frame's resolution, its mass, last frame's acceleration.
    {"body_position", "p", "", "m", "the body's centre", "body", "", "bodies_before[].position", "F"},
    {"body_velocity", "ṗ", "", "m/s", "the body's velocity", "body", "", "bodies_before[].velocity", "F"},
    {"body_angular_velocity", "θ̇", "", "rad/s", "the body's angular velocity", "body", "",
     "bodies_before[].angular_velocity", "F"},
    {"body_inverse_mass", "m⁻¹", "", "1/kg", "the body's inverse mass", "body", "", "scene.bodies[].inverse_mass", "F"},
    {"body_inverse_inertia", "I⁻¹ = R I⁻¹_body Rᵀ", "", "1/(kg·m²)", "inverse inertia tensor, world coordinates",
     "body", "", "bodies_before[].inverse_inertia_world", "F"},
    {"body_acceleration", "a, last frame's", "ch. 15", "m/s²", "what last frame's forces did to the body", "body", "",
     "", ""},
    // What the contact is given, by collision detection or the case file.
    {"swapped", "world given as body 0 ⇒ exchanged", "", "",
     "the bodies were exchanged and the normal reversed when read", "contact", "", "", "C"},
    {"bodies", "[body 0, body 1], world last", "", "", "the two bodies, after any swap", "contact", "swapped", "", "C"},
    {"point", "q, from collision detection", "", "m", "the contact point, world", "contact", "", "", "C"},
    {"normal", "n, from collision detection", "", "", "the way body 0 must move to separate", "contact", "swapped", "",
     "C"},
    {"penetration", "from collision detection", "", "m", "overlap along the normal", "contact", "", "", "CP"},
    {"restitution", "c", "", "", "share of the closing speed given back", "contact", "", "", "CV"},
    {"friction", "μ", "", "", "friction coefficient (0: frictionless)", "contact", "", "", "C"},
    // Step 1: basis
    {"tangent_seed", "Y if |n.x| > |n.y|, else X", "", "", "world axis farther from n: seed × n never vanishes",
     "basis", "normal", "", "C"},
    {"tangent1", "t₁ = normalise(seed × n)", "", "", "first sliding direction (contact y)", "basis",
     "normal tangent_seed", "", ""},
    {"tangent2", "t₂ = n × t₁", "", "", "second sliding direction (contact z)", "basis", "normal tangent1", "", ""},
    {"basis", "C = [n t₁ t₂] (columns)", "", "", "contact → world; Cᵀ maps world → contact", "basis",
     "normal tangent1 tangent2", "", "C"},
    // Step 2
    {"relative_position", "q_rel = q − p", "(1.8)", "m", "the contact point seen from the body's centre",
     "relative_position", "point body_position bodies", "", "C"},
    // Step 3
    {"torque_per_unit_impulse", "u = q_rel × n", "(14.2)", "N·m·s per N·s",
     "impulsive torque of a unit impulse along n", "velocity_per_unit_impulse", "relative_position normal", "", "C"},
    {"rotation_per_unit_impulse", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s per N·s", "change of spin that torque causes",
     "velocity_per_unit_impulse", "torque_per_unit_impulse body_inverse_inertia", "", "C"},
    {"velocity_per_unit_impulse", "Δθ̇ × q_rel", "(9.5)", "m/s per N·s", "velocity that spin gives the contact point",
     "velocity_per_unit_impulse", "rotation_per_unit_impulse relative_position", "", "C"},
    {"angular_component", "(Δθ̇ × q_rel) · n", "", "m/s per N·s", "its part along the normal",
     "velocity_per_unit_impulse", "velocity_per_unit_impulse normal", "", "C"},
    {"linear_component", "m⁻¹", "(7.5)", "m/s per N·s", "linear velocity change per unit impulse",
     "velocity_per_unit_impulse", "body_inverse_mass bodies", "", "C"},
    {"delta_velocity_per_unit_impulse", "d = Σ (m⁻¹ + angular)", "", "m/s per N·s",
     "how fast the points separate per unit impulse", "velocity_per_unit_impulse", "angular_component linear_component",
     "", "C"},
    // Step 4
    {"point_velocity", "θ̇ × q_rel + ṗ", "(9.5)", "m/s", "velocity of the body's contact point", "contact_velocity",
     "relative_position body_velocity body_angular_velocity", "", "C"},
    {"tangential_acceleration_velocity", "tangential part of a_last Δt", "ch. 15", "m/s",
     "sliding last frame's forces caused: friction removes it", "contact_velocity", "body_acceleration basis", "", "C"},
    {"contact_velocity", "Cᵀ (v₀ − v₁)", "", "m/s", "x: separating velocity v_s (< 0 closing); y, z: sliding",
     "contact_velocity", "point_velocity tangential_acceleration_velocity basis", "", "CV"},
    // Step 5
    {"separating_velocity", "v_s = contact_velocity.x", "", "m/s", "negative: the points are closing",
     "desired_delta_velocity", "contact_velocity", "", "CV"},
    {"restitution_cutoff", "setting restitution_cutoff", "ch. 15", "m/s", "slow contacts do not bounce (no jitter)",
     "settings", "", "", "CV"},
    {"restitution_cutoff_applied", "|v_s| < cut-off ⇒ c = 0", "ch. 15", "", "whether the cut-off took the bounce away",
     "desired_delta_velocity", "separating_velocity restitution_cutoff", "", "CV"},
    {"restitution_used", "c, or 0 below the cut-off", "", "", "the restitution this contact gets now",
     "desired_delta_velocity", "restitution restitution_cutoff_applied", "", "CV"},
    {"velocity_from_acceleration_applied", "setting velocity_from_acceleration", "ch. 15", "",
     "last frame's acceleration is taken out of the bounce", "settings", "", "", "CV"},
    {"velocity_from_acceleration", "(a₀ − a₁) · n Δt", "ch. 15", "m/s",
     "closing speed last frame's forces added: not bounced", "desired_delta_velocity",
     "body_acceleration normal velocity_from_acceleration_applied", "", "CV"},
    {"desired_delta_velocity", "Δv = −v_s − c (v_s − v_acc)", "v_s' = −c v_s", "m/s",
     "change of separating velocity the impulse must make", "desired_delta_velocity",
     "separating_velocity restitution_used velocity_from_acceleration position_bias", "", "CV"},
    // Accumulating solvers (projected Gauss-Seidel, soft step) and the position bias: Catto's sequential impulses
    {"position_bias", "β max(d − slop, 0) / Δt", "Baumgarte", "m/s",
     "extra separating speed asked for, to push out the penetration", "position_bias", "penetration", "", "V"},
    {"accumulated_before", "λ, this frame's total so far", "", "N·s",
     "impulse this contact has given so far (x normal, y, z sliding)", "accumulated_impulse", "", "accumulated.before",
     "V"},
    {"accumulated_unclamped", "λ + Δv / d", "", "N·s", "the total this visit asks for, before its limits",
     "accumulated_impulse", "accumulated_before desired_delta_velocity delta_velocity_per_unit_impulse",
     "accumulated.unclamped", "V"},
    {"clamp", "λ_n ≥ 0, |λ_t| ≤ μ λ_n", "", "",
     "which limit applied: a contact can only push, friction stays inside its cone", "accumulated_impulse",
     "accumulated_unclamped friction", "accumulated.clamp", "V"},
    {"accumulated_after", "clamp(λ + Δv / d)", "", "N·s",
     "the new total; only its change is applied, so a later visit can take back an earlier push", "accumulated_impulse",
     "accumulated_unclamped clamp", "accumulated.after", "V"},
    // Step 6
    {"delta_velocity_matrix", "K = Cᵀ(Σ m⁻¹ − [q_rel]× I⁻¹ [q_rel]×)C", "ch. 15", "m/s per N·s",
     "velocity change per unit impulse, every direction", "impulse",
     "relative_position body_inverse_mass body_inverse_inertia basis", "friction_solve.delta_velocity_matrix", "V"},
    {"target_delta_velocity", "(Δv, −v_t₁, −v_t₂)", "ch. 15", "m/s", "bounce as desired, stop all sliding", "impulse",
     "desired_delta_velocity contact_velocity", "friction_solve.target_delta_velocity", "V"},
    {"solvable", "K invertible, response > 0", "ch. 15", "", "whether the friction solve could be used", "impulse",
     "delta_velocity_matrix", "friction_solve.solvable", "V"},
    {"static_impulse", "K⁻¹ · target", "ch. 15", "N·s", "the impulse if friction can hold", "impulse",
     "delta_velocity_matrix target_delta_velocity", "friction_solve.static_impulse", "V"},
    {"tangential_impulse", "|(g_t₁, g_t₂)|", "ch. 15", "N·s", "sideways part of the static impulse", "impulse",
     "static_impulse", "friction_solve.tangential_impulse", "V"},
    {"cone_limit", "μ g_n", "ch. 15", "N·s", "most sideways impulse friction can give", "impulse",
     "static_impulse friction", "friction_solve.cone_limit", "V"},
    {"sliding_direction", "(g_t₁, g_t₂) / |(g_t₁, g_t₂)|", "ch. 15", "", "direction kept once the contact slides",
     "impulse", "static_impulse", "friction_solve.sliding_direction", "V"},
    {"sliding_normal_response", "K₀₀ + μ (K₀₁ ŷ + K₀₂ ẑ)", "ch. 15", "m/s per N·s",
     "normal velocity change per unit normal impulse, sliding", "impulse",
     "delta_velocity_matrix sliding_direction friction", "friction_solve.sliding_normal_response", "V"},
    {"impulse_model", "μ = 0: frictionless; else 3×3 solve + cone", "", "", "which impulse calculation applies",
     "impulse", "friction tangential_impulse cone_limit clamp", "", "V"},
    {"impulse_contact", "g = Δv / d, (g, 0, 0)", "(14.3)", "N·s", "the impulse in contact coordinates", "impulse",
     "desired_delta_velocity delta_velocity_per_unit_impulse impulse_model static_impulse sliding_direction "
     "sliding_normal_response cone_limit accumulated_before accumulated_after",
     "", "V"},
    {"impulse_world", "C · impulse_contact", "", "N·s", "+ on body 0, − on body 1", "impulse", "impulse_contact basis",
     "", "V"},
    // Step 7
    {"impulsive_torque", "u = q_rel × g", "(14.2)", "N·m·s", "turning effect of the impulse on the body",
     "velocity_change", "relative_position impulse_world", "", "V"},
    {"velocity_change", "Δṗ = g m⁻¹", "(7.5)", "m/s", "change of the body's linear velocity", "velocity_change",
     "impulse_world body_inverse_mass", "", "V"},
    {"rotation_change", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s", "change of the body's angular velocity", "velocity_change",
     "impulsive_torque body_inverse_inertia", "", "V"},
    {"velocity_update", "contact_velocity ± Cᵀ(Δṗ + Δθ̇ × q_rel), then desired_delta_velocity again", "", "m/s",
     "a contact sharing a body that changed speed: its velocity before → after", "updates",
     "contact_velocity velocity_change rotation_change relative_position basis restitution_used", "updates", "V"},
    // The choice an iteration makes
    {"iteration", "counts from 0 within the phase", "", "", "which iteration", "choice", "", "", "PV"},
    {"contact", "argmax over contacts above ε", "", "", "the contact this iteration resolves", "choice", "", "", "PV"},
    {"sweep", "sub-step, stage and sweep", "", "", "where a sweeping solver was when it visited the contact", "choice",
     "", "", "V"},
    {"epsilon", "setting position_epsilon or velocity_epsilon", "", "", "values at or below it are left alone",
     "choice", "", "", "PV"},
    {"pass", "relaxation: the pass; split impulse: the push sweep", "", "", "which pass over the contacts", "choice",
     "", "", "P"},
    // Step 8: velocity-based resolution's rewind
    {"closing_velocity", "−(v_p₀ − v_p₁) · n", "", "m/s", "how fast the contact points approach", "rewind",
     "body_velocity body_angular_velocity relative_position normal", "rewind.closing_velocity", "P"},
    {"rewind_time_limit", "Δt, the frame's duration", "", "s", "the bodies go back at most to the start of the frame",
     "settings", "", "rewind.time_limit", "P"},
    {"rewind_time", "t = min(penetration / closing, Δt)", "", "s", "how far back along their paths the bodies go",
     "rewind", "penetration closing_velocity rewind_time_limit", "rewind.time", "P"},
    {"removed_penetration", "closing_velocity · t", "", "m", "penetration the paths explain", "rewind",
     "closing_velocity rewind_time", "rewind.removed_penetration", "P"},
    {"rewind_linear_change", "−ṗ t", "", "m", "translation back along the path", "rewind", "body_velocity rewind_time",
     "rewind.linear_change", "P"},
    {"rewind_angular_change", "−θ̇ t", "", "rad", "rotation back along the path", "rewind",
     "body_angular_velocity rewind_time", "rewind.angular_change", "P"},
    // Step 8: projection
    {"amount", "penetration", "", "m", "how much of it this move removes", "penetration_inertia",
     "penetration removed_penetration", "", "P"},
    {"linear_inertia", "m⁻¹", "", "m/s per N·s", "how readily the body gives way by moving", "penetration_inertia",
     "body_inverse_mass", "", "P"},
    {"angular_inertia", "((I⁻¹(q_rel × n)) × q_rel) · n", "", "m/s per N·s", "how readily it gives way by turning",
     "penetration_inertia", "relative_position normal body_inverse_inertia", "", "P"},
    {"total_inertia", "Σ (linear + angular)", "", "m/s per N·s", "all the give at this contact", "penetration_inertia",
     "linear_inertia angular_inertia", "", "P"},
    {"linear_move_before", "±amount · linear / total", "", "m", "the linear share the inertias asked for", "move_split",
     "amount linear_inertia total_inertia", "angular_limit.linear_move_before", "P"},
    {"angular_move_before", "±amount · angular / total", "", "m", "the angular share the inertias asked for",
     "move_split", "amount angular_inertia total_inertia", "angular_limit.angular_move_before", "P"},
    {"angular_limit_policy", "setting angular_limit.policy", "", "", "how the largest turn is set", "settings", "",
     "angular_limit.policy", "P"},
    {"angular_limit_factor", "setting angular_limit.factor", "", "", "the limit's scale", "settings", "",
     "angular_limit.factor", "P"},
    {"angular_limit", "maximum |angular_move|", "", "m", "largest turn allowed; the excess moves linearly",
     "move_split", "relative_position normal angular_limit_policy angular_limit_factor", "angular_limit.maximum", "P"},
    {"angular_limit_applied", "|angular_move_before| > maximum", "", "", "whether the limit cut the angular move back",
     "move_split", "angular_move_before angular_limit", "angular_limit.applied", "P"},
    {"linear_move", "±amount · linear / total", "", "m", "distance removed by moving the body", "move_split",
     "amount linear_inertia total_inertia angular_limit_applied angular_limit angular_move_before "
     "linear_move_before",
     "", "P"},
    {"angular_move", "±amount · angular / total", "", "m", "distance removed by turning the body", "move_split",
     "amount angular_inertia total_inertia angular_limit_applied angular_limit angular_move_before", "", "P"},
    {"linear_change", "n · linear_move", "", "m", "the translation applied to the body", "position_change",
     "linear_move normal rewind_linear_change", "", "P"},
    {"angular_change", "I⁻¹(q_rel × n) · angular_move / angular", "", "rad", "the rotation applied (axis × angle)",
     "position_change", "angular_move angular_inertia rotation_per_unit_impulse rewind_angular_change", "", "P"},
    {"penetration_update", "before ∓ (linear_change + angular_change × q_rel) · n", "", "m",
     "a contact sharing a moved body: its penetration before → after", "updates",
     "penetration linear_change angular_change relative_position normal", "updates", "P"},
    // What the frame's resolution did to the bodies.
    {"bodies_after", "bodies_before + every change", "", "", "each body's state after resolution", "updates",
     "velocity_change rotation_change linear_change angular_change", "bodies_after", "F"},
};

}  // namespace

const std::vector<Annotation>& vocabulary() {
    return rows;
}

const Annotation* find_annotation(std::string_view quantity) {
    // Looked up for every row of every table the window draws: indexed once.
    static const std::unordered_map<std::string_view, const Annotation*> index = [] {
        std::unordered_map<std::string_view, const Annotation*> names;
        for (const Annotation& a : rows) names.emplace(a.quantity, &a);
        return names;
    }();
    const auto found = index.find(quantity);
    return found == index.end() ? nullptr : found->second;
}

const Annotation& annotation(std::string_view quantity) {
    const Annotation* found = find_annotation(quantity);
    assert(found && "every vocabulary name has an annotation");
    return found ? *found : rows.front();
}

std::vector<std::string_view> inputs_of(const Annotation& a) {
    std::vector<std::string_view> names;
    std::string_view rest = a.inputs;
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (space != 0) names.push_back(rest.substr(0, space));
        if (space == std::string_view::npos) break;
        rest.remove_prefix(space + 1);
    }
    return names;
}

std::vector<std::string_view> consumers(std::string_view quantity) {
    // The rows are in derivation order, but a row may name a later one (impulse_model reads the friction
    // solve it chooses between), so the closure is grown until it stops changing.
    std::set<std::string_view> reached{quantity};
    std::vector<std::string_view> found;
    for (bool grew = true; grew;) {
        grew = false;
        for (const Annotation& a : rows) {
            if (reached.count(a.quantity)) continue;
            for (std::string_view input : inputs_of(a))
                if (reached.count(input)) {
                    reached.insert(a.quantity);
                    found.push_back(a.quantity);
                    grew = true;
                    break;
                }
        }
    }
    return found;
}

const Annotation* quantity_of_path(std::string_view path, ItemKind item) {
    // The path's keys without indices: "updates[0].after[0]" -> "updates.after".
    std::string keys;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '[') {
            i = path.find(']', i);
            if (i == std::string_view::npos) break;
            continue;
        }
        keys += path[i];
    }
    const char kind = item == ItemKind::contact ? 'C' : item == ItemKind::position_iteration ? 'P' : 'V';
    const Annotation* best = nullptr;
    std::size_t best_length = 0;
    for (const Annotation& a : rows) {
        if (a.items.find(kind) == std::string_view::npos) continue;
        const std::string_view key = a.trace_key.empty() ? a.quantity : a.trace_key;
        // The whole path, or a key that holds it ("updates" holds "updates.after").
        const bool holds =
            keys == key || (keys.size() > key.size() && keys.starts_with(key) && keys[key.size()] == '.');
        if (holds && key.size() > best_length) best = &a, best_length = key.size();
    }
    return best;
}

}  // namespace impulse::explain
