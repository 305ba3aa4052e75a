#include "explain/derivation_table.hpp"

#include "explain/annotations.hpp"
#include "explain/format.hpp"
#include "resolver/settings_names.hpp"

namespace impulse::explain {

namespace {

// Collects the rows of one step, filling formula, equation, unit and meaning from the annotations.
class Table {
public:
    // `contact_to_world` is the contact's basis when known: vectors are then also shown in the other frame.
    Table(std::string step, std::string title, const Mat3* contact_to_world = nullptr)
        : table_{std::move(step), std::move(title), {}}, basis_(contact_to_world) {}

    // `note` follows the unit: "0.25 m/s (not applied)".
    Table& row(std::string_view key, const std::string& value, std::optional<int> body = std::nullopt,
               std::string_view formula = {}, std::string_view note = {}) {
        const Annotation& a = annotation(key);
        std::string quantity(key);
        if (body) quantity += "[" + std::to_string(*body) + "]";
        std::string shown = with_unit(value, a.unit);
        if (!note.empty()) shown += " (" + std::string(note) + ")";
        table_.rows.push_back({quantity, shown, std::string(formula.empty() ? a.formula : formula),
                               std::string(a.equation), std::string(a.meaning)});
        return *this;
    }

    // One row per body present (body 1 is absent when it is the world).
    template <typename T, typename Format>
    Table& per_body(std::string_view key, const PerBody<T>& values, Format format) {
        for (int i = 0; i < 2; ++i)
            if (values[i]) row(key, format(*values[i]), i);
        return *this;
    }

    // A world vector, shown in contact coordinates too (C^T v): e.g. q_rel along the normal and tangents.
    Table& world_vector(std::string_view key, const Vec3& v, std::optional<int> body = std::nullopt) {
        row(key, vector(v), body);
        if (basis_) table_.rows.back().other_frame = "contact " + vector(basis_->transpose() * v);
        return *this;
    }
    Table& world_vectors(std::string_view key, const PerBody<Vec3>& values) {
        for (int i = 0; i < 2; ++i)
            if (values[i]) world_vector(key, *values[i], i);
        return *this;
    }
    // A vector in contact coordinates, shown in world coordinates too (C v).
    Table& contact_vector(std::string_view key, const Vec3& v, std::string_view formula = {}) {
        row(key, vector(v), std::nullopt, formula);
        if (basis_) table_.rows.back().other_frame = "world " + vector(*basis_ * v);
        return *this;
    }

    // Replaces the equation of the row just added (the same quantity can come from another equation).
    Table& equation(std::string_view text) {
        table_.rows.back().equation = std::string(text);
        return *this;
    }

    StepTable done() { return std::move(table_); }

private:
    StepTable table_;
    const Mat3* basis_;
};

template <typename Member>
auto unit_response_field(const VelocityPerUnitImpulse& chain, Member member) {
    PerBody<std::decay_t<decltype(std::declval<UnitImpulseResponse>().*member)>> values;
    for (int i = 0; i < 2; ++i)
        if (chain.bodies[i]) values[i] = (*chain.bodies[i]).*member;
    return values;
}

StepTable desired_table(const DesiredDeltaVelocity& d) {
    Table t("desired_delta_velocity", "Step 5 · desired_delta_velocity — the velocity change the impulse must make");
    t.row("separating_velocity", number(d.separating_velocity));
    t.row("restitution", number(d.restitution));
    if (d.restitution_cutoff > 0.0)
        t.row("restitution_cutoff", number(d.restitution_cutoff), std::nullopt, {},
              d.restitution_cutoff_applied ? "applied: c = 0" : "not applied");
    t.row("restitution_used", number(d.restitution_used));
    if (d.velocity_from_acceleration_applied) t.row("velocity_from_acceleration", number(d.velocity_from_acceleration));
    // Baumgarte's term (or soft step's soft push): the separating speed added to push the bodies apart.
    if (d.position_bias) t.row("position_bias", number(*d.position_bias));
    // Without the chapter-15 refinements and the bias the formula is the chapter's own.
    const bool plain = !d.velocity_from_acceleration_applied && !d.restitution_cutoff_applied && !d.position_bias;
    t.row("desired_delta_velocity", number(d.desired_delta_velocity), std::nullopt,
          plain ? "Δv = −(1 + c) v_s" : std::string_view{});
    return t.done();
}

std::vector<StepTable> updates_tables(const std::string& what, std::vector<Row> rows) {
    if (rows.empty()) return {};
    return {StepTable{"updates", "Updates — " + what, std::move(rows)}};
}

}  // namespace

std::vector<StepTable> preparation_tables(const ContactPreparation& d) {
    std::vector<StepTable> tables;
    const Mat3* basis = &d.basis.contact_to_world;

    Table basis_step("basis", "Step 1 · basis — contact coordinates from the normal");
    basis_step.row("normal", vector(d.basis.normal))
        .row("tangent_seed", d.basis.seed == TangentSeed::world_x ? "world X" : "world Y")
        .row("tangent1", vector(d.basis.tangent1))
        .row("tangent2", vector(d.basis.tangent2))
        .row("basis", matrix_rows(d.basis.contact_to_world));
    tables.push_back(basis_step.done());

    Table relative("relative_position", "Step 2 · relative_position — where the contact is on each body", basis);
    relative.world_vectors("relative_position", d.relative_position);
    tables.push_back(relative.done());

    const VelocityPerUnitImpulse& chain = d.velocity_per_unit_impulse;
    Table unit("velocity_per_unit_impulse", "Step 3 · velocity per unit impulse — linear and angular parts", basis);
    unit.world_vectors("torque_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::torque_per_unit_impulse))
        .world_vectors("rotation_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::rotation_per_unit_impulse))
        .world_vectors("velocity_per_unit_impulse",
                       unit_response_field(chain, &UnitImpulseResponse::velocity_per_unit_impulse))
        .per_body("angular_component", unit_response_field(chain, &UnitImpulseResponse::angular_component), number)
        .per_body("linear_component", unit_response_field(chain, &UnitImpulseResponse::linear_component), number)
        .row("delta_velocity_per_unit_impulse", number(chain.delta_velocity_per_unit_impulse));
    tables.push_back(unit.done());

    Table velocity("contact_velocity", "Step 4 · contact_velocity — how the contact points move", basis);
    velocity.world_vectors("point_velocity", d.contact_velocity.point_velocity)
        .per_body("tangential_acceleration_velocity", d.contact_velocity.tangential_acceleration_velocity, vector)
        .contact_vector("contact_velocity", d.contact_velocity.contact_velocity);
    tables.push_back(velocity.done());

    tables.push_back(desired_table(d.desired_delta_velocity));
    return tables;
}

std::vector<StepTable> position_iteration_tables(const PositionIteration& it, const Mat3* basis) {
    std::vector<StepTable> tables;
    if (const auto& r = it.resolution) {
        const std::string method(name_of(position_method_names, r->method));
        if (r->rewind) {
            const Rewind& w = *r->rewind;
            Table rewind("rewind", "Velocity-based · move the bodies back along their paths", basis);
            rewind.row("closing_velocity", number(w.closing_velocity))
                .row("rewind_time", number(w.time), std::nullopt, {},
                     w.time == w.time_limit && w.time > 0 ? "the whole frame" : "")
                .row("removed_penetration", number(w.removed_penetration))
                .world_vectors("rewind_linear_change", w.linear_change)
                .world_vectors("rewind_angular_change", w.angular_change);
            tables.push_back(rewind.done());
        }
        // When moving back along the paths removed everything, there is nothing left to project.
        const bool projected = !(r->rewind && r->amount <= 1e-12 * r->penetration);
        if (projected) {
            Table inertia("penetration_inertia", "Step 8 · inertia along the normal (" + method + ")");
            inertia.row("penetration", number(r->penetration))
                .row("amount", number(r->amount))
                .per_body("linear_inertia", r->inertia.linear_inertia, number)
                .per_body("angular_inertia", r->inertia.angular_inertia, number)
                .row("total_inertia", number(r->inertia.total_inertia));
            tables.push_back(inertia.done());

            Table moves("move_split", "Step 8 · linear_move and angular_move — the split of the move");
            if (const auto& limit = r->angular_limit) {
                moves.per_body("linear_move_before", limit->before.linear_move, number)
                    .per_body("angular_move_before", limit->before.angular_move, number);
                const std::string policy(name_of(angular_limit_policy_names, limit->policy));
                if (limit->policy == AngularLimitPolicy::none) moves.row("angular_limit", "no limit (policy none)");
                for (int i = 0; i < 2 && limit->policy != AngularLimitPolicy::none; ++i) {
                    if (!limit->applied[i]) continue;  // no body 1: the world
                    const std::string maximum = limit->maximum[i] ? number(*limit->maximum[i]) : "none";
                    moves.row(
                        "angular_limit", maximum, i, {},
                        policy + " " + number(limit->factor) + (*limit->applied[i] ? ", applied" : ", not reached"));
                }
            }
            moves.per_body("linear_move", r->moves.linear_move, number)
                .per_body("angular_move", r->moves.angular_move, number);
            tables.push_back(moves.done());
        }

        Table change("position_change", "Step 8 · linear_change and angular_change — the move applied", basis);
        change.world_vectors("linear_change", r->change.linear_change)
            .world_vectors("angular_change", r->change.angular_change);
        tables.push_back(change.done());
    }
    std::vector<Row> rows;
    for (const PenetrationUpdate& u : it.updates)
        rows.push_back({"contact " + std::to_string(u.contact),
                        "penetration " + number(u.before) + " → " + number(u.after) + " m",
                        "(linear_change + angular_change × q_rel) · n", "",
                        "body " + std::to_string(u.body) + " moved (its body " + std::to_string(u.slot) + ")"});
    for (StepTable& t : updates_tables("penetrations of contacts sharing a moved body", rows)) tables.push_back(t);
    return tables;
}

std::string sweep_text(const SweepPlace& sweep, const ResolverSettings& settings) {
    std::string text;
    // A method that owns the whole step works in sub-steps (restitution comes once, after them).
    if (method_row(settings.velocity_method).scope == MethodScope::whole_step &&
        sweep.stage != SolverStage::restitution)
        text = "sub-step " + std::to_string(sweep.substep) + " · ";
    text += std::string(name_of(solver_stage_names, sweep.stage));
    if (sweep.stage == SolverStage::solve || sweep.stage == SolverStage::relax || sweep.stage == SolverStage::push)
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
    }
    return "";
}

std::vector<StepTable> velocity_iteration_tables(const VelocityIteration& it, const Mat3* basis) {
    std::vector<StepTable> tables;
    if (const auto& r = it.resolution) {
        Table velocity("contact_velocity", "Step 4 · contact_velocity — as the resolver has it now", basis);
        velocity.contact_vector("contact_velocity", r->contact_velocity);
        tables.push_back(velocity.done());
        tables.push_back(desired_table(r->desired_delta_velocity));
        if (const auto& a = it.accumulated) {
            Table total("accumulated_impulse",
                        "Step 6 · accumulated impulse — the running total, kept within its limits", basis);
            total.contact_vector("accumulated_before", a->before)
                .contact_vector("accumulated_unclamped", a->unclamped)
                .row("clamp", std::string(name_of(impulse_clamp_names, a->clamp)))
                .contact_vector("accumulated_after", a->after);
            tables.push_back(total.done());
        }

        const Impulse& g = r->impulse;
        Table impulse("impulse", "Step 6 · impulse_contact and impulse_world — the impulse", basis);
        impulse.row("impulse_model", std::string(name_of(impulse_model_names, g.model)));
        if (const auto& s = g.friction) {
            impulse.row("delta_velocity_matrix", matrix_rows(s->delta_velocity_matrix))
                .contact_vector("target_delta_velocity", s->target_delta_velocity)
                .contact_vector("static_impulse", s->static_impulse)
                .row("tangential_impulse", number(s->tangential_impulse))
                .row("cone_limit", number(s->cone_limit));
            if (s->sliding_direction)
                impulse.row("sliding_direction",
                            "(" + number(s->sliding_direction->x()) + ", " + number(s->sliding_direction->y()) + ")");
            if (s->sliding_normal_response) impulse.row("sliding_normal_response", number(*s->sliding_normal_response));
        }
        impulse
            .contact_vector("impulse_contact", g.impulse_contact,
                            it.accumulated                          ? "accumulated_after − accumulated_before"
                            : g.model == ImpulseModel::frictionless ? std::string_view{}
                            : g.model == ImpulseModel::static_friction
                                ? "static_impulse (inside the cone)"
                                : "(g_n, μ g_n ŷ, μ g_n ẑ), g_n = Δv / sliding response")
            .world_vector("impulse_world", g.impulse_world);
        tables.push_back(impulse.done());

        Table change("velocity_change", "Step 7 · velocity_change and rotation_change — the impulse applied", basis);
        change.world_vectors("impulsive_torque", r->velocity_change.impulsive_torque)
            .world_vectors("velocity_change", r->velocity_change.velocity_change)
            .world_vectors("rotation_change", r->velocity_change.rotation_change);
        tables.push_back(change.done());
    }
    std::vector<Row> rows;
    for (const VelocityUpdate& u : it.updates)
        rows.push_back({"contact " + std::to_string(u.contact),
                        "v_s " + number(u.before.x()) + " → " + number(u.after.x()) + " m/s, Δv " +
                            number(u.desired_delta_velocity_before) + " → " + number(u.desired_delta_velocity_after) +
                            " m/s",
                        "contact_velocity ± Cᵀ(Δṗ + Δθ̇ × q_rel), then step 5", "",
                        "body " + std::to_string(u.body) + " changed speed (its body " + std::to_string(u.slot) + ")"});
    for (StepTable& t : updates_tables("contacts sharing a body that changed speed", rows)) tables.push_back(t);
    return tables;
}

}  // namespace impulse::explain
