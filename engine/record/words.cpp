#include "record/words.hpp"

#include <algorithm>
#include <array>

namespace impulse::words {

namespace {

constexpr Kind integer = Kind::integer, number = Kind::number, boolean = Kind::boolean, word = Kind::word,
               vec2 = Kind::vec2, vec3 = Kind::vec3, mat3 = Kind::mat3, per_body_number = Kind::per_body_number,
               per_body_vec3 = Kind::per_body_vec3, per_body_bool = Kind::per_body_bool, bodies = Kind::bodies,
               object = Kind::object, list = Kind::list, none = Kind::none;
constexpr Role given = Role::given, setting = Role::setting, computed = Role::computed, context = Role::context;

// One row per word, in the order the derivation computes them. `inputs` name other rows; tests check that every
// input is a row, that the inputs never loop, that every stored word is a key of the schema with the same kind,
// and that every key the trace writes is a word here.
// Columns: quantity, formula, equation, unit, meaning, step, inputs, items, kind, role, stored_at, format1.
constexpr std::array table{
    // What a body brings: its state before the frame's resolution, its mass, last frame's acceleration.
    Word{"body_position", "p", "", "m", "the body's centre", step::body, "", "", none, given,
         "bodies_before[].position"},
    Word{"body_velocity", "ṗ", "", "m/s", "the body's velocity", step::body, "", "", none, given,
         "bodies_before[].velocity"},
    Word{"body_angular_velocity", "θ̇", "", "rad/s", "the body's angular velocity", step::body, "", "", none, given,
         "bodies_before[].angular_velocity"},
    Word{"body_inverse_mass", "m⁻¹", "", "1/kg", "the body's inverse mass", step::body, "", "", none, given,
         "scene.bodies[].inverse_mass"},
    Word{"body_inverse_inertia", "I⁻¹ = R I⁻¹_body Rᵀ", "", "1/(kg·m²)", "inverse inertia tensor, world coordinates",
         step::body, "", "", none, given, "bodies_before[].inverse_inertia_world"},
    Word{"body_acceleration", "a, last frame's", "ch. 15", "m/s²", "what last frame's forces did to the body",
         step::body, "", "", none, given, "(not recorded)"},

    // --- a prepared contact: what it is given, then steps 1-5 ----------------------------------------------
    Word{"contact", "index into the frame's contacts", "", "", "which contact this is", step::contact, "", "C",
         integer, given},
    Word{"swapped", "world given as body 0 ⇒ exchanged", "", "",
         "the bodies were exchanged and the normal reversed when read", step::contact, "", "C", boolean, given},
    Word{"bodies", "[body 0, body 1], world last", "", "", "the two bodies, after any swap", step::contact, "swapped",
         "C", bodies, given},
    Word{"inert", "both inverse masses 0", "", "", "never resolved: nothing can move", step::contact, "", "C",
         boolean, given},
    Word{"point", "q, from collision detection", "", "m", "the contact point, world", step::contact, "", "C", vec3,
         given},
    Word{"normal", "n, from collision detection", "", "", "the way body 0 must move to separate", step::contact,
         "swapped", "C", vec3, given},
    Word{"penetration", "from collision detection", "", "m", "overlap along the normal", step::contact, "", "C",
         number, given},
    Word{"restitution", "c", "", "", "share of the closing speed given back", step::contact, "", "C", number, given},
    Word{"restitution", "c, the contact's", "", "", "share of the closing speed given back", step::settings, "", "V",
         number, setting},
    Word{"friction", "μ", "", "", "friction coefficient (0: frictionless)", step::contact, "", "C", number, given},
    Word{"origin", "the test and the features that made the contact", "", "", "why the contact exists",
         step::contact, "", "C", object, context},
    Word{"origin.test", "explicit, sphere_sphere, sphere_half_space, box_half_space, box_sphere or box_box", "", "",
         "the collision test that found it", step::contact, "", "C", word, context},
    Word{"origin.features", "[body0, body1]", "", "", "the feature of each body that touches", step::contact, "", "C",
         list, context},
    Word{"origin.features[].kind", "face, edge, vertex, sphere, plane or none", "", "", "what kind of feature",
         step::contact, "", "C", word, context},
    Word{"origin.features[].index", "box numbering in docs/scenes.md; −1 where none applies", "", "",
         "which feature", step::contact, "", "C", integer, context},
    // Step 1: basis
    Word{"tangent_seed", "Y if |n.x| > |n.y|, else X", "", "", "world axis farther from n: seed × n never vanishes",
         step::basis, "normal", "C", word},
    Word{"tangent1", "t₁ = normalise(seed × n)", "", "", "first sliding direction (contact y)", step::basis,
         "normal tangent_seed", "", none, computed, "basis (column 1)"},
    Word{"tangent2", "t₂ = n × t₁", "", "", "second sliding direction (contact z)", step::basis, "normal tangent1", "",
         none, computed, "basis (column 2)"},
    Word{"basis", "C = [n t₁ t₂] (columns)", "", "", "contact → world; Cᵀ maps world → contact", step::basis,
         "normal tangent1 tangent2", "C", mat3},
    // Step 2
    Word{"relative_position", "q_rel = q − p", "(1.8)", "m", "the contact point seen from the body's centre",
         step::relative_position, "point body_position bodies", "C", per_body_vec3},
    // Step 3
    Word{"torque_per_unit_impulse", "u = q_rel × n", "(14.2)", "N·m·s per N·s",
         "impulsive torque of a unit impulse along n", step::delta_velocity_per_unit_impulse,
         "relative_position normal", "C", per_body_vec3},
    Word{"rotation_per_unit_impulse", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s per N·s", "change of spin that torque causes",
         step::delta_velocity_per_unit_impulse, "torque_per_unit_impulse body_inverse_inertia", "C", per_body_vec3},
    Word{"point_velocity_per_unit_impulse", "Δθ̇ × q_rel", "(9.5)", "m/s per N·s",
         "velocity that spin gives the contact point", step::delta_velocity_per_unit_impulse,
         "rotation_per_unit_impulse relative_position", "C", per_body_vec3, computed, {},
         "velocity_per_unit_impulse"},
    Word{"angular_component", "(Δθ̇ × q_rel) · n", "", "m/s per N·s", "its part along the normal",
         step::delta_velocity_per_unit_impulse, "point_velocity_per_unit_impulse normal", "C", per_body_number},
    Word{"linear_component", "m⁻¹", "(7.5)", "m/s per N·s", "linear velocity change per unit impulse",
         step::delta_velocity_per_unit_impulse, "body_inverse_mass bodies", "C", per_body_number},
    Word{"delta_velocity_per_unit_impulse", "d = Σ (m⁻¹ + angular)", "", "m/s per N·s",
         "how fast the points separate per unit impulse", step::delta_velocity_per_unit_impulse,
         "angular_component linear_component", "C", number},
    // Step 4
    Word{"point_velocity", "θ̇ × q_rel + ṗ", "(9.5)", "m/s", "velocity of the body's contact point",
         step::contact_velocity, "relative_position body_velocity body_angular_velocity", "C", per_body_vec3},
    Word{"tangential_acceleration_velocity", "tangential part of a_last Δt", "ch. 15", "m/s",
         "sliding last frame's forces caused: friction removes it", step::contact_velocity, "body_acceleration basis",
         "C", per_body_vec3},
    Word{"contact_velocity", "Cᵀ (v₀ − v₁)", "", "m/s", "x: separating velocity v_s (< 0 closing); y, z: sliding",
         step::contact_velocity, "point_velocity tangential_acceleration_velocity basis", "CV", vec3},
    // Step 5
    Word{"separating_velocity", "v_s = contact_velocity.x", "", "m/s", "negative: the points are closing",
         step::desired_delta_velocity, "contact_velocity", "CV", number},
    Word{"restitution_cutoff", "setting restitution_cutoff", "ch. 15", "m/s", "slow contacts do not bounce (no jitter)",
         step::settings, "", "CV", number, setting},
    Word{"restitution_cutoff_applied", "|v_s| < cut-off ⇒ c = 0", "ch. 15", "",
         "whether the cut-off took the bounce away", step::desired_delta_velocity,
         "separating_velocity restitution_cutoff", "CV", boolean},
    Word{"restitution_used", "c, or 0 below the cut-off", "", "", "the restitution this contact gets now",
         step::desired_delta_velocity, "restitution restitution_cutoff_applied", "CV", number},
    Word{"velocity_from_acceleration_applied", "setting velocity_from_acceleration", "ch. 15", "",
         "last frame's acceleration is taken out of the bounce", step::settings, "", "CV", boolean, setting},
    Word{"velocity_from_acceleration", "(a₀ − a₁) · n Δt", "ch. 15", "m/s",
         "closing speed last frame's forces added: not bounced", step::desired_delta_velocity,
         "body_acceleration normal velocity_from_acceleration_applied", "CV", number},
    // Baumgarte's term: the penetration is written out, not called d, which names the per-unit-impulse response.
    Word{"position_bias", "β max(penetration − slop, 0) / Δt", "Baumgarte", "m/s",
         "extra separating speed asked for, to push out the penetration", step::desired_delta_velocity, "penetration",
         "CV", number},
    Word{"desired_delta_velocity", "Δv = −v_s − c (v_s − v_acc)", "v_s' = −c v_s", "m/s",
         "change of separating velocity the impulse must make", step::desired_delta_velocity,
         "separating_velocity restitution_used velocity_from_acceleration position_bias", "CV", number},

    // --- an iteration's choice ------------------------------------------------------------------------------
    Word{"iteration", "counts from 0 within the phase", "", "", "which iteration", step::choice, "", "PV", integer,
         given},
    Word{"contact", "argmax over contacts above ε", "", "", "the contact this iteration resolves", step::choice, "",
         "PV", integer, given},
    Word{"penetration", "the chosen contact's, now", "", "m", "its penetration, compared with the epsilon",
         step::choice, "", "P", number},
    Word{"epsilon", "setting position_epsilon", "", "m", "penetrations at or below it are left alone", step::choice,
         "", "P", number, given},
    Word{"epsilon", "setting velocity_epsilon", "", "m/s", "desired velocity changes at or below it are left alone",
         step::choice, "", "V", number, given},
    Word{"pass", "relaxation: the pass; split impulse: the push sweep", "", "", "which pass over the contacts",
         step::choice, "", "P", integer, given},
    Word{"sweep", "sub-step, stage and sweep", "", "", "where a sweeping solver was when it visited the contact",
         step::choice, "", "V", object, given},
    Word{"sweep.substep", "soft step's sub-step; else 0", "", "", "which sub-step", step::choice, "", "V", integer,
         given},
    Word{"sweep.pass", "the sweep within its stage", "", "", "which sweep", step::choice, "", "V", integer, given},
    Word{"sweep.stage", "warm_start, solve, relax, restitution or push", "", "", "what the sweep was doing",
         step::choice, "", "V", word, given},

    // --- a velocity iteration: the accumulating solvers' running total (Catto's sequential impulses) ----------
    Word{"accumulated", "λ before, unclamped, after, and the clamp", "", "",
         "the running total of an accumulating solver, contact coordinates", step::accumulated, "", "V", object},
    Word{"accumulated.before", "λ, this frame's total so far", "", "N·s",
         "impulse this contact has given so far (x normal, y, z sliding)", step::accumulated, "", "V", vec3, computed,
         {}, {}},
    Word{"accumulated.unclamped", "λ + Δv / d", "", "N·s", "the total this visit asks for, before its limits",
         step::accumulated, "accumulated.before desired_delta_velocity delta_velocity_per_unit_impulse", "V", vec3},
    Word{"accumulated.clamp", "λ_n ≥ 0, |λ_t| ≤ μ λ_n", "", "",
         "which limit applied: a contact can only push, friction stays inside its cone", step::accumulated,
         "accumulated.unclamped friction", "V", word},
    Word{"accumulated.after", "clamp(λ + Δv / d)", "", "N·s",
         "the new total; only its change is applied, so a later visit can take back an earlier push",
         step::accumulated, "accumulated.unclamped accumulated.clamp", "V", vec3},
    // Step 6
    Word{"impulse_model", "μ = 0: frictionless; else 3×3 solve + cone", "", "", "which impulse calculation applies",
         step::impulse, "friction friction_solve.tangential_impulse friction_solve.cone_limit accumulated.clamp", "V",
         word},
    Word{"friction_solve", "K, its target and its solution", "ch. 15", "", "the friction solve of a contact with μ > 0",
         step::impulse, "", "V", object},
    Word{"friction_solve.delta_velocity_matrix", "K = Cᵀ(Σ m⁻¹ − [q_rel]× I⁻¹ [q_rel]×)C", "ch. 15", "m/s per N·s",
         "velocity change per unit impulse, every direction", step::impulse,
         "relative_position body_inverse_mass body_inverse_inertia basis", "V", mat3},
    Word{"friction_solve.target_delta_velocity", "(Δv, −v_t₁, −v_t₂)", "ch. 15", "m/s",
         "bounce as desired, stop all sliding", step::impulse, "desired_delta_velocity contact_velocity", "V", vec3},
    Word{"friction_solve.solvable", "K invertible, response > 0", "ch. 15", "",
         "whether the friction solve could be used", step::impulse, "friction_solve.delta_velocity_matrix", "V",
         boolean},
    Word{"friction_solve.static_impulse", "K⁻¹ · target", "ch. 15", "N·s", "the impulse if friction can hold",
         step::impulse, "friction_solve.delta_velocity_matrix friction_solve.target_delta_velocity", "V", vec3},
    Word{"friction_solve.tangential_impulse", "|(g_t₁, g_t₂)|", "ch. 15", "N·s", "sideways part of the static impulse",
         step::impulse, "friction_solve.static_impulse", "V", number},
    Word{"friction_solve.cone_limit", "μ g_n", "ch. 15", "N·s", "most sideways impulse friction can give",
         step::impulse, "friction_solve.static_impulse friction", "V", number},
    Word{"friction_solve.sliding_direction", "(g_t₁, g_t₂) / |(g_t₁, g_t₂)|", "ch. 15", "",
         "direction kept once the contact slides", step::impulse, "friction_solve.static_impulse", "V", vec2},
    Word{"friction_solve.sliding_normal_response", "K₀₀ + μ (K₀₁ ŷ + K₀₂ ẑ)", "ch. 15", "m/s per N·s",
         "normal velocity change per unit normal impulse, sliding", step::impulse,
         "friction_solve.delta_velocity_matrix friction_solve.sliding_direction friction", "V", number},
    Word{"impulse", "g = Δv / d, (g, 0, 0)", "(14.3)", "N·s", "the impulse in contact coordinates", step::impulse,
         "desired_delta_velocity delta_velocity_per_unit_impulse impulse_model friction_solve.static_impulse "
         "friction_solve.sliding_direction friction_solve.sliding_normal_response friction_solve.cone_limit "
         "accumulated.before accumulated.after",
         "V", vec3, computed, {}, "impulse_contact"},
    Word{"impulse_world", "C · impulse", "", "N·s", "+ on body 0, − on body 1", step::impulse, "impulse basis", "V",
         vec3},
    // Step 7
    Word{"impulsive_torque", "u = q_rel × g", "(14.2)", "N·m·s", "turning effect of the impulse on the body",
         step::velocity_change, "relative_position impulse_world", "V", per_body_vec3},
    Word{"velocity_change", "Δṗ = g m⁻¹", "(7.5)", "m/s", "change of the body's linear velocity",
         step::velocity_change, "impulse_world body_inverse_mass", "V", per_body_vec3},
    Word{"rotation_change", "Δθ̇ = I⁻¹ u", "(14.1)", "rad/s", "change of the body's angular velocity",
         step::velocity_change, "impulsive_torque body_inverse_inertia", "V", per_body_vec3},
    Word{"velocity_update", "contact_velocity ± Cᵀ(Δṗ + Δθ̇ × q_rel), then desired_delta_velocity again", "", "m/s",
         "a contact sharing a body that changed speed: its velocity before → after", step::updates,
         "contact_velocity velocity_change rotation_change relative_position basis restitution_used", "", none,
         computed, "updates (a velocity iteration's)"},
    Word{"updates", "every contact sharing a body this iteration changed", "", "", "the other contacts' bookkeeping",
         step::updates, "", "PV", list},
    Word{"updates[].contact", "shares a changed body", "", "", "a contact whose velocity this impulse changes",
         step::updates, "", "V", integer, given},
    Word{"updates[].body", "index into the scene's bodies", "", "", "the body it shares", step::updates, "", "V",
         integer, given},
    Word{"updates[].slot", "0 or 1", "", "", "which of that contact's bodies it is", step::updates, "", "V", integer,
         given},
    Word{"updates[].delta", "±Cᵀ(velocity_change + rotation_change × q_rel)", "", "m/s",
         "change of its contact velocity (+ for its body 0, − for its body 1)", step::updates,
         "velocity_change rotation_change relative_position basis", "V", vec3},
    Word{"updates[].before", "its contact_velocity before", "", "m/s",
         "as earlier iterations left it, contact coordinates", step::updates, "", "V", vec3, given},
    Word{"updates[].after", "before + delta", "", "m/s", "its contact velocity now", step::updates,
         "updates[].before updates[].delta", "V", vec3},
    Word{"updates[].desired_delta_velocity_before", "its desired_delta_velocity before", "", "m/s",
         "as earlier iterations left it", step::updates, "", "V", number, given},
    Word{"updates[].desired_delta_velocity_after", "step 5 on the new contact_velocity", "", "m/s",
         "its desired velocity change now", step::updates, "updates[].after restitution_used", "V", number},

    // --- a position iteration: step 8 ------------------------------------------------------------------------
    Word{"method", "setting position_method", "", "", "how the penetration is removed", step::settings, "", "P", word,
         setting},
    // Velocity-based resolution's rewind.
    Word{"rewind", "move back along the paths", "", "", "velocity-based resolution's first move", step::rewind, "",
         "P", object},
    Word{"rewind.closing_velocity", "−(v_p₀ − v_p₁) · n", "", "m/s", "how fast the contact points approach",
         step::rewind, "body_velocity body_angular_velocity relative_position normal", "P", number},
    Word{"rewind.time_limit", "Δt, the frame's duration", "", "s", "the bodies go back at most to the start of the frame",
         step::settings, "", "P", number, setting},
    Word{"rewind.time", "t = min(penetration / closing, Δt)", "", "s", "how far back along their paths the bodies go",
         step::rewind, "penetration rewind.closing_velocity rewind.time_limit", "P", number},
    Word{"rewind.removed_penetration", "closing_velocity · t", "", "m", "penetration the paths explain", step::rewind,
         "rewind.closing_velocity rewind.time", "P", number},
    Word{"rewind.linear_change", "−ṗ t", "", "m", "translation back along the path", step::rewind,
         "body_velocity rewind.time", "P", per_body_vec3},
    Word{"rewind.angular_change", "−θ̇ t", "", "rad", "rotation back along the path", step::rewind,
         "body_angular_velocity rewind.time", "P", per_body_vec3},
    // Projection.
    Word{"amount", "penetration", "", "m", "how much of it this move removes", step::penetration_inertia,
         "penetration rewind.removed_penetration method", "P", number},
    // The split impulse pushes with an impulse, not a distance: its own word, in its own unit.
    Word{"push_impulse", "λ_after − λ_before of the push sweep", "", "N·s",
         "split impulse: the pseudo-impulse this visit adds to the push", step::penetration_inertia,
         "penetration delta_velocity_per_unit_impulse", "P", number, computed, {}, "amount"},
    Word{"linear_inertia", "m⁻¹", "", "m/s per N·s", "how readily the body gives way by moving",
         step::penetration_inertia, "body_inverse_mass", "P", per_body_number},
    Word{"angular_inertia", "((I⁻¹(q_rel × n)) × q_rel) · n", "", "m/s per N·s", "how readily it gives way by turning",
         step::penetration_inertia, "relative_position normal body_inverse_inertia", "P", per_body_number},
    Word{"penetration_inertia", "Σ (linear + angular)", "", "m/s per N·s", "all the give at this contact",
         step::penetration_inertia, "linear_inertia angular_inertia", "P", number, computed, {}, "total_inertia"},
    Word{"angular_limit", "the limit on the angular move", "", "", "nonlinear projection's cap on turning",
         step::move_split, "", "P", object},
    Word{"angular_limit.linear_move_before", "±amount · linear / total", "", "m",
         "the linear share the inertias asked for", step::move_split, "amount linear_inertia penetration_inertia", "P",
         per_body_number},
    Word{"angular_limit.angular_move_before", "±amount · angular / total", "", "m",
         "the angular share the inertias asked for", step::move_split, "amount angular_inertia penetration_inertia",
         "P", per_body_number},
    Word{"angular_limit.policy", "setting angular_limit.policy", "", "",
         "how the largest turn is set: none, fixed, lever_arm, angle", step::settings, "", "P", word, setting},
    Word{"angular_limit.factor", "setting angular_limit.factor", "", "", "the limit's scale", step::settings, "", "P",
         number, setting},
    Word{"angular_limit.maximum", "maximum |angular_move|", "", "m", "largest turn allowed; the excess moves linearly",
         step::move_split, "relative_position normal angular_limit.policy angular_limit.factor", "P", per_body_number},
    Word{"angular_limit.applied", "|angular_move_before| > maximum", "", "",
         "whether the limit cut the angular move back", step::move_split,
         "angular_limit.angular_move_before angular_limit.maximum", "P", per_body_bool},
    Word{"move_split", "the move shared between moving and turning", "", "", "each body's share of the move",
         step::move_split, "", "P", object},
    Word{"move_split.linear_move", "±amount · linear / total", "", "m", "distance removed by moving the body",
         step::move_split,
         "amount linear_inertia penetration_inertia angular_limit.applied angular_limit.maximum "
         "angular_limit.angular_move_before angular_limit.linear_move_before",
         "P", per_body_number, computed, {}, "linear_move"},
    Word{"move_split.angular_move", "±amount · angular / total", "", "m", "distance removed by turning the body",
         step::move_split,
         "amount angular_inertia penetration_inertia angular_limit.applied angular_limit.maximum "
         "angular_limit.angular_move_before",
         "P", per_body_number, computed, {}, "angular_move"},
    Word{"position_change", "the translation and rotation applied", "", "", "the move applied to each body",
         step::position_change, "", "P", object},
    Word{"position_change.linear_change", "n · linear_move", "", "m", "the translation applied to the body",
         step::position_change, "move_split.linear_move normal rewind.linear_change", "P", per_body_vec3, computed, {},
         "linear_change"},
    Word{"position_change.angular_change", "I⁻¹(q_rel × n) · angular_move / angular", "", "rad",
         "the rotation applied (axis × angle)", step::position_change,
         "move_split.angular_move angular_inertia rotation_per_unit_impulse rewind.angular_change", "P", per_body_vec3,
         computed, {}, "angular_change"},
    Word{"penetration_update", "before ∓ (linear_change + angular_change × q_rel) · n", "", "m",
         "a contact sharing a moved body: its penetration before → after", step::updates,
         "penetration position_change.linear_change position_change.angular_change relative_position normal", "",
         none, computed, "updates (a position iteration's)"},
    Word{"updates[].contact", "shares a moved body", "", "", "a contact whose penetration this move changes",
         step::updates, "", "P", integer, given},
    Word{"updates[].body", "index into the scene's bodies", "", "", "the moved body it shares", step::updates, "", "P",
         integer, given},
    Word{"updates[].slot", "0 or 1", "", "", "which of that contact's bodies it is", step::updates, "", "P", integer,
         given},
    Word{"updates[].before", "its penetration before", "", "m", "as earlier iterations left it", step::updates, "",
         "P", number, given},
    Word{"updates[].delta", "∓(linear_change + angular_change × q_rel) · n", "", "m",
         "change of its penetration (− for its body 0, + for its body 1)", step::updates,
         "position_change.linear_change position_change.angular_change relative_position normal", "P", number},
    Word{"updates[].after", "before + delta", "", "m", "its penetration now", step::updates,
         "updates[].before updates[].delta", "P", number},

    // What the frame's resolution did to the bodies.
    Word{"bodies_after", "bodies_before + every change", "", "", "each body's state after resolution", step::updates,
         "velocity_change rotation_change position_change.linear_change position_change.angular_change", "", none,
         computed, "bodies_after"},
};

constexpr std::array renamed_steps{
    StepRename{"velocity_per_unit_impulse", step::delta_velocity_per_unit_impulse},
    StepRename{"accumulated_impulse", step::accumulated},
};

}  // namespace

std::span<const StepRename> step_renames() {
    return renamed_steps;
}

std::span<const Word> all() {
    return table;
}

const Word* find(std::string_view quantity) {
    const auto found = std::find_if(table.begin(), table.end(), [&](const Word& w) { return w.quantity == quantity; });
    return found == table.end() ? nullptr : &*found;
}

const Word* find(std::string_view quantity, char item) {
    for (const Word& w : table)
        if (w.quantity == quantity && held_by(w, item)) return &w;
    return nullptr;
}

bool is_per_body(Kind kind) {
    return kind == Kind::per_body_number || kind == Kind::per_body_vec3 || kind == Kind::per_body_bool;
}

}  // namespace impulse::words
