#include "explain/derivation_table.hpp"

#include "explain/annotations.hpp"
#include "explain/avbd_tables.hpp"
#include "explain/format.hpp"
#include "formats/words.hpp"
#include "formats/settings_names.hpp"

#include <algorithm>
#include <map>
#include <variant>

namespace impulse::explain {

namespace {

// Collects the rows of one step with their raw values, and formats them once all are known: a value is
// rounding noise (and shown as 0) when it is below noise_fraction of the largest value of the same unit in
// the table. Formula, equation, unit and meaning come from the vocabulary unless a row says otherwise.
class Table {
public:
    // `contact_to_world` is the contact's basis when known: vectors are then also shown in the other frame.
    Table(std::string step, std::string title, const Mat3* contact_to_world = nullptr)
        : step_(std::move(step)), title_(std::move(title)), basis_(contact_to_world) {}

    using Value = std::variant<std::string, double, Vec3, Mat3>;

    // `note` follows the unit: "0.25 m/s (not applied)"; `formula` replaces the vocabulary's.
    Table& row(std::string_view key, Value value, std::optional<int> body = std::nullopt, std::string_view formula = {},
               std::string_view note = {}) {
        const Annotation& a = annotation(key);
        std::string quantity(key);
        if (body) quantity += "[" + std::to_string(*body) + "]";
        pending_.push_back({std::move(quantity),
                            std::string(key),
                            std::move(value),
                            std::string(a.unit),
                            std::string(formula.empty() ? a.formula : formula),
                            std::string(a.equation),
                            std::string(a.meaning),
                            std::string(note),
                            std::nullopt,
                            {}});
        return *this;
    }

    // One row per body present (body 1 is absent when it is the world).
    template <typename T>
    Table& per_body(std::string_view key, const PerBody<T>& values, std::string_view formula = {}) {
        for (int i = 0; i < 2; ++i)
            if (values[i]) row(key, *values[i], i, formula);
        return *this;
    }

    // A world vector, shown in contact coordinates too (C^T v): e.g. q_rel along the normal and tangents.
    Table& world_vector(std::string_view key, const Vec3& v, std::optional<int> body = std::nullopt,
                        std::string_view formula = {}) {
        row(key, v, body, formula);
        if (basis_) pending_.back().other = basis_->transpose() * v, pending_.back().other_prefix = "contact ";
        return *this;
    }
    Table& world_vectors(std::string_view key, const PerBody<Vec3>& values, std::string_view formula = {}) {
        for (int i = 0; i < 2; ++i)
            if (values[i]) world_vector(key, *values[i], i, formula);
        return *this;
    }
    // A vector in contact coordinates, shown in world coordinates too (C v).
    Table& contact_vector(std::string_view key, const Vec3& v, std::string_view formula = {}) {
        row(key, v, std::nullopt, formula);
        if (basis_) pending_.back().other = *basis_ * v, pending_.back().other_prefix = "world ";
        return *this;
    }

    // Replaces the equation of the row just added (the same quantity can come from another equation).
    Table& equation(std::string_view text) {
        pending_.back().equation = std::string(text);
        return *this;
    }
    // Replaces the unit of the row just added (a method that records another kind of value under the key).
    Table& unit(std::string_view text) {
        pending_.back().unit = std::string(text);
        return *this;
    }

    StepTable done() {
        std::map<std::string, double> scale;
        const auto grow = [&scale](const std::string& unit, double size) {
            double& s = scale[unit];
            s = std::max(s, size);
        };
        for (const Pending& p : pending_) {
            if (const double* x = std::get_if<double>(&p.value)) grow(p.unit, std::abs(*x));
            if (const Vec3* v = std::get_if<Vec3>(&p.value)) grow(p.unit, v->cwiseAbs().maxCoeff());
            if (const Mat3* m = std::get_if<Mat3>(&p.value)) grow(p.unit, m->cwiseAbs().maxCoeff());
            if (p.other) grow(p.unit, p.other->cwiseAbs().maxCoeff());
        }
        StepTable table{step_, title_, {}};
        for (const Pending& p : pending_) {
            const double s = scale[p.unit];
            std::string shown, exact_text;
            if (const std::string* t = std::get_if<std::string>(&p.value))
                shown = *t, exact_text = *t;
            else if (const double* x = std::get_if<double>(&p.value))
                shown = with_unit(number(*x, s), p.unit), exact_text = with_unit(exact(*x), p.unit);
            else if (const Vec3* v = std::get_if<Vec3>(&p.value))
                shown = with_unit(vector(*v, s), p.unit), exact_text = with_unit(exact(*v), p.unit);
            else if (const Mat3* m = std::get_if<Mat3>(&p.value))
                shown = with_unit(matrix_rows(*m, s), p.unit), exact_text = with_unit(exact(*m), p.unit);
            if (!p.note.empty()) shown += " (" + p.note + ")";
            std::string other;
            if (p.other) other = p.other_prefix + vector(*p.other, s);
            table.rows.push_back(
                {p.quantity, shown, p.formula, p.equation, p.meaning, std::move(other), p.key, std::move(exact_text)});
        }
        return table;
    }

private:
    struct Pending {
        std::string quantity, key;
        Value value;
        std::string unit, formula, equation, meaning, note;
        std::optional<Vec3> other;
        std::string other_prefix;
    };
    std::string step_, title_;
    const Mat3* basis_;
    std::vector<Pending> pending_;
};

template <typename Member>
auto unit_response_field(const UnitImpulseChain& chain, Member member) {
    PerBody<std::decay_t<decltype(std::declval<UnitImpulseResponse>().*member)>> values;
    for (int i = 0; i < 2; ++i)
        if (chain.bodies[i]) values[i] = (*chain.bodies[i]).*member;
    return values;
}

std::string yes_no(bool value, std::string_view yes, std::string_view no) {
    return std::string(value ? yes : no);
}

// How a velocity iteration's desired Δv was made. `accumulating`: projected Gauss-Seidel or soft step, whose
// Δv is the rest of the way to the visit's target (a warm start's: what re-applying the total does);
// Baumgarte's bias (or soft step's soft push) is a term of the step when the record holds one.
std::string desired_formula(const DesiredDeltaVelocity& d, bool accumulating, bool warm_start) {
    if (accumulating && warm_start) return "(K λ)_n: the normal change the re-applied total makes";
    if (accumulating)
        return d.position_bias ? "Δv = target − v_s (target: the bounce judged at preparation + position_bias)"
                               : "Δv = target − v_s (target: the bounce judged at preparation)";
    const bool plain = !d.velocity_from_acceleration_applied && !d.restitution_cutoff_applied;
    std::string formula = plain ? "Δv = −(1 + c) v_s" : "Δv = −v_s − c (v_s − v_acc)";
    if (d.position_bias) formula += " + position_bias";
    return formula;
}

StepTable desired_table(const DesiredDeltaVelocity& d, bool accumulating = false, bool warm_start = false) {
    Table t(std::string(formats::words::step::desired_delta_velocity),
            "desired_delta_velocity — the velocity change the impulse must make");
    t.row("separating_velocity", d.separating_velocity);
    t.row("restitution", d.restitution);
    if (d.restitution_cutoff > 0.0) {
        t.row("restitution_cutoff", d.restitution_cutoff);
        t.row("restitution_cutoff_applied",
              yes_no(d.restitution_cutoff_applied, "yes: |v_s| is below the cut-off, c = 0", "no"));
    }
    t.row("restitution_used", d.restitution_used);
    if (d.velocity_from_acceleration_applied) t.row("velocity_from_acceleration", d.velocity_from_acceleration);
    // Baumgarte's term (or soft step's soft push): the separating speed added to push the bodies apart.
    if (d.position_bias) t.row("position_bias", *d.position_bias);
    t.row("desired_delta_velocity", d.desired_delta_velocity, std::nullopt,
          desired_formula(d, accumulating, warm_start));
    // The chapter's v_s' = −c v_s is the book's target; an accumulating solver's is its own.
    if (accumulating) t.equation("");
    return t.done();
}

std::vector<StepTable> updates_tables(const std::string& what, std::vector<Row> rows) {
    if (rows.empty()) return {};
    return {StepTable{std::string(formats::words::step::updates), "updates — " + what, std::move(rows)}};
}

// A row of the updates table: contact `contact`'s values before → after, each at the scale of the pair.
Row update_row(std::string_view key, int contact, std::string value, std::string exact_text, std::string meaning) {
    const Annotation& a = annotation(key);
    return {"contact " + std::to_string(contact),
            std::move(value),
            std::string(a.formula),
            std::string(a.equation),
            std::move(meaning),
            {},
            std::string(key),
            std::move(exact_text)};
}

std::string change_text(double before, double after, std::string_view unit) {
    const double scale = std::max(std::abs(before), std::abs(after));
    return number(before, scale) + " → " + number(after, scale) + " " + std::string(unit);
}

// When moving back along the paths removed everything, there is nothing left to project.
bool projected(const PositionResolution& r) {
    return !(r.rewind && r.amount <= 1e-12 * r.penetration);
}

std::string amount_formula(const PositionResolution& r) {
    if (r.method == PositionMethod::split_impulse) return "the push impulse this visit, λ_after − λ_before";
    if (r.rewind) return "penetration − rewind.removed_penetration";
    if (r.penetration > 0.0 && r.amount != r.penetration)
        return "relaxation.fraction × penetration (" + number(r.amount / r.penetration) + " here)";
    return "penetration";
}

}  // namespace

std::vector<StepTable> preparation_tables(const ContactPreparation& d) {
    std::vector<StepTable> tables;
    const Mat3* basis = &d.basis.contact_to_world;

    Table basis_step(std::string(formats::words::step::basis), "basis — contact coordinates from the normal");
    basis_step.row("swapped", yes_no(d.swapped, "yes: given with the world as body 0, exchanged and n reversed", "no"))
        .row("normal", d.basis.normal())
        .row("tangent_seed", std::string(d.basis.seed == TangentSeed::world_x ? "world X" : "world Y"))
        .row("tangent1", d.basis.tangent1())
        .row("tangent2", d.basis.tangent2())
        .row("basis", d.basis.contact_to_world);
    tables.push_back(basis_step.done());

    Table relative(std::string(formats::words::step::relative_position),
                   "relative_position — where the contact is on each body", basis);
    relative.world_vectors("relative_position", d.relative_position);
    tables.push_back(relative.done());

    const UnitImpulseChain& chain = d.unit_impulse_chain;
    Table unit(std::string(formats::words::step::delta_velocity_per_unit_impulse),
               "delta_velocity_per_unit_impulse — linear and angular parts", basis);
    unit.world_vectors("torque_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::torque_per_unit_impulse))
        .world_vectors("rotation_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::rotation_per_unit_impulse))
        .world_vectors("point_velocity_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::point_velocity_per_unit_impulse))
        .per_body("angular_component", unit_response_field(chain, &UnitImpulseResponse::angular_component))
        .per_body("linear_component", unit_response_field(chain, &UnitImpulseResponse::linear_component))
        .row("delta_velocity_per_unit_impulse", chain.delta_velocity_per_unit_impulse);
    tables.push_back(unit.done());

    Table velocity(std::string(formats::words::step::contact_velocity),
                   "contact_velocity — how the contact points move", basis);
    velocity.world_vectors("point_velocity", d.velocity_terms.point_velocity)
        .per_body("tangential_acceleration_velocity", d.velocity_terms.tangential_acceleration_velocity)
        .contact_vector("contact_velocity", d.velocity_terms.contact_velocity,
                        // With the refinement on, last frame's sideways acceleration is in it too.
                        d.velocity_terms.tangential_acceleration_velocity[0]
                            ? "Cᵀ (v₀ − v₁) + tangential_acceleration_velocity₀ − …₁"
                            : "");
    tables.push_back(velocity.done());

    tables.push_back(desired_table(d.desired_terms));
    return tables;
}

std::vector<StepTable> position_iteration_tables(const PositionIteration& it, const Mat3* basis) {
    std::vector<StepTable> tables;
    if (const auto& r = it.resolution) {
        const std::string method(formats::name_of(formats::position_method_names, r->method));
        const bool linear_only = r->method == PositionMethod::linear_projection;
        // The split impulse records its pushes in this vocabulary: an impulse, and the moves it made.
        const bool split = r->method == PositionMethod::split_impulse;
        if (r->rewind) {
            const Rewind& w = *r->rewind;
            Table rewind(std::string(formats::words::step::rewind),
                         "rewind — move the bodies back along their paths (velocity_based)", basis);
            rewind.row("rewind.closing_velocity", w.closing_velocity)
                .row("rewind.time", w.time, std::nullopt, {},
                     w.time == w.time_limit && w.time > 0 ? "the whole frame" : "")
                .row("rewind.removed_penetration", w.removed_penetration)
                .world_vectors("rewind.linear_change", w.linear_change)
                .world_vectors("rewind.angular_change", w.angular_change);
            tables.push_back(rewind.done());
        }
        if (projected(*r)) {
            Table inertia(std::string(formats::words::step::penetration_inertia),
                          "penetration_inertia — how readily each body gives way (" + method + ")");
            // The split impulse pushes with an impulse (N·s), not a distance: its own word.
            inertia.row("penetration", r->penetration)
                .row(split ? "push_impulse" : "amount", split ? r->push_impulse : r->amount, std::nullopt,
                     split ? "" : amount_formula(*r));
            inertia.per_body("linear_inertia", r->inertia.linear_inertia)
                .per_body("angular_inertia", r->inertia.angular_inertia,
                          linear_only ? "0: linear projection never turns" : "")
                .row("penetration_inertia", r->inertia.penetration_inertia, std::nullopt,
                     linear_only ? "Σ linear" : "");
            tables.push_back(inertia.done());

            Table moves(std::string(formats::words::step::move_split),
                        "move_split — how much of the move is linear, how much angular");
            bool limited = false;
            if (const auto& limit = r->angular_limit) {
                moves.per_body("angular_limit.linear_move_before", limit->before.linear_move)
                    .per_body("angular_limit.angular_move_before", limit->before.angular_move);
                const std::string policy(formats::name_of(formats::angular_limit_policy_names, limit->policy));
                const std::string maximum_formula =
                    limit->policy == AngularLimitPolicy::fixed       ? "angular_limit.factor"
                    : limit->policy == AngularLimitPolicy::lever_arm ? "factor × |q_rel − (q_rel · n) n|"
                    : limit->policy == AngularLimitPolicy::angle     ? "the move that turns the body by factor degrees"
                                                                     : "";
                if (limit->policy == AngularLimitPolicy::none)
                    moves.row("angular_limit.maximum", std::string("no limit (policy none)"));
                for (int i = 0; i < 2 && limit->policy != AngularLimitPolicy::none; ++i) {
                    if (!limit->applied[i]) continue;  // no body 1: the world
                    if (limit->maximum[i])
                        moves.row("angular_limit.maximum", *limit->maximum[i], i, maximum_formula,
                                  policy + " " + number(limit->factor));
                    else
                        moves.row("angular_limit.maximum", std::string("none"), i, maximum_formula);
                    moves.row("angular_limit.applied",
                              yes_no(*limit->applied[i], "yes: the excess moves linearly", "no"), i);
                    limited = limited || *limit->applied[i];
                }
            }
            const std::string_view linear_formula = split ? "linear_change · n"
                                                    : limited
                                                        ? "±amount · linear / total; limited: total move − angular"
                                                        : "";
            const std::string_view angular_formula = split     ? "(angular_change × q_rel) · n"
                                                     : limited ? "±amount · angular / total; limited: ±angular_limit"
                                                               : "";
            moves.per_body("move_split.linear_move", r->moves.linear_move, linear_formula)
                .per_body("move_split.angular_move", r->moves.angular_move, angular_formula);
            tables.push_back(moves.done());
        }

        Table change(std::string(formats::words::step::position_change), "position_change — the move applied", basis);
        // Velocity-based resolution applies the rewind and the projection together.
        change
            .world_vectors("position_change.linear_change", r->change.linear_change,
                           r->rewind ? "rewind.linear_change + n · linear_move"
                           : split   ? "Δṗ of the push × Δt = push_impulse m⁻¹ n Δt"
                                     : "")
            .world_vectors("position_change.angular_change", r->change.angular_change,
                           r->rewind     ? "rewind.angular_change + I⁻¹(q_rel × n) · angular_move / angular"
                           : linear_only ? "0: linear projection never turns"
                           : split       ? "Δθ̇ of the push × Δt = I⁻¹(q_rel × push_impulse n) Δt"
                                         : "");
        tables.push_back(change.done());
    }
    std::vector<Row> rows;
    for (const PenetrationUpdate& u : it.updates)
        rows.push_back(
            update_row("penetration_update", u.contact, "penetration " + change_text(u.before, u.after, "m"),
                       exact(u.before) + " → " + exact(u.after) + " m",
                       "body " + std::to_string(u.body) + " moved (its body " + std::to_string(u.slot) + ")"));
    for (StepTable& t : updates_tables("penetrations of contacts sharing a moved body", rows)) tables.push_back(t);
    return tables;
}

std::string sweep_text(const SweepPlace& sweep, const ResolverSettings& settings) {
    std::string text;
    // A method that owns the whole step works in sub-steps (restitution comes once, after them).
    if (method_row(settings.velocity_method).scope == MethodScope::whole_step &&
        settings.velocity_method != VelocityMethod::avbd && sweep.stage != SolverStage::restitution)
        text = "sub-step " + std::to_string(sweep.substep) + " · ";
    text += std::string(formats::name_of(formats::solver_stage_names, sweep.stage));
    if (sweep.stage == SolverStage::solve || sweep.stage == SolverStage::relax || sweep.stage == SolverStage::push ||
        sweep.stage == SolverStage::stabilize || sweep.stage == SolverStage::dual)
        text += " sweep " + std::to_string(sweep.pass);
    return text;
}

std::string sweep_meaning(SolverStage stage) {
    switch (stage) {
        case SolverStage::warm_start:
            return "last frame's total impulse for this contact, applied again before any sweep";
        case SolverStage::solve:
            return "one visit of a sweep: move this contact's total towards its target, within its limits";
        case SolverStage::relax:
            return "a sweep without the position bias: takes back the speed the push added";
        case SolverStage::restitution:
            return "the bounce, once after the sub-steps: target −c times the closing speed before solving";
        case SolverStage::push:
            return "a sweep on pseudo-velocities that only move positions";
        case SolverStage::stabilize:
            return "AVBD's last sweep, after the velocities were taken: moves the bodies out of what penetration is "
                   "left "
                   "(α = 0) without giving them speed";
        case SolverStage::dual:
            return "AVBD's dual update after the sweep: each contact's λ becomes its force, k grows while violated";
    }
    return "";
}

std::vector<StepTable> velocity_iteration_tables(const VelocityIteration& it, const Mat3* basis) {
    if (is_avbd_visit(it)) return avbd_iteration_tables(it);
    std::vector<StepTable> tables;
    if (const auto& r = it.resolution) {
        Table velocity(std::string(formats::words::step::contact_velocity),
                       "contact_velocity — as the resolver has it now", basis);
        // The book's resolver keeps it as bookkeeping (the prepared value, updated by each iteration that
        // changed a body); the accumulating solvers read it from the bodies at every visit.
        velocity.contact_vector("contact_velocity", r->contact_velocity,
                                it.accumulated ? "Cᵀ (v₀ − v₁), read from the bodies at this visit"
                                               : "as prepared, + the updates of the iterations before");
        tables.push_back(velocity.done());
        const bool accumulating = it.accumulated.has_value();
        const bool warm_start = it.sweep && it.sweep->stage == SolverStage::warm_start;
        tables.push_back(desired_table(r->desired_terms, accumulating, warm_start));
        if (const auto& a = it.accumulated) {
            Table total(std::string(formats::words::step::accumulated),
                        "accumulated — the running total, kept within its limits", basis);
            total.contact_vector("accumulated.before", a->before)
                .contact_vector("accumulated.unclamped", a->unclamped,
                                warm_start ? "λ, last frame's total re-applied"
                                           : "λ + this visit's raw impulse (normal: Δv over the normal response; "
                                             "sliding: −K_tt⁻¹ v_t)")
                .row("accumulated.clamp", std::string(formats::name_of(formats::impulse_clamp_names, a->clamp)))
                .contact_vector("accumulated.after", a->after, "clamp(accumulated.unclamped)");
            tables.push_back(total.done());
        }

        const Impulse& g = r->impulse_terms;
        Table impulse(std::string(formats::words::step::impulse), "impulse — in contact and world coordinates", basis);
        impulse.row(
            "impulse_model", std::string(formats::name_of(formats::impulse_model_names, g.impulse_model)), std::nullopt,
            accumulating ? "μ = 0: frictionless; sliding when the clamp held friction to its cone; else static" : "");
        if (const auto& s = g.friction_solve) {
            impulse.row("friction_solve.delta_velocity_matrix", s->delta_velocity_matrix)
                .contact_vector("friction_solve.target_delta_velocity", s->target_delta_velocity)
                .contact_vector("friction_solve.static_impulse", s->static_impulse)
                .row("friction_solve.tangential_impulse", s->tangential_impulse)
                .row("friction_solve.cone_limit", s->cone_limit);
            if (s->sliding_direction)
                impulse.row("friction_solve.sliding_direction", "(" + number(s->sliding_direction->x(), 1.0) + ", " +
                                                                    number(s->sliding_direction->y(), 1.0) + ")");
            if (s->sliding_normal_response)
                impulse.row("friction_solve.sliding_normal_response", *s->sliding_normal_response);
        }
        impulse.contact_vector("impulse", g.impulse,
                               accumulating ? "accumulated.after − accumulated.before"
                               : g.impulse_model == ImpulseModel::frictionless ? std::string_view{}
                               : g.impulse_model == ImpulseModel::static_friction
                                   ? "friction_solve.static_impulse (inside the cone)"
                                   : "(g_n, μ g_n ŷ, μ g_n ẑ), g_n = Δv / sliding_normal_response");
        // (14.3) is the frictionless g = Δv / d; the friction solve is chapter 15's, a sweep's increment its own.
        if (accumulating || g.impulse_model != ImpulseModel::frictionless)
            impulse.equation(accumulating ? "" : "ch. 15");
        impulse.world_vector("impulse_world", g.impulse_world);
        tables.push_back(impulse.done());

        Table change(std::string(formats::words::step::velocity_change), "velocity_change — the impulse applied",
                     basis);
        change.world_vectors("impulsive_torque", r->velocity_change_terms.impulsive_torque)
            .world_vectors("velocity_change", r->velocity_change_terms.velocity_change)
            .world_vectors("rotation_change", r->velocity_change_terms.rotation_change);
        tables.push_back(change.done());
    }
    std::vector<Row> rows;
    for (const VelocityUpdate& u : it.updates) {
        const double scale =
            std::max({std::abs(u.before.x()), std::abs(u.after.x()), std::abs(u.desired_delta_velocity_before),
                      std::abs(u.desired_delta_velocity_after)});
        rows.push_back(update_row(
            "velocity_update", u.contact,
            "v_s " + number(u.before.x(), scale) + " → " + number(u.after.x(), scale) + " m/s, Δv " +
                number(u.desired_delta_velocity_before, scale) + " → " + number(u.desired_delta_velocity_after, scale) +
                " m/s",
            "v_s " + exact(u.before.x()) + " → " + exact(u.after.x()) + " m/s, Δv " +
                exact(u.desired_delta_velocity_before) + " → " + exact(u.desired_delta_velocity_after) + " m/s",
            "body " + std::to_string(u.body) + " changed speed (its body " + std::to_string(u.slot) + ")"));
    }
    for (StepTable& t : updates_tables("contacts sharing a body that changed speed", rows)) tables.push_back(t);
    return tables;
}

std::vector<std::string_view> preparation_steps(const ContactPreparation&) {
    return {formats::words::step::basis, formats::words::step::relative_position,
            formats::words::step::delta_velocity_per_unit_impulse, formats::words::step::contact_velocity,
            formats::words::step::desired_delta_velocity};
}

std::vector<std::string_view> position_iteration_steps(const PositionIteration& it) {
    std::vector<std::string_view> steps;
    if (const auto& r = it.resolution) {
        if (r->rewind) steps.push_back(formats::words::step::rewind);
        if (projected(*r))
            steps.insert(steps.end(), {formats::words::step::penetration_inertia, formats::words::step::move_split});
        steps.push_back(formats::words::step::position_change);
    }
    if (!it.updates.empty()) steps.push_back(formats::words::step::updates);
    return steps;
}

std::vector<std::string_view> velocity_iteration_steps(const VelocityIteration& it) {
    if (is_avbd_visit(it)) return avbd_iteration_steps(it);
    std::vector<std::string_view> steps;
    if (it.resolution) {
        steps.insert(steps.end(),
                     {formats::words::step::contact_velocity, formats::words::step::desired_delta_velocity});
        if (it.accumulated) steps.push_back(formats::words::step::accumulated);
        steps.insert(steps.end(), {formats::words::step::impulse, formats::words::step::velocity_change});
    }
    if (!it.updates.empty()) steps.push_back(formats::words::step::updates);
    return steps;
}

}  // namespace impulse::explain
