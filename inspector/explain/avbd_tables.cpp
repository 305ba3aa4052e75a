#include "explain/avbd_tables.hpp"

#include "explain/format.hpp"
#include "formats/words.hpp"

#include <algorithm>

namespace impulse::explain {

namespace {

// The word of a velocity iteration named `key` (AVBD's position_change.* are not step 8's).
const formats::words::Word& word(std::string_view key) {
    const formats::words::Word* w = formats::words::find(key, 'V');
    return w ? *w : *formats::words::find(key);
}

// A row with the word's formula, equation and meaning; `label` names it ("gathered[0].force"), `note` precedes the
// meaning ("contact 3, its body 0").
Row row(std::string_view key, std::string label, std::string shown, std::string exact_text,
        std::string_view note = {}) {
    const formats::words::Word& w = word(key);
    std::string meaning = note.empty() ? std::string(w.meaning) : std::string(note) + ": " + std::string(w.meaning);
    return {std::move(label),        std::move(shown),     std::string(w.formula),
            std::string(w.equation), std::move(meaning),   {},
            std::string(key),        std::move(exact_text)};
}

Row vec3_row(std::string_view key, std::string label, const Vec3& v, double scale, std::string_view note = {}) {
    const std::string_view unit = word(key).unit;
    return row(key, std::move(label), with_unit(vector(v, scale), unit), with_unit(exact(v), unit), note);
}

Row stiffness_row(std::string_view key, std::string label, const Stiffness& k, std::string_view note = {}) {
    const double scale = std::max(std::abs(k.normal), std::abs(k.tangential));
    const std::string_view unit = word(key).unit;
    return row(key, std::move(label),
               with_unit("(" + number(k.normal, scale) + ", " + number(k.tangential, scale) + ")", unit),
               with_unit("(" + exact(k.normal) + ", " + exact(k.tangential) + ")", unit), note);
}

// Six numbers: the move's (or force's) three, then the turn's (or torque's), each three at its own scale.
std::string six(const Vec6& v, bool exact_digits) {
    const Vec3 a = v.head<3>(), b = v.tail<3>();
    const auto inner = [](const std::string& bracketed) { return bracketed.substr(1, bracketed.size() - 2); };
    return exact_digits ? inner(exact(a)) + " | " + inner(exact(b))
                        : inner(vector(a, a.cwiseAbs().maxCoeff())) + " | " + inner(vector(b, b.cwiseAbs().maxCoeff()));
}

std::string matrix6(const Mat6& m, bool exact_digits) {
    std::string out;
    for (int r = 0; r < 6; ++r) {
        if (r > 0) out += "\n";
        out += "[" + six(m.row(r).transpose(), exact_digits) + "]";
    }
    return out;
}

std::string gathered_label(std::size_t i, std::string_view part) {
    return "gathered[" + std::to_string(i) + "]." + std::string(part);
}

std::string contact_note(const AvbdContactRows& c) {
    return "contact " + std::to_string(c.contact) + ", the body is its body " + std::to_string(c.slot);
}

double largest(const std::vector<AvbdContactRows>& rows, Vec3 AvbdContactRows::*member) {
    double s = 0.0;
    for (const AvbdContactRows& c : rows) s = std::max(s, (c.*member).cwiseAbs().maxCoeff());
    return s;
}

std::vector<StepTable> body_visit_tables(const BodyVisitRecord& v) {
    std::vector<StepTable> tables;
    StepTable constraint{std::string(formats::words::step::constraint),
                         "constraint — each of the body's contacts, where the bodies stand now",
                         {}};
    const double c_scale = largest(v.gathered, &AvbdContactRows::constraint);
    for (std::size_t i = 0; i < v.gathered.size(); ++i)
        constraint.rows.push_back(vec3_row("gathered[].constraint", gathered_label(i, "constraint"),
                                           v.gathered[i].constraint, c_scale, contact_note(v.gathered[i])));
    tables.push_back(std::move(constraint));

    StepTable force{std::string(formats::words::step::force), "force — each contact's augmented-Lagrangian force", {}};
    const double f_scale =
        std::max(largest(v.gathered, &AvbdContactRows::force), largest(v.gathered, &AvbdContactRows::lambda));
    for (std::size_t i = 0; i < v.gathered.size(); ++i) {
        const AvbdContactRows& c = v.gathered[i];
        const std::string note = contact_note(c);
        force.rows.push_back(vec3_row("gathered[].lambda", gathered_label(i, "lambda"), c.lambda, f_scale, note));
        force.rows.push_back(stiffness_row("gathered[].stiffness", gathered_label(i, "stiffness"), c.stiffness, note));
        force.rows.push_back(vec3_row("gathered[].force", gathered_label(i, "force"), c.force, f_scale, note));
    }
    tables.push_back(std::move(force));

    tables.push_back(
        {std::string(formats::words::step::block_matrix),
         "block_matrix — the body's 6×6 block H",
         {row("block_matrix", "block_matrix", with_unit(matrix6(v.block_matrix, false), word("block_matrix").unit),
              matrix6(v.block_matrix, true))}});
    tables.push_back(
        {std::string(formats::words::step::block_force),
         "block_force — the right-hand side f",
         {row("block_force", "block_force", with_unit("(" + six(v.block_force, false) + ")", word("block_force").unit),
              "(" + six(v.block_force, true) + ")")}});

    const double move = v.position_change.linear.cwiseAbs().maxCoeff();
    const double turn = v.position_change.angular.cwiseAbs().maxCoeff();
    Vec6 displacement;
    displacement << v.displacement.linear, v.displacement.angular;
    tables.push_back(
        {std::string(formats::words::step::position_change),
         "position_change — the block solve H Δx = f moves the body",
         {vec3_row("position_change.linear_change", "position_change.linear_change", v.position_change.linear, move),
          vec3_row("position_change.angular_change", "position_change.angular_change", v.position_change.angular, turn),
          row("displacement", "displacement",
              with_unit("(" + six(displacement, false) + ")", word("displacement").unit),
              "(" + six(displacement, true) + ")")}});
    return tables;
}

std::vector<StepTable> dual_update_tables(const DualUpdateRecord& d) {
    const AvbdContactRows& c = d.rows;
    const double f_scale = std::max(
        {c.force.cwiseAbs().maxCoeff(), c.lambda.cwiseAbs().maxCoeff(), d.updated.lambda.cwiseAbs().maxCoeff()});
    return {
        {std::string(formats::words::step::constraint),
         "constraint — at the bodies' positions after the sweep",
         {vec3_row("constraint", "constraint", c.constraint, c.constraint.cwiseAbs().maxCoeff())}},
        {std::string(formats::words::step::force),
         "force — what the contact exerts there",
         {vec3_row("lambda", "lambda", c.lambda, f_scale), stiffness_row("stiffness", "stiffness", c.stiffness),
          row("friction", "friction", number(c.friction), number(c.friction)),
          vec3_row("force", "force", c.force, f_scale)}},
        {std::string(formats::words::step::dual_update),
         "dual_update — λ and k for the next sweep",
         {vec3_row("dual_update.lambda", "dual_update.lambda", d.updated.lambda, f_scale),
          stiffness_row("dual_update.stiffness", "dual_update.stiffness", d.updated.stiffness)}},
    };
}

}  // namespace

bool is_avbd_visit(const VelocityIteration& it) {
    return it.body_visit || it.dual_update || (it.sweep && it.sweep->stage == SolverStage::dual);
}

StepTable avbd_choice_table(const VelocityIteration& it, const ResolverSettings& settings) {
    const std::string count = std::to_string(it.iteration);
    const std::string place = it.sweep ? sweep_text(*it.sweep, settings) : std::string();
    std::vector<Row> rows{
        {"iteration", count, "", "", "visits count from 0 within the phase", {}, "iteration", count},
        {"sweep", place, "", "", it.sweep ? sweep_meaning(it.sweep->stage) : std::string(), {}, "sweep", place},
    };
    if (const auto& v = it.body_visit) {
        const std::string body = std::to_string(v->body);
        rows.push_back({"body",
                        body,
                        "next in index order",
                        "",
                        "a sweep visits every body that has a contact, in turn; the others stay where they are",
                        {},
                        "body",
                        body});
        return {std::string(formats::words::step::choice), "choice — " + place + " visits body " + body,
                std::move(rows)};
    }
    const std::string contact = std::to_string(it.contact);
    rows.push_back({"contact",
                    contact,
                    "next in index order",
                    "",
                    "after every sweep over the bodies, every contact's λ and k are updated in turn",
                    {},
                    "contact",
                    contact});
    return {std::string(formats::words::step::choice), "choice — " + place + " updates contact " + contact,
            std::move(rows)};
}

std::vector<StepTable> avbd_iteration_tables(const VelocityIteration& it) {
    if (it.body_visit) return body_visit_tables(*it.body_visit);
    if (it.dual_update) return dual_update_tables(*it.dual_update);
    return {};
}

std::vector<std::string_view> avbd_iteration_steps(const VelocityIteration& it) {
    if (it.body_visit)
        return {formats::words::step::constraint, formats::words::step::force, formats::words::step::block_matrix,
                formats::words::step::block_force, formats::words::step::position_change};
    if (it.dual_update)
        return {formats::words::step::constraint, formats::words::step::force, formats::words::step::dual_update};
    return {};
}

}  // namespace impulse::explain
