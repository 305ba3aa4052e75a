#include "formats/trace_items_json.hpp"

#include "formats/trace_avbd_json.hpp"

#include "formats/settings_names.hpp"
#include "formats/word_table.hpp"

namespace impulse::formats {

namespace {

// --- keys -----------------------------------------------------------------------------------------------
// Every key of a contact or iteration record is looked up in the word list (formats/word_table.hpp) when this file
// compiles: a key the list does not hold for that item does not build.

consteval std::string_view contact_key(std::string_view word) {  // a prepared contact's
    return words::key(word, "C");
}
consteval std::string_view position_key(std::string_view word) {  // a position iteration's
    return words::key(word, "P");
}
consteval std::string_view velocity_key(std::string_view word) {  // a velocity iteration's
    return words::key(word, "V");
}
consteval std::string_view step5_key(std::string_view word) {  // step 5's, held by contacts and velocity iterations
    return words::key(word, "CV");
}

// --- small helpers -------------------------------------------------------------------------------------

json per_body_vec3(const PerBody<Vec3>& v) {
    return per_body_json(v, vec3_json);
}
json per_body_number(const PerBody<double>& v) {
    return per_body_json(v, number_json);
}
json per_body_bool(const PerBody<bool>& v) {
    return per_body_json(v, [](bool b) { return json(b); });
}
PerBody<Vec3> read_per_body_vec3(const json& j) {
    return read_per_body<Vec3>(j, read_vec3);
}
PerBody<double> read_per_body_number(const json& j) {
    return read_per_body<double>(j, read_number);
}
PerBody<bool> read_per_body_bool(const json& j) {
    return read_per_body<bool>(j, [](const json& b) { return b.get<bool>(); });
}

template <typename Enum, std::size_t N>
Enum read_enum(const NameTable<Enum, N>& table, const json& value) {
    return *value_of(table, value.get<std::string>());  // the schema limited it to the table's words
}

json body_index(int body) {
    return body == world_body ? json(nullptr) : json(body);
}
int read_body_index(const json& j) {
    return j.is_null() ? world_body : j.get<int>();
}

// --- step 5, shared by prepared contacts and velocity iterations ----------------------------------------

void write_desired(json& out, const DesiredDeltaVelocity& d) {
    out[step5_key("separating_velocity")] = d.separating_velocity;
    out[step5_key("restitution")] = d.restitution;
    out[step5_key("restitution_cutoff")] = d.restitution_cutoff;
    out[step5_key("restitution_cutoff_applied")] = d.restitution_cutoff_applied;
    out[step5_key("restitution_used")] = d.restitution_used;
    out[step5_key("velocity_from_acceleration_applied")] = d.velocity_from_acceleration_applied;
    out[step5_key("velocity_from_acceleration")] = d.velocity_from_acceleration;
    if (d.position_bias) out[step5_key("position_bias")] = *d.position_bias;  // absent when Baumgarte is off
    out[step5_key("desired_delta_velocity")] = d.desired_delta_velocity;
}

DesiredDeltaVelocity read_desired(const json& j) {
    return {j[step5_key("separating_velocity")].get<double>(),
            j[step5_key("restitution")].get<double>(),
            j[step5_key("restitution_cutoff")].get<double>(),
            j[step5_key("restitution_cutoff_applied")].get<bool>(),
            j[step5_key("restitution_used")].get<double>(),
            j[step5_key("velocity_from_acceleration_applied")].get<bool>(),
            j[step5_key("velocity_from_acceleration")].get<double>(),
            j.contains(step5_key("position_bias")) ? std::optional(j[step5_key("position_bias")].get<double>())
                                                   : std::nullopt,
            j[step5_key("desired_delta_velocity")].get<double>()};
}

// --- why a contact exists ------------------------------------------------------------------------------

json origin_json(const ContactOrigin& o) {
    json features = json::array();
    for (const Feature& f : o.features)
        features.push_back({{contact_key("origin.features[].kind"), name_of(feature_kind_names, f.kind)},
                            {contact_key("origin.features[].index"), f.index}});
    return {{contact_key("origin.test"), name_of(collision_test_names, o.test)},
            {contact_key("origin.features"), features}};
}

ContactOrigin read_origin(const json& j) {
    ContactOrigin o;
    o.test = read_enum(collision_test_names, j[contact_key("origin.test")]);
    for (std::size_t i = 0; i < 2; ++i)
        o.features[i] = {
            read_enum(feature_kind_names, j[contact_key("origin.features")][i][contact_key("origin.features[].kind")]),
            j[contact_key("origin.features")][i][contact_key("origin.features[].index")].get<int>()};
    return o;
}

}  // namespace

// --- steps 1-5 of a contact -----------------------------------------------------------------------------

json item_json(const ContactPreparation& d) {
    json out = {
        {contact_key("contact"), d.contact},
        {contact_key("bodies"), json::array({body_index(d.bodies[0]), body_index(d.bodies[1])})},
        {contact_key("swapped"), d.swapped},
        {contact_key("inert"), d.inert},
        {contact_key("point"), vec3_json(d.point)},
    };
    if (d.body1_point) out[contact_key("body1_point")] = vec3_json(*d.body1_point);  // a recycled contact's
    out[contact_key("normal")] = vec3_json(d.normal);
    out[contact_key("penetration")] = d.penetration;
    out[contact_key("restitution")] = d.restitution;
    out[contact_key("friction")] = d.friction;
    out[contact_key("origin")] = origin_json(d.origin);
    out[contact_key("basis")] = mat3_json(d.basis.contact_to_world);
    out[contact_key("tangent_seed")] = name_of(tangent_seed_names, d.basis.seed);
    out[contact_key("relative_position")] = per_body_vec3(d.relative_position);
    const auto& bodies = d.unit_impulse_chain.bodies;
    const auto field = [&bodies](auto member) {
        PerBody<std::decay_t<decltype((*bodies[0]).*member)>> values;
        for (int i = 0; i < 2; ++i)
            if (bodies[i]) values[i] = (*bodies[i]).*member;
        return values;
    };
    out[contact_key("torque_per_unit_impulse")] = per_body_vec3(field(&UnitImpulseResponse::torque_per_unit_impulse));
    out[contact_key("rotation_per_unit_impulse")] =
        per_body_vec3(field(&UnitImpulseResponse::rotation_per_unit_impulse));
    out[contact_key("point_velocity_per_unit_impulse")] =
        per_body_vec3(field(&UnitImpulseResponse::point_velocity_per_unit_impulse));
    out[contact_key("angular_component")] = per_body_number(field(&UnitImpulseResponse::angular_component));
    out[contact_key("linear_component")] = per_body_number(field(&UnitImpulseResponse::linear_component));
    out[contact_key("delta_velocity_per_unit_impulse")] = d.unit_impulse_chain.delta_velocity_per_unit_impulse;
    out[contact_key("point_velocity")] = per_body_vec3(d.velocity_terms.point_velocity);
    out[contact_key("tangential_acceleration_velocity")] =
        per_body_vec3(d.velocity_terms.tangential_acceleration_velocity);
    out[contact_key("contact_velocity")] = vec3_json(d.velocity_terms.contact_velocity);
    write_desired(out, d.desired_terms);
    return out;
}

ContactPreparation read_preparation(const json& j) {
    ContactPreparation d;
    d.contact = j[contact_key("contact")].get<int>();
    d.bodies = {read_body_index(j[contact_key("bodies")][0]), read_body_index(j[contact_key("bodies")][1])};
    d.swapped = j[contact_key("swapped")].get<bool>();
    d.inert = j[contact_key("inert")].get<bool>();
    d.point = read_vec3(j[contact_key("point")]);
    if (j.contains(contact_key("body1_point"))) d.body1_point = read_vec3(j[contact_key("body1_point")]);
    d.normal = read_vec3(j[contact_key("normal")]);
    d.penetration = j[contact_key("penetration")].get<double>();
    d.restitution = j[contact_key("restitution")].get<double>();
    d.friction = j[contact_key("friction")].get<double>();
    d.origin = read_origin(j[contact_key("origin")]);
    d.basis.contact_to_world = read_mat3(j[contact_key("basis")]);
    d.basis.seed = read_enum(tangent_seed_names, j[contact_key("tangent_seed")]);
    d.relative_position = read_per_body_vec3(j[contact_key("relative_position")]);
    const PerBody<Vec3> torque = read_per_body_vec3(j[contact_key("torque_per_unit_impulse")]);
    const PerBody<Vec3> rotation = read_per_body_vec3(j[contact_key("rotation_per_unit_impulse")]);
    const PerBody<Vec3> velocity = read_per_body_vec3(j[contact_key("point_velocity_per_unit_impulse")]);
    const PerBody<double> angular = read_per_body_number(j[contact_key("angular_component")]);
    const PerBody<double> linear = read_per_body_number(j[contact_key("linear_component")]);
    for (int i = 0; i < 2; ++i)
        if (torque[i])
            d.unit_impulse_chain.bodies[i] = {*torque[i], *rotation[i], *velocity[i], *angular[i], *linear[i]};
    d.unit_impulse_chain.delta_velocity_per_unit_impulse =
        j[contact_key("delta_velocity_per_unit_impulse")].get<double>();
    d.velocity_terms.point_velocity = read_per_body_vec3(j[contact_key("point_velocity")]);
    d.velocity_terms.tangential_acceleration_velocity =
        read_per_body_vec3(j[contact_key("tangential_acceleration_velocity")]);
    d.velocity_terms.contact_velocity = read_vec3(j[contact_key("contact_velocity")]);
    d.desired_terms = read_desired(j);
    return d;
}

// --- position iterations --------------------------------------------------------------------------------

namespace {

json rewind_json(const Rewind& r) {
    return {{position_key("rewind.closing_velocity"), r.closing_velocity},
            {position_key("rewind.time"), r.time},
            {position_key("rewind.time_limit"), r.time_limit},
            {position_key("rewind.removed_penetration"), r.removed_penetration},
            {position_key("rewind.linear_change"), per_body_vec3(r.linear_change)},
            {position_key("rewind.angular_change"), per_body_vec3(r.angular_change)}};
}

Rewind read_rewind(const json& j) {
    return {j[position_key("rewind.closing_velocity")].get<double>(),
            j[position_key("rewind.time")].get<double>(),
            j[position_key("rewind.time_limit")].get<double>(),
            j[position_key("rewind.removed_penetration")].get<double>(),
            read_per_body_vec3(j[position_key("rewind.linear_change")]),
            read_per_body_vec3(j[position_key("rewind.angular_change")])};
}

json angular_limit_json(const AngularLimit& a) {
    return {{position_key("angular_limit.policy"), name_of(angular_limit_policy_names, a.policy)},
            {position_key("angular_limit.factor"), a.factor},
            {position_key("angular_limit.maximum"), per_body_number(a.maximum)},
            {position_key("angular_limit.applied"), per_body_bool(a.applied)},
            {position_key("angular_limit.linear_move_before"), per_body_number(a.before.linear_move)},
            {position_key("angular_limit.angular_move_before"), per_body_number(a.before.angular_move)}};
}

AngularLimit read_angular_limit(const json& j) {
    return {read_enum(angular_limit_policy_names, j[position_key("angular_limit.policy")]),
            j[position_key("angular_limit.factor")].get<double>(),
            read_per_body_number(j[position_key("angular_limit.maximum")]),
            read_per_body_bool(j[position_key("angular_limit.applied")]),
            MoveSplit{read_per_body_number(j[position_key("angular_limit.linear_move_before")]),
                      read_per_body_number(j[position_key("angular_limit.angular_move_before")])}};
}

}  // namespace

json item_json(const PositionIteration& it) {
    json out = {{position_key("iteration"), it.iteration},
                {position_key("contact"), it.contact},
                {position_key("penetration"), it.penetration}};
    // The split impulse compares nothing with an epsilon: it records its slop instead, under its own word.
    if (it.slop)
        out[position_key("slop")] = *it.slop;
    else
        out[position_key("epsilon")] = it.epsilon;
    if (it.pass) out[position_key("pass")] = *it.pass;
    if (const auto& r = it.resolution) {
        out[position_key("method")] = name_of(position_method_names, r->method);
        // The split impulse pushes with an impulse (N·s), the projections by a distance (m): two words.
        if (r->method == PositionMethod::split_impulse)
            out[position_key("push_impulse")] = r->push_impulse;
        else
            out[position_key("amount")] = r->amount;
        if (r->rewind) out[position_key("rewind")] = rewind_json(*r->rewind);
        out[position_key("linear_inertia")] = per_body_number(r->inertia.linear_inertia);
        out[position_key("angular_inertia")] = per_body_number(r->inertia.angular_inertia);
        out[position_key("penetration_inertia")] = r->inertia.penetration_inertia;
        out[position_key("move_split")] = {
            {position_key("move_split.linear_move"), per_body_number(r->moves.linear_move)},
            {position_key("move_split.angular_move"), per_body_number(r->moves.angular_move)}};
        if (r->angular_limit) out[position_key("angular_limit")] = angular_limit_json(*r->angular_limit);
        out[position_key("position_change")] = {
            {position_key("position_change.linear_change"), per_body_vec3(r->change.linear_change)},
            {position_key("position_change.angular_change"), per_body_vec3(r->change.angular_change)}};
    }
    json updates = json::array();
    for (const PenetrationUpdate& u : it.updates)
        updates.push_back({{position_key("updates[].contact"), u.contact},
                           {position_key("updates[].body"), u.body},
                           {position_key("updates[].slot"), u.slot},
                           {position_key("updates[].delta"), u.delta},
                           {position_key("updates[].before"), u.before},
                           {position_key("updates[].after"), u.after}});
    out[position_key("updates")] = updates;
    return out;
}

PositionIteration read_position_iteration(const json& j) {
    PositionIteration it;
    it.iteration = j[position_key("iteration")].get<int>();
    it.contact = j[position_key("contact")].get<int>();
    it.penetration = j[position_key("penetration")].get<double>();
    const bool pushed = j.contains(position_key("slop"));  // the split impulse's (the schema allows one of the two)
    it.epsilon = pushed ? 0.0 : j[position_key("epsilon")].get<double>();
    if (pushed) it.slop = j[position_key("slop")].get<double>();
    if (j.contains(position_key("pass"))) it.pass = j[position_key("pass")].get<int>();
    if (j.contains(position_key("method"))) {
        PositionResolution r;
        r.method = read_enum(position_method_names, j[position_key("method")]);
        r.penetration = it.penetration;
        if (r.method == PositionMethod::split_impulse)
            r.push_impulse = j[position_key("push_impulse")].get<double>();
        else
            r.amount = j[position_key("amount")].get<double>();
        if (j.contains(position_key("rewind"))) r.rewind = read_rewind(j[position_key("rewind")]);
        r.inertia = {read_per_body_number(j[position_key("linear_inertia")]),
                     read_per_body_number(j[position_key("angular_inertia")]),
                     j[position_key("penetration_inertia")].get<double>()};
        const json& moves = j[position_key("move_split")];
        r.moves = {read_per_body_number(moves[position_key("move_split.linear_move")]),
                   read_per_body_number(moves[position_key("move_split.angular_move")])};
        if (j.contains(position_key("angular_limit")))
            r.angular_limit = read_angular_limit(j[position_key("angular_limit")]);
        const json& change = j[position_key("position_change")];
        r.change = {read_per_body_vec3(change[position_key("position_change.linear_change")]),
                    read_per_body_vec3(change[position_key("position_change.angular_change")])};
        it.resolution = r;
    }
    for (const json& u : j[position_key("updates")])
        it.updates.push_back(
            {u[position_key("updates[].contact")].get<int>(), u[position_key("updates[].body")].get<int>(),
             u[position_key("updates[].slot")].get<int>(), u[position_key("updates[].delta")].get<double>(),
             u[position_key("updates[].before")].get<double>(), u[position_key("updates[].after")].get<double>()});
    return it;
}

// --- velocity iterations --------------------------------------------------------------------------------

namespace {

json friction_solve_json(const FrictionSolve& s) {
    json out = {{velocity_key("friction_solve.delta_velocity_matrix"), mat3_json(s.delta_velocity_matrix)},
                {velocity_key("friction_solve.target_delta_velocity"), vec3_json(s.target_delta_velocity)},
                {velocity_key("friction_solve.solvable"), s.solvable},
                {velocity_key("friction_solve.static_impulse"), vec3_json(s.static_impulse)},
                {velocity_key("friction_solve.tangential_impulse"), s.tangential_impulse},
                {velocity_key("friction_solve.cone_limit"), s.cone_limit}};
    if (s.sliding_direction)
        out[velocity_key("friction_solve.sliding_direction")] =
            json::array({s.sliding_direction->x(), s.sliding_direction->y()});
    if (s.sliding_normal_response)
        out[velocity_key("friction_solve.sliding_normal_response")] = *s.sliding_normal_response;
    return out;
}

FrictionSolve read_friction_solve(const json& j) {
    FrictionSolve s;
    s.delta_velocity_matrix = read_mat3(j[velocity_key("friction_solve.delta_velocity_matrix")]);
    s.target_delta_velocity = read_vec3(j[velocity_key("friction_solve.target_delta_velocity")]);
    s.solvable = j[velocity_key("friction_solve.solvable")].get<bool>();
    s.static_impulse = read_vec3(j[velocity_key("friction_solve.static_impulse")]);
    s.tangential_impulse = j[velocity_key("friction_solve.tangential_impulse")].get<double>();
    s.cone_limit = j[velocity_key("friction_solve.cone_limit")].get<double>();
    if (j.contains(velocity_key("friction_solve.sliding_direction")))
        s.sliding_direction = Eigen::Vector2d(j[velocity_key("friction_solve.sliding_direction")][0].get<double>(),
                                              j[velocity_key("friction_solve.sliding_direction")][1].get<double>());
    if (j.contains(velocity_key("friction_solve.sliding_normal_response")))
        s.sliding_normal_response = j[velocity_key("friction_solve.sliding_normal_response")].get<double>();
    return s;
}

}  // namespace

json item_json(const VelocityIteration& it) {
    json out = {{velocity_key("iteration"), it.iteration}, {velocity_key("contact"), it.contact}};
    if (!is_avbd_iteration(it)) {  // a body visit or a dual update aims at no desired delta v
        out[velocity_key("desired_delta_velocity")] = it.desired_delta_velocity;
        out[velocity_key("epsilon")] = it.epsilon;
    }
    if (const auto& w = it.sweep)
        out[velocity_key("sweep")] = {{velocity_key("sweep.substep"), w->substep},
                                      {velocity_key("sweep.pass"), w->pass},
                                      {velocity_key("sweep.stage"), name_of(solver_stage_names, w->stage)}};
    if (const auto& a = it.accumulated)
        out[velocity_key("accumulated")] = {
            {velocity_key("accumulated.before"), vec3_json(a->before)},
            {velocity_key("accumulated.unclamped"), vec3_json(a->unclamped)},
            {velocity_key("accumulated.after"), vec3_json(a->after)},
            {velocity_key("accumulated.clamp"), name_of(impulse_clamp_names, a->clamp)}};
    if (const auto& r = it.resolution) {
        out[velocity_key("contact_velocity")] = vec3_json(r->contact_velocity);
        write_desired(out, r->desired_terms);
        out[velocity_key("impulse_model")] = name_of(impulse_model_names, r->impulse_terms.impulse_model);
        if (r->impulse_terms.friction_solve)
            out[velocity_key("friction_solve")] = friction_solve_json(*r->impulse_terms.friction_solve);
        out[velocity_key("impulse")] = vec3_json(r->impulse_terms.impulse);
        out[velocity_key("impulse_world")] = vec3_json(r->impulse_terms.impulse_world);
        out[velocity_key("impulsive_torque")] = per_body_vec3(r->velocity_change_terms.impulsive_torque);
        out[velocity_key("velocity_change")] = per_body_vec3(r->velocity_change_terms.velocity_change);
        out[velocity_key("rotation_change")] = per_body_vec3(r->velocity_change_terms.rotation_change);
    }
    write_avbd_iteration(it, out);
    json updates = json::array();
    for (const VelocityUpdate& u : it.updates)
        updates.push_back({{velocity_key("updates[].contact"), u.contact},
                           {velocity_key("updates[].body"), u.body},
                           {velocity_key("updates[].slot"), u.slot},
                           {velocity_key("updates[].delta"), vec3_json(u.delta)},
                           {velocity_key("updates[].before"), vec3_json(u.before)},
                           {velocity_key("updates[].after"), vec3_json(u.after)},
                           {velocity_key("updates[].desired_delta_velocity_before"), u.desired_delta_velocity_before},
                           {velocity_key("updates[].desired_delta_velocity_after"), u.desired_delta_velocity_after}});
    out[velocity_key("updates")] = updates;
    return out;
}

VelocityIteration read_velocity_iteration(const json& j) {
    VelocityIteration it;
    it.iteration = j[velocity_key("iteration")].get<int>();
    it.contact = j[velocity_key("contact")].get<int>();
    // AVBD's body visits and dual updates have neither (0 in the record, as the recorder makes them).
    const bool aims = j.contains(velocity_key("desired_delta_velocity"));
    it.desired_delta_velocity = aims ? j[velocity_key("desired_delta_velocity")].get<double>() : 0.0;
    it.epsilon = aims ? j[velocity_key("epsilon")].get<double>() : 0.0;
    if (j.contains(velocity_key("sweep"))) {
        const json& w = j[velocity_key("sweep")];
        it.sweep = SweepPlace{w[velocity_key("sweep.substep")].get<int>(), w[velocity_key("sweep.pass")].get<int>(),
                              read_enum(solver_stage_names, w[velocity_key("sweep.stage")])};
    }
    if (j.contains(velocity_key("accumulated"))) {
        const json& a = j[velocity_key("accumulated")];
        it.accumulated = AccumulatedImpulse{read_vec3(a[velocity_key("accumulated.before")]),
                                            read_vec3(a[velocity_key("accumulated.unclamped")]),
                                            read_vec3(a[velocity_key("accumulated.after")]),
                                            read_enum(impulse_clamp_names, a[velocity_key("accumulated.clamp")])};
    }
    if (j.contains(velocity_key("impulse_model"))) {
        VelocityResolution r;
        r.contact_velocity = read_vec3(j[velocity_key("contact_velocity")]);
        r.desired_terms = read_desired(j);
        r.impulse_terms.impulse_model = read_enum(impulse_model_names, j[velocity_key("impulse_model")]);
        if (j.contains(velocity_key("friction_solve")))
            r.impulse_terms.friction_solve = read_friction_solve(j[velocity_key("friction_solve")]);
        r.impulse_terms.impulse = read_vec3(j[velocity_key("impulse")]);
        r.impulse_terms.impulse_world = read_vec3(j[velocity_key("impulse_world")]);
        r.velocity_change_terms = {read_per_body_vec3(j[velocity_key("impulsive_torque")]),
                                   read_per_body_vec3(j[velocity_key("velocity_change")]),
                                   read_per_body_vec3(j[velocity_key("rotation_change")])};
        it.resolution = r;
    }
    read_avbd_iteration(j, it);
    for (const json& u : j[velocity_key("updates")])
        it.updates.push_back(
            {u[velocity_key("updates[].contact")].get<int>(), u[velocity_key("updates[].body")].get<int>(),
             u[velocity_key("updates[].slot")].get<int>(), read_vec3(u[velocity_key("updates[].delta")]),
             read_vec3(u[velocity_key("updates[].before")]), read_vec3(u[velocity_key("updates[].after")]),
             u[velocity_key("updates[].desired_delta_velocity_before")].get<double>(),
             u[velocity_key("updates[].desired_delta_velocity_after")].get<double>()});
    return it;
}

}  // namespace impulse::formats
