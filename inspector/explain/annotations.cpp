#include "explain/annotations.hpp"

#include <array>
#include <cassert>

namespace impulse::explain {

namespace {

constexpr std::array annotations{
    // Step 1: basis
    Annotation{"normal", "n, from collision detection", "", "", "the way body 0 must move to separate"},
    Annotation{"tangent_seed", "Y if |n.x| > |n.y|, else X", "", "",
               "world axis farther from n: seed × n never vanishes"},
    Annotation{"tangent1", "t₁ = normalise(seed × n)", "", "", "first sliding direction (contact y)"},
    Annotation{"tangent2", "t₂ = n × t₁", "", "", "second sliding direction (contact z)"},
    Annotation{"basis", "C = [n t₁ t₂] (columns)", "", "", "contact → world; Cᵀ maps world → contact"},
    // Step 2
    Annotation{"relative_position", "q_rel = q − p", "(1.8)", "m", "the contact point seen from the body's centre"},
    // Step 3
    Annotation{"torque_per_unit_impulse", "u = q_rel × n", "(14.2)", "N·m·s per N·s",
               "impulsive torque of a unit impulse along n"},
    Annotation{"rotation_per_unit_impulse", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s per N·s",
               "change of spin that torque causes"},
    Annotation{"velocity_per_unit_impulse", "Δθ̇ × q_rel", "(9.5)", "m/s per N·s",
               "velocity that spin gives the contact point"},
    Annotation{"angular_component", "(Δθ̇ × q_rel) · n", "", "m/s per N·s", "its part along the normal"},
    Annotation{"linear_component", "m⁻¹", "(7.5)", "m/s per N·s", "linear velocity change per unit impulse"},
    Annotation{"delta_velocity_per_unit_impulse", "d = Σ (m⁻¹ + angular)", "", "m/s per N·s",
               "how fast the points separate per unit impulse"},
    // Step 4
    Annotation{"point_velocity", "θ̇ × q_rel + ṗ", "(9.5)", "m/s", "velocity of the body's contact point"},
    Annotation{"tangential_acceleration_velocity", "tangential part of a_last Δt", "ch. 15", "m/s",
               "sliding last frame's forces caused: friction removes it"},
    Annotation{"contact_velocity", "Cᵀ (v₀ − v₁)", "", "m/s",
               "x: separating velocity v_s (< 0 closing); y, z: sliding"},
    // Step 5
    Annotation{"separating_velocity", "v_s = contact_velocity.x", "", "m/s", "negative: the points are closing"},
    Annotation{"restitution", "c", "", "", "share of the closing speed given back"},
    Annotation{"restitution_cutoff", "|v_s| < cut-off ⇒ c = 0", "ch. 15", "m/s",
               "slow contacts do not bounce (no jitter)"},
    Annotation{"restitution_used", "c, or 0 below the cut-off", "", "", "the restitution this contact gets now"},
    Annotation{"velocity_from_acceleration", "(a₀ − a₁) · n Δt", "ch. 15", "m/s",
               "closing speed last frame's forces added: not bounced"},
    Annotation{"desired_delta_velocity", "Δv = −v_s − c (v_s − v_acc)", "v_s' = −c v_s", "m/s",
               "change of separating velocity the impulse must make"},
    // Step 6
    Annotation{"impulse_model", "μ = 0: frictionless; else 3×3 solve + cone", "", "",
               "which impulse calculation applies"},
    Annotation{"delta_velocity_matrix", "K = Cᵀ(Σ m⁻¹ − [q_rel]× I⁻¹ [q_rel]×)C", "ch. 15", "m/s per N·s",
               "velocity change per unit impulse, every direction"},
    Annotation{"target_delta_velocity", "(Δv, −v_t₁, −v_t₂)", "ch. 15", "m/s", "bounce as desired, stop all sliding"},
    Annotation{"static_impulse", "K⁻¹ · target", "ch. 15", "N·s", "the impulse if friction can hold"},
    Annotation{"tangential_impulse", "|(g_t₁, g_t₂)|", "ch. 15", "N·s", "sideways part of the static impulse"},
    Annotation{"cone_limit", "μ g_n", "ch. 15", "N·s", "most sideways impulse friction can give"},
    Annotation{"sliding_direction", "(g_t₁, g_t₂) / |(g_t₁, g_t₂)|", "ch. 15", "",
               "direction kept once the contact slides"},
    Annotation{"sliding_normal_response", "K₀₀ + μ (K₀₁ ŷ + K₀₂ ẑ)", "ch. 15", "m/s per N·s",
               "normal velocity change per unit normal impulse, sliding"},
    // Accumulating solvers (projected Gauss-Seidel, soft step): Catto's sequential impulses
    Annotation{"position_bias", "β max(d − slop, 0) / Δt", "Baumgarte", "m/s",
               "extra separating speed asked for, to push out the penetration"},
    Annotation{"accumulated_before", "λ, this frame's total so far", "", "N·s",
               "impulse this contact has given so far (x normal, y, z sliding)"},
    Annotation{"accumulated_unclamped", "λ + Δv / d", "", "N·s", "the total this visit asks for, before its limits"},
    Annotation{"clamp", "λ_n ≥ 0, |λ_t| ≤ μ λ_n", "", "",
               "which limit applied: a contact can only push, friction stays inside its cone"},
    Annotation{"accumulated_after", "clamp(λ + Δv / d)", "", "N·s",
               "the new total; only its change is applied, so a later visit can take back an earlier push"},
    Annotation{"impulse_contact", "g = Δv / d, (g, 0, 0)", "(14.3)", "N·s", "the impulse in contact coordinates"},
    Annotation{"impulse_world", "C · impulse_contact", "", "N·s", "+ on body 0, − on body 1"},
    // Step 7
    Annotation{"impulsive_torque", "u = q_rel × g", "(14.2)", "N·m·s", "turning effect of the impulse on the body"},
    Annotation{"velocity_change", "Δṗ = g m⁻¹", "(7.5)", "m/s", "change of the body's linear velocity"},
    Annotation{"rotation_change", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s", "change of the body's angular velocity"},
    // Step 8
    Annotation{"penetration", "from collision detection", "", "m", "overlap along the normal"},
    Annotation{"amount", "penetration (× fraction)", "", "m", "how much of it this move removes"},
    Annotation{"linear_inertia", "m⁻¹", "", "m/s per N·s", "how readily the body gives way by moving"},
    Annotation{"angular_inertia", "((I⁻¹(q_rel × n)) × q_rel) · n", "", "m/s per N·s",
               "how readily it gives way by turning"},
    Annotation{"total_inertia", "Σ (linear + angular)", "", "m/s per N·s", "all the give at this contact"},
    Annotation{"linear_move", "±amount · linear / total", "", "m", "distance removed by moving the body"},
    Annotation{"angular_move", "±amount · angular / total", "", "m", "distance removed by turning the body"},
    Annotation{"angular_limit", "|angular_move| ≤ maximum", "", "m", "largest turn allowed; the excess moves linearly"},
    Annotation{"linear_move_before", "before the limit", "", "m", "the linear share the inertias asked for"},
    Annotation{"angular_move_before", "before the limit", "", "m", "the angular share the inertias asked for"},
    Annotation{"linear_change", "n · linear_move", "", "m", "the translation applied to the body"},
    Annotation{"angular_change", "I⁻¹(q_rel × n) · angular_move / angular", "", "rad",
               "the rotation applied (axis × angle)"},
    Annotation{"closing_velocity", "−(v_p₀ − v_p₁) · n", "", "m/s", "how fast the contact points approach"},
    Annotation{"rewind_time", "t = min(penetration / closing, Δt)", "", "s",
               "how far back along their paths the bodies go"},
    Annotation{"removed_penetration", "closing_velocity · t", "", "m", "penetration the paths explain"},
    Annotation{"rewind_linear_change", "−ṗ t", "", "m", "translation back along the path"},
    Annotation{"rewind_angular_change", "−θ̇ t", "", "rad", "rotation back along the path"},
};

}  // namespace

const Annotation* find_annotation(std::string_view quantity) {
    for (const Annotation& a : annotations)
        if (a.quantity == quantity) return &a;
    return nullptr;
}

const Annotation& annotation(std::string_view quantity) {
    const Annotation* found = find_annotation(quantity);
    assert(found && "every vocabulary name has an annotation");
    return found ? *found : annotations.front();
}

}  // namespace impulse::explain
