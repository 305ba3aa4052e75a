#include "formats/trace_avbd_json.hpp"

#include "formats/word_table.hpp"

namespace impulse::formats {

namespace {

consteval std::string_view key(std::string_view word) {  // a velocity iteration's
    return words::key(word, "V");
}

json vec6_json(const Vec6& v) {
    json out = json::array();
    for (int i = 0; i < 6; ++i) out.push_back(v[i]);
    return out;
}
Vec6 read_vec6(const json& j) {
    Vec6 v;
    for (int i = 0; i < 6; ++i) v[i] = j.at(static_cast<std::size_t>(i)).get<double>();
    return v;
}
json mat6_json(const Mat6& m) {
    json out = json::array();
    for (int r = 0; r < 6; ++r) out.push_back(vec6_json(m.row(r).transpose()));
    return out;
}
Mat6 read_mat6(const json& j) {
    Mat6 m;
    for (int r = 0; r < 6; ++r) m.row(r) = read_vec6(j.at(static_cast<std::size_t>(r))).transpose();
    return m;
}
json stiffness_json(const Stiffness& k) {
    return json::array({k.normal, k.tangential});
}
Stiffness read_stiffness(const json& j) {
    return {j.at(0).get<double>(), j.at(1).get<double>()};
}
json displacement_json(const Displacement& d) {
    Vec6 v;
    v << d.linear, d.angular;
    return vec6_json(v);
}
Displacement read_displacement(const json& j) {
    const Vec6 v = read_vec6(j);
    return {v.head<3>(), v.tail<3>()};
}

json gathered_json(const AvbdContactRows& c) {
    return {{key("gathered[].contact"), c.contact},
            {key("gathered[].slot"), c.slot},
            {key("gathered[].constraint"), vec3_json(c.constraint)},
            {key("gathered[].stiffness"), stiffness_json(c.stiffness)},
            {key("gathered[].lambda"), vec3_json(c.lambda)},
            {key("gathered[].force"), vec3_json(c.force)},
            {key("gathered[].friction"), c.friction}};
}
AvbdContactRows read_gathered(const json& j) {
    return {j[key("gathered[].contact")].get<int>(),    j[key("gathered[].slot")].get<int>(),
            read_vec3(j[key("gathered[].constraint")]), read_stiffness(j[key("gathered[].stiffness")]),
            read_vec3(j[key("gathered[].lambda")]),     read_vec3(j[key("gathered[].force")]),
            j[key("gathered[].friction")].get<double>()};
}

}  // namespace

bool is_avbd_iteration(const VelocityIteration& it) {
    return it.body_visit || it.dual_update ||
           (it.sweep && (it.sweep->stage == SolverStage::stabilize || it.sweep->stage == SolverStage::dual));
}

void write_avbd_iteration(const VelocityIteration& it, json& out) {
    if (const auto& v = it.body_visit) {
        out[key("body")] = v->body;
        json gathered = json::array();
        for (const AvbdContactRows& c : v->gathered) gathered.push_back(gathered_json(c));
        out[key("gathered")] = gathered;
        out[key("block_matrix")] = mat6_json(v->block_matrix);
        out[key("block_force")] = vec6_json(v->block_force);
        out[key("position_change")] = {{key("position_change.linear_change"), vec3_json(v->position_change.linear)},
                                       {key("position_change.angular_change"), vec3_json(v->position_change.angular)}};
        out[key("displacement")] = displacement_json(v->displacement);
    }
    if (const auto& d = it.dual_update) {
        out[key("constraint")] = vec3_json(d->rows.constraint);
        out[key("stiffness")] = stiffness_json(d->rows.stiffness);
        out[key("lambda")] = vec3_json(d->rows.lambda);
        out[key("force")] = vec3_json(d->rows.force);
        out[key("friction")] = d->rows.friction;
        out[key("dual_update")] = {{key("dual_update.lambda"), vec3_json(d->updated.lambda)},
                                   {key("dual_update.stiffness"), stiffness_json(d->updated.stiffness)}};
    }
}

void read_avbd_iteration(const json& j, VelocityIteration& it) {
    if (j.contains(key("body"))) {
        BodyVisitRecord& v = it.body_visit.emplace();
        v.body = j[key("body")].get<int>();
        for (const json& c : j[key("gathered")]) v.gathered.push_back(read_gathered(c));
        v.block_matrix = read_mat6(j[key("block_matrix")]);
        v.block_force = read_vec6(j[key("block_force")]);
        const json& change = j[key("position_change")];
        v.position_change = {read_vec3(change[key("position_change.linear_change")]),
                             read_vec3(change[key("position_change.angular_change")])};
        v.displacement = read_displacement(j[key("displacement")]);
    }
    if (j.contains(key("dual_update"))) {
        DualUpdateRecord& d = it.dual_update.emplace();
        d.rows.contact = it.contact;
        d.rows.constraint = read_vec3(j[key("constraint")]);
        d.rows.stiffness = read_stiffness(j[key("stiffness")]);
        d.rows.lambda = read_vec3(j[key("lambda")]);
        d.rows.force = read_vec3(j[key("force")]);
        d.rows.friction = j[key("friction")].get<double>();
        const json& u = j[key("dual_update")];
        d.updated = {read_vec3(u[key("dual_update.lambda")]), read_stiffness(u[key("dual_update.stiffness")])};
    }
}

}  // namespace impulse::formats
