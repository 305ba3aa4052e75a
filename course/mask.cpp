#include "course/mask.hpp"

#include "explain/annotations.hpp"
#include "formats/input_error.hpp"
#include "formats/trace_json.hpp"
#include "course/trace_path.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace impulse::course {

namespace {

using json = nlohmann::ordered_json;
using model::Cursor;
using model::Stage;

// What a value shows about itself only, never about a hidden change: indices, settings, what a contact is given.
bool fixed_row(std::string_view key) {
    static const std::set<std::string_view, std::less<>> fixed{"iteration",
                                                               "contact",
                                                               "sweep",
                                                               "epsilon",
                                                               "slop",
                                                               "pass",
                                                               "restitution",
                                                               "friction",
                                                               "restitution_cutoff",
                                                               "velocity_from_acceleration_applied",
                                                               "rewind.time_limit",
                                                               "angular_limit.policy",
                                                               "angular_limit.factor"};
    return fixed.count(key) > 0;
}

// Every item of a frame, in the order they ran: the prepared contacts, then each phase's iterations.
std::vector<Cursor> items_of(const Trace& trace, int f) {
    std::vector<Cursor> items;
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
    for (Stage stage : model::stages(frame))
        for (int i = 0; i < model::item_count(frame, stage); ++i) items.push_back(Cursor{f, stage, i, 0});
    return items;
}

int rank_in(const Trace& trace, const Cursor& c) {
    if (c.stage == Stage::preparation) return 0;
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(c.frame)];
    int offset = 1;
    for (Stage stage : model::stages(frame)) {
        if (stage == Stage::preparation) continue;
        if (stage == c.stage) return offset + c.item;
        offset += model::item_count(frame, stage);
    }
    return offset;
}

// The paths to compare with a question's value in any item: the path itself, and with its first index free
// when that index picks a body ([body0, body1]) or an update.
std::vector<std::string> paths_like(const json& item, const std::string& path) {
    const std::size_t open = path.find('[');
    if (open == std::string::npos) return {path};
    const std::string key = path.substr(0, open);
    const std::size_t close = path.find(']', open);
    if (close == std::string::npos || !item.contains(key) || !item[key].is_array()) return {path};
    const json& array = item[key];
    const bool per_body =
        array.size() == 2 && (array[0].is_array() || array[0].is_number() || array[0].is_null() || array[1].is_null());
    if (!per_body && key != "updates") return {path};
    std::vector<std::string> paths;
    for (std::size_t i = 0; i < array.size(); ++i)
        paths.push_back(key + "[" + std::to_string(i) + "]" + path.substr(close + 1));
    return paths;
}

void add_with_consumers(std::set<std::string, std::less<>>& keys, std::string_view name) {
    keys.insert(std::string(name));
    for (std::string_view c : explain::consumers(name)) keys.insert(std::string(c));
}

// A question asked before the step that computes its quantity looks ahead: the inputs that step computes on
// the way (the parts that add up to it) would hand the answer over, so they are hidden too.
void add_same_step_inputs(std::set<std::string, std::less<>>& keys, std::string_view quantity) {
    const explain::Annotation& a = explain::annotation(quantity);
    std::vector<std::string_view> todo = explain::inputs_of(a);
    while (!todo.empty()) {
        const std::string_view name = todo.back();
        todo.pop_back();
        const explain::Annotation* input = explain::find_annotation(name);
        if (!input || input->step != a.step || !keys.insert(std::string(name)).second) continue;
        for (std::string_view next : explain::inputs_of(*input)) todo.push_back(next);
    }
}

bool looks_ahead(const Trace& trace, const Cursor& place, std::string_view quantity) {
    const std::vector<explain::StepTable> tables = model::step_tables(trace, place);
    const std::string_view step = explain::annotation(quantity).step;
    for (std::size_t t = 0; t < tables.size(); ++t) {
        const bool computes =
            tables[t].step == step || std::any_of(tables[t].rows.begin(), tables[t].rows.end(),
                                                  [&](const explain::Row& r) { return r.key == quantity; });
        if (computes) return static_cast<int>(t) > place.step;
    }
    return false;
}

// Whether what a question hides changes the bodies: an impulse or a move, or an update (the bodies' new
// state gives a contact's velocity or penetration after it in one step).
bool changes_bodies(const std::set<std::string, std::less<>>& keys) {
    return keys.count("bodies_after") || keys.count("velocity_update") || keys.count("penetration_update");
}

// The numbers in a value as shown with every digit ("(0, -0.5, 0) m", "v_s -2 → 1 m/s").
std::vector<double> numbers_in(const std::string& text) {
    std::vector<double> found;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        const bool starts =
            std::isdigit(static_cast<unsigned char>(c)) ||
            ((c == '-' || c == '.') && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])));
        // A digit inside a name ("t₁", "contact 3" is text, not a value) is not a value's start.
        const bool inside_word = i > 0 && (std::isalpha(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_');
        if (!starts || inside_word) {
            ++i;
            continue;
        }
        char* end = nullptr;
        found.push_back(std::strtod(text.c_str() + i, &end));
        i = std::max(i + 1, static_cast<std::size_t>(end - text.c_str()));
    }
    return found;
}

}  // namespace

std::vector<std::optional<QuestionReach>> question_reaches(const PreparedLesson& prepared, const Trace& trace) {
    const Lesson& lesson = prepared.lesson;
    std::vector<std::optional<QuestionReach>> reaches(lesson.steps.size());
    for (std::size_t i = 0; i < lesson.steps.size(); ++i) {
        const Step& step = lesson.steps[i];
        if (!step.question || !prepared.answers[i]) continue;
        const Question& q = *step.question;
        const Answer& answer = *prepared.answers[i];
        QuestionReach reach;
        reach.step = static_cast<int>(i);
        std::optional<Cursor> place;
        try {
            place = model::resolve_goto(trace, model::parse_goto(step.at, "at"), "at");
        } catch (const formats::InputError&) {
            // A re-run with other settings may not have this place: the question then hides its keys in
            // every frame and contact.
        }
        const std::string quantity = place ? question_quantity(q, place->stage) : answer.quantity;
        if (quantity.empty()) continue;
        add_with_consumers(reach.keys, quantity);
        for (const std::string& r : q.reveals) add_with_consumers(reach.keys, r);
        if (!place) {
            reaches[i] = std::move(reach);
            continue;
        }
        if (looks_ahead(trace, *place, quantity)) add_same_step_inputs(reach.keys, quantity);
        // Everything the answer is computed from: the student works from those, so they stay in view even
        // when one equals the answer.
        std::vector<std::string_view> todo = explain::inputs_of(explain::annotation(quantity));
        while (!todo.empty()) {
            const std::string_view name = todo.back();
            todo.pop_back();
            if (!reach.inputs.insert(std::string(name)).second) continue;
            if (const explain::Annotation* a = explain::find_annotation(name))
                for (std::string_view next : explain::inputs_of(*a)) todo.push_back(next);
        }
        reach.frame = place->frame;
        const int own = model::contact_at(trace, *place);
        reach.contacts.insert(own);

        // Contacts whose same quantity has the answer's value: the same answer, shown elsewhere.
        const std::vector<Cursor> items = items_of(trace, place->frame);
        if (q.kind == Question::Kind::predict) {
            std::string problem;
            const json own_item = item_json(trace, *place);
            const json* here = follow(own_item, q.value, problem);
            if (here && here->is_number()) {
                const double value = here->get<double>();
                const double allowed =
                    std::max(q.tolerance.relative.value_or(0.0) * std::abs(value), q.tolerance.absolute.value_or(0.0));
                reach.answer = value;
                reach.allowed = allowed;
                reach.unit = explain::annotation(quantity).unit;
                // Only the kinds of item that hold the quantity (the brick wall's 2000 velocity iterations hold
                // no relaxation amount).
                const std::string_view kinds = explain::annotation(quantity).items;
                for (const Cursor& item : items) {
                    const char kind = item.stage == Stage::preparation ? 'C'
                                      : item.stage == Stage::position  ? 'P'
                                                                       : 'V';
                    if (kinds.find(kind) == std::string_view::npos) continue;
                    const json j = item_json(trace, item);
                    for (const std::string& path : paths_like(j, q.value)) {
                        const json* other = follow(j, path, problem);
                        if (other && other->is_number() && std::abs(other->get<double>() - value) <= allowed)
                            reach.contacts.insert(model::contact_at(trace, item));
                    }
                }
            }
        }

        // The bodies a hidden change moves: from the question's own item on (an earlier visit of its contact
        // is what the question starts from), and every item of the other contacts that share its value.
        if (changes_bodies(reach.keys)) {
            const int from = rank_in(trace, *place);
            const FrameRecord& frame = trace.frames[static_cast<std::size_t>(place->frame)];
            for (const Cursor& item : items) {
                if (item.stage == Stage::preparation) continue;
                const int contact = model::contact_at(trace, item);
                if (!reach.contacts.count(contact) || (contact == own && rank_in(trace, item) < from)) continue;
                const bool resolved =
                    item.stage == Stage::position
                        ? frame.position.iterations[static_cast<std::size_t>(item.item)].resolution.has_value()
                        : frame.velocity.iterations[static_cast<std::size_t>(item.item)].resolution.has_value();
                const ContactPreparation* p = model::preparation_of(frame, contact);
                if (!resolved || !p) continue;
                for (int body : p->bodies)
                    if (body != world_body && !reach.bodies.count(body)) reach.bodies.emplace(body, item);
            }
        }
        reaches[i] = std::move(reach);
    }
    return reaches;
}

Mask::Mask(const std::vector<std::optional<QuestionReach>>& reaches, const std::vector<bool>& open, const Trace& trace)
    : trace_(&trace) {
    for (std::size_t i = 0; i < reaches.size() && i < open.size(); ++i)
        if (open[i] && reaches[i]) reaches_.push_back(*reaches[i]);
}

int Mask::rank(const Cursor& c) const {
    return rank_in(*trace_, c);
}

bool Mask::later(const Cursor& at, const Cursor& from, bool including) const {
    if (at.frame != from.frame) return at.frame > from.frame;
    return including ? rank(at) >= rank(from) : rank(at) > rank(from);
}

HiddenBy Mask::touches_hidden_body(const Cursor& at, int contact, bool including) const {
    const ContactPreparation* p = model::preparation_of(trace_->frames[static_cast<std::size_t>(at.frame)], contact);
    if (!p) return std::nullopt;
    for (const QuestionReach& r : reaches_)
        for (int body : p->bodies)
            if (const auto found = r.bodies.find(body); found != r.bodies.end() && later(at, found->second, including))
                return r.step;
    return std::nullopt;
}

HiddenBy Mask::answer_equal_to(std::string_view key, double value, std::string_view unit, bool inputs_too) const {
    const explain::Annotation* a = explain::find_annotation(key);
    if (unit.empty() && a) unit = a->unit;
    if (unit.empty()) return std::nullopt;
    for (const QuestionReach& r : reaches_)
        if (r.answer && r.unit == unit && std::abs(*r.answer) > r.allowed && std::abs(value - *r.answer) <= r.allowed &&
            (inputs_too || !r.inputs.count(key)))
            return r.step;
    return std::nullopt;
}

HiddenBy Mask::row_hidden_by(const Cursor& item, const explain::Row& row) const {
    if (reaches_.empty() || row.key.empty()) return std::nullopt;
    const int contact = model::contact_at(*trace_, item);
    for (const QuestionReach& r : reaches_) {
        const bool here = r.frame < 0 || (r.frame == item.frame && r.contacts.count(contact));
        if (here && r.keys.count(row.key)) return r.step;
    }
    // Any value in it equal to an open answer (read only when an answer is in the row's unit).
    const explain::Annotation* a = explain::find_annotation(row.key);
    if (a && !fixed_row(row.key) && std::any_of(reaches_.begin(), reaches_.end(), [&](const QuestionReach& r) {
            return r.answer && r.unit == a->unit;
        }))
        for (double v : numbers_in(row.exact))
            if (const HiddenBy by = answer_equal_to(row.key, v)) return by;
    // Computed from a body a hidden change moved earlier: everything but what the item is given.
    if (fixed_row(row.key)) return std::nullopt;
    return touches_hidden_body(item, contact, false);
}

HiddenBy Mask::other_frame_hidden_by(const Cursor& item, const explain::Row& row) const {
    if (const HiddenBy by = row_hidden_by(item, row)) return by;
    if (row.other_frame.empty() || reaches_.empty()) return std::nullopt;
    const explain::Annotation* a = explain::find_annotation(row.key);
    if (!a || fixed_row(row.key)) return std::nullopt;
    // The same quantity in the other frame: the answer it would hand over is in the same unit.
    for (double v : numbers_in(row.other_frame))
        if (const HiddenBy by = answer_equal_to(row.key, v, a->unit, true)) return by;
    return std::nullopt;
}

HiddenBy Mask::value_hidden_by(const Cursor& at, int contact, std::string_view key, double value) const {
    if (reaches_.empty()) return std::nullopt;
    for (const QuestionReach& r : reaches_) {
        const bool here = r.frame < 0 || (r.frame == at.frame && r.contacts.count(contact));
        if (here && r.keys.count(key)) return r.step;
    }
    if (const HiddenBy by = answer_equal_to(key, value, key == "impulse_world" ? "N·s" : "")) return by;
    return touches_hidden_body(at, contact, false);
}

HiddenBy Mask::bodies_hidden_by(int frame, int contact) const {
    for (const QuestionReach& r : reaches_)
        if (r.keys.count("bodies") && (r.frame < 0 || (r.frame == frame && r.contacts.count(contact)))) return r.step;
    return std::nullopt;
}

HiddenBy Mask::body_hidden_by(const Cursor& at, int body, bool after, const BodyState& state) const {
    if (const HiddenBy by = body_hidden_by(at, body, after)) return by;
    for (int k = 0; k < 3; ++k)
        for (const HiddenBy by :
             {answer_equal_to("body_position", state.position[k]), answer_equal_to("body_velocity", state.velocity[k]),
              answer_equal_to("body_angular_velocity", state.angular_velocity[k])})
            if (by) return by;
    return std::nullopt;
}

HiddenBy Mask::body_hidden_by(const Cursor& at, int body, bool after) const {
    for (const QuestionReach& r : reaches_)
        if (const auto found = r.bodies.find(body); found != r.bodies.end() && later(at, found->second, after))
            return r.step;
    return std::nullopt;
}

std::optional<Cursor> Mask::body_shown_until(const Cursor& at, int body) const {
    std::optional<Cursor> earliest;
    for (const QuestionReach& r : reaches_)
        if (const auto found = r.bodies.find(body); found != r.bodies.end() && later(at, found->second, true))
            if (!earliest || later(*earliest, found->second, false)) earliest = found->second;
    return earliest;
}

}  // namespace impulse::course
