#include "model/navigator.hpp"

#include "formats/words.hpp"

#include "explain/avbd_tables.hpp"
#include "explain/format.hpp"
#include "formats/input_error.hpp"
#include "methods/method_table.hpp"

#include <algorithm>

namespace impulse::model {

namespace {

using explain::Row;
using explain::StepTable;

const FrameRecord& frame_at(const Trace& trace, const Cursor& c) {
    return trace.frames[static_cast<std::size_t>(c.frame)];
}

// Why an iteration picked its contact, as the first table of every iteration: worst first, or a sweep's turn.
// `what` is the vocabulary name of the value it compares (penetration or desired_delta_velocity).
StepTable choice_table(const char* what, int iteration, int contact, double value, double epsilon, const char* unit,
                       const std::string& pass, const std::optional<SweepPlace>& sweep,
                       const ResolverSettings& settings) {
    const std::string v = explain::number(value) + " " + unit;
    const std::string e = explain::number(epsilon) + " " + unit;
    const std::string v_exact = explain::exact(value) + " " + unit;
    const std::string e_exact = explain::exact(epsilon) + " " + unit;
    const std::string count = std::to_string(iteration), chosen = std::to_string(contact);
    if (sweep) {
        const std::string place = explain::sweep_text(*sweep, settings);
        // Soft step's order (soft_step.order): the contacts as detected, or colour by colour, or a colour's pairs four
        // at a time side by side (methods/graph_colouring.hpp, methods/wide_records.hpp).
        const bool soft_step = settings.velocity_method == VelocityMethod::soft_step;
        const SolveOrder order = soft_step ? settings.soft_step.order : SolveOrder::contacts;
        const char* const formula = order == SolveOrder::contacts  ? "next in index order"
                                    : order == SolveOrder::colours ? "next in colour order"
                                                                   : "next in colour order, four pairs side by side";
        const char* const meaning =
            order == SolveOrder::contacts ? "a sweep visits every contact in turn, whatever its value"
            : order == SolveOrder::colours
                ? "a sweep visits every contact once, colour by colour (no two pairs of a colour share a moving body), "
                  "whatever its value"
                : "a sweep visits every contact once, colour by colour, four of a colour's pairs at a time in single "
                  "precision, whatever its value";
        std::vector<Row> rows{
            {"iteration", count, "", "", "contact visits count from 0 within the phase", {}, "iteration", count},
            {"sweep", place, "", "", explain::sweep_meaning(sweep->stage), {}, "sweep", place},
            {"contact", chosen, formula, "", meaning, {}, "contact", chosen},
            {what, v, "", "", "its value now, after the visits before this one", {}, what, v_exact},
        };
        return {std::string(formats::words::step::choice), "choice — " + place + " visits contact " + chosen,
                std::move(rows)};
    }
    std::vector<Row> rows{
        {"iteration", count + pass, "", "", "iterations count from 0 within the phase", {}, "iteration", count + pass},
        {"contact",
         chosen,
         "argmax over contacts above ε",
         "",
         std::string("the contact with the largest ") + what + " is resolved first (worst first)",
         {},
         "contact",
         chosen},
        {what, v, "", "", "its value now, after the updates made by earlier iterations", {}, what, v_exact},
        {"epsilon",
         e,
         "",
         "",
         std::string("values at or below ε are left alone: the phase stops when no ") + what + " is above it",
         {},
         "epsilon",
         e_exact},
    };
    return {std::string(formats::words::step::choice), "choice — iteration " + count + " picks contact " + chosen,
            std::move(rows)};
}

// The split impulse's slop, in the place of the choice table's epsilon: its pushes compare nothing, they aim short.
Row slop_row(double slop) {
    return {"slop",
            explain::number(slop) + " m",
            "setting position_bias.slop",
            "",
            "the pushes leave this much penetration: their target is β max(penetration − slop, 0) / h",
            {},
            "slop",
            explain::exact(slop) + " m"};
}

// A position iteration's pass, as the choice table words it.
std::string pass_text(const PositionIteration& it, const ResolverSettings& settings) {
    if (!it.pass) return "";
    // The method's word for a pass (methods/method_table.hpp), from the record or, filtered out, the settings.
    const std::string_view name =
        method_row(it.resolution ? it.resolution->method : position_method_in_effect(settings)).pass_name;
    return " (" + std::string(name.empty() ? "pass" : name) + " " + std::to_string(*it.pass) + ")";
}

int steps_in(const Trace& trace, const Cursor& c) {
    return static_cast<int>(step_names(trace, c).size());
}

// The first (or last) stage of frame `f` at or after (before) index `f`, skipping frames with nothing recorded.
std::optional<Cursor> first_in_frames_from(const Trace& trace, int f) {
    for (; f < static_cast<int>(trace.frames.size()); ++f) {
        const std::vector<Stage> s = stages(trace.frames[static_cast<std::size_t>(f)]);
        if (!s.empty()) return Cursor{f, s.front(), 0, 0};
    }
    return std::nullopt;
}

std::optional<Cursor> last_in_frames_from(const Trace& trace, int f) {
    for (; f >= 0; --f) {
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
        const std::vector<Stage> s = stages(frame);
        if (s.empty()) continue;
        Cursor c{f, s.back(), item_count(frame, s.back()) - 1, 0};
        c.step = steps_in(trace, c) - 1;
        return c;
    }
    return std::nullopt;
}

// The neighbouring stage's first (or last) item, crossing frames.
std::optional<Cursor> stage_after(const Trace& trace, const Cursor& c) {
    const std::vector<Stage> s = stages(frame_at(trace, c));
    const auto here = std::find(s.begin(), s.end(), c.stage);
    if (here != s.end() && here + 1 != s.end()) return Cursor{c.frame, *(here + 1), 0, 0};
    return first_in_frames_from(trace, c.frame + 1);
}

std::optional<Cursor> stage_before(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    const std::vector<Stage> s = stages(frame);
    const auto here = std::find(s.begin(), s.end(), c.stage);
    if (here != s.end() && here != s.begin()) {
        const Stage before = *(here - 1);
        return Cursor{c.frame, before, item_count(frame, before) - 1, 0};
    }
    std::optional<Cursor> last = last_in_frames_from(trace, c.frame - 1);
    if (last) last->step = 0;
    return last;
}

// The step index with the same name in another item, or 0.
int same_step(const Trace& trace, const Cursor& target, const std::string& name) {
    const std::vector<std::string_view> steps = step_names(trace, target);
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (steps[i] == name) return static_cast<int>(i);
    return 0;
}

std::string step_name(const Trace& trace, const Cursor& c) {
    const std::vector<std::string_view> steps = step_names(trace, c);
    return c.step < static_cast<int>(steps.size()) ? std::string(steps[static_cast<std::size_t>(c.step)])
                                                   : std::string();
}

std::optional<Cursor> item_after(const Trace& trace, const Cursor& c) {
    if (c.item + 1 < item_count(frame_at(trace, c), c.stage)) return Cursor{c.frame, c.stage, c.item + 1, 0};
    return stage_after(trace, c);
}

std::optional<Cursor> item_before(const Trace& trace, const Cursor& c) {
    if (c.item > 0) return Cursor{c.frame, c.stage, c.item - 1, 0};
    return stage_before(trace, c);
}

std::optional<Cursor> with_step_named(const Trace& trace, std::optional<Cursor> target, const std::string& name) {
    if (target) target->step = same_step(trace, *target, name);
    return target;
}

}  // namespace

std::string_view stage_name(Stage stage) {
    switch (stage) {
        case Stage::preparation:
            return "preparation";
        case Stage::position:
            return "position";
        case Stage::velocity:
            return "velocity";
    }
    return "";
}

std::vector<Stage> stages(const FrameRecord& frame) {
    std::vector<Stage> order{Stage::preparation};
    if (frame.phase_order == PhaseOrder::positions_first)
        order.insert(order.end(), {Stage::position, Stage::velocity});
    else
        order.insert(order.end(), {Stage::velocity, Stage::position});
    std::erase_if(order, [&frame](Stage s) { return item_count(frame, s) == 0; });
    return order;
}

int item_count(const FrameRecord& frame, Stage stage) {
    switch (stage) {
        case Stage::preparation:
            return static_cast<int>(frame.contacts.size());
        case Stage::position:
            return static_cast<int>(frame.position.iterations.size());
        case Stage::velocity:
            return static_cast<int>(frame.velocity.iterations.size());
    }
    return 0;
}

const ContactPreparation* preparation_of(const FrameRecord& frame, int contact) {
    // Contacts are recorded in increasing index order.
    const auto found = std::lower_bound(frame.contacts.begin(), frame.contacts.end(), contact,
                                        [](const ContactPreparation& c, int i) { return c.contact < i; });
    return found != frame.contacts.end() && found->contact == contact ? &*found : nullptr;
}

int contact_at(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    const auto item = static_cast<std::size_t>(c.item);
    switch (c.stage) {
        case Stage::preparation:
            return frame.contacts[item].contact;
        case Stage::position:
            return frame.position.iterations[item].contact;
        case Stage::velocity:
            return frame.velocity.iterations[item].contact;
    }
    return 0;
}

std::vector<StepTable> step_tables(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    const auto item = static_cast<std::size_t>(c.item);
    if (c.stage == Stage::preparation) return explain::preparation_tables(frame.contacts[item]);

    const ContactPreparation* prepared = preparation_of(frame, contact_at(trace, c));
    const Mat3* basis = prepared ? &prepared->basis.contact_to_world : nullptr;
    std::vector<StepTable> tables;
    if (c.stage == Stage::position) {
        const PositionIteration& it = frame.position.iterations[item];
        StepTable choice = choice_table("penetration", it.iteration, it.contact, it.penetration, it.epsilon, "m",
                                        pass_text(it, trace.scene.settings), std::nullopt, trace.scene.settings);
        if (it.slop) choice.rows.back() = slop_row(*it.slop);  // the split impulse compares nothing with an epsilon
        tables.push_back(std::move(choice));
        for (StepTable& t : explain::position_iteration_tables(it, basis)) tables.push_back(std::move(t));
    } else {
        const VelocityIteration& it = frame.velocity.iterations[item];
        if (explain::is_avbd_visit(it))
            tables.push_back(explain::avbd_choice_table(it, trace.scene.settings));
        else
            tables.push_back(choice_table("desired_delta_velocity", it.iteration, it.contact, it.desired_delta_velocity,
                                          it.epsilon, "m/s", "", it.sweep, trace.scene.settings));
        for (StepTable& t : explain::velocity_iteration_tables(it, basis)) tables.push_back(std::move(t));
    }
    return tables;
}

std::vector<std::string_view> step_names(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    const auto item = static_cast<std::size_t>(c.item);
    if (c.stage == Stage::preparation) return explain::preparation_steps(frame.contacts[item]);
    std::vector<std::string_view> steps{formats::words::step::choice};
    for (const std::string_view s : c.stage == Stage::position
                                        ? explain::position_iteration_steps(frame.position.iterations[item])
                                        : explain::velocity_iteration_steps(frame.velocity.iterations[item]))
        steps.push_back(s);
    return steps;
}

std::optional<Cursor> first_cursor(const Trace& trace) {
    return first_in_frames_from(trace, 0);
}

std::optional<Cursor> last_cursor(const Trace& trace) {
    return last_in_frames_from(trace, static_cast<int>(trace.frames.size()) - 1);
}

std::optional<Cursor> next_step(const Trace& trace, const Cursor& c) {
    if (c.step + 1 < steps_in(trace, c)) return Cursor{c.frame, c.stage, c.item, c.step + 1};
    return item_after(trace, c);
}

std::optional<Cursor> previous_step(const Trace& trace, const Cursor& c) {
    if (c.step > 0) return Cursor{c.frame, c.stage, c.item, c.step - 1};
    std::optional<Cursor> before = item_before(trace, c);
    if (before) before->step = steps_in(trace, *before) - 1;
    return before;
}

std::optional<Cursor> next_item(const Trace& trace, const Cursor& c) {
    return with_step_named(trace, item_after(trace, c), step_name(trace, c));
}

std::optional<Cursor> previous_item(const Trace& trace, const Cursor& c) {
    return with_step_named(trace, item_before(trace, c), step_name(trace, c));
}

std::optional<Cursor> next_contact(const Trace& trace, const Cursor& c) {
    if (c.stage == Stage::preparation) return next_item(trace, c);
    const int here = contact_at(trace, c);
    std::optional<Cursor> target = item_after(trace, c);
    while (target && target->frame == c.frame && target->stage == c.stage && contact_at(trace, *target) == here)
        target = item_after(trace, *target);
    return with_step_named(trace, target, step_name(trace, c));
}

std::optional<Cursor> previous_contact(const Trace& trace, const Cursor& c) {
    if (c.stage == Stage::preparation) return previous_item(trace, c);
    const int here = contact_at(trace, c);
    std::optional<Cursor> target = item_before(trace, c);
    while (target && target->frame == c.frame && target->stage == c.stage && contact_at(trace, *target) == here)
        target = item_before(trace, *target);
    return with_step_named(trace, target, step_name(trace, c));
}

std::optional<Cursor> next_iteration(const Trace& trace, const Cursor& c) {
    // From a frame's last iteration or from a preparation, past the (next) preparation to the first phase.
    std::optional<Cursor> target = c.stage == Stage::preparation ? stage_after(trace, c) : next_item(trace, c);
    while (target && target->stage == Stage::preparation) target = stage_after(trace, *target);
    return target;
}

std::optional<Cursor> previous_iteration(const Trace& trace, const Cursor& c) {
    std::optional<Cursor> target = previous_item(trace, c);
    while (target && target->stage == Stage::preparation) target = stage_before(trace, *target);
    return target;
}

std::optional<Cursor> next_stage(const Trace& trace, const Cursor& c) {
    return stage_after(trace, c);
}

std::optional<Cursor> previous_stage(const Trace& trace, const Cursor& c) {
    // From inside a stage, go back to its start first, as a page-up key does.
    if (c.item > 0 || c.step > 0) return Cursor{c.frame, c.stage, 0, 0};
    std::optional<Cursor> before = stage_before(trace, c);
    if (before) before->item = 0;
    return before;
}

Location location_of(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    return {frame.frame, c.stage, c.stage == Stage::preparation ? 0 : c.item, contact_at(trace, c),
            step_name(trace, c)};
}

std::optional<Cursor> nearest_cursor(const Trace& trace, const Location& where) {
    std::optional<Cursor> cursor = first_cursor(trace);
    if (!cursor) return std::nullopt;
    const auto frame = std::find_if(trace.frames.begin(), trace.frames.end(),
                                    [&](const FrameRecord& r) { return r.frame == where.frame_number; });
    if (frame == trace.frames.end()) return cursor;
    const int f = static_cast<int>(frame - trace.frames.begin());
    const std::vector<Stage> present = stages(*frame);
    if (present.empty()) return cursor;
    Cursor c{f, present.front(), 0, 0};
    if (std::find(present.begin(), present.end(), where.stage) != present.end()) {
        c.stage = where.stage;
        const int count = item_count(*frame, c.stage);
        if (c.stage == Stage::preparation) {
            // The same contact if still recorded, else the first one after it.
            const auto next = std::lower_bound(frame->contacts.begin(), frame->contacts.end(), where.contact,
                                               [](const ContactPreparation& p, int i) { return p.contact < i; });
            c.item = std::min(static_cast<int>(next - frame->contacts.begin()), count - 1);
        } else {
            // The iteration nearest the old one that resolves the same contact; else the same iteration.
            c.item = std::min(where.iteration, count - 1);
            for (int d = 0; d < count; ++d) {
                const int later = where.iteration + d, earlier = where.iteration - d;
                if (later < count && contact_at(trace, Cursor{f, c.stage, later, 0}) == where.contact) {
                    c.item = later;
                    break;
                }
                if (earlier >= 0 && earlier < count &&
                    contact_at(trace, Cursor{f, c.stage, earlier, 0}) == where.contact) {
                    c.item = earlier;
                    break;
                }
            }
        }
    }
    c.step = same_step(trace, c, where.step);
    return c;
}

std::string body_label(const Trace& trace, int body) {
    return body == world_body ? std::string("world") : trace.scene.body_names[static_cast<std::size_t>(body)];
}

std::string describe(const Trace& trace, const Cursor& c) {
    const FrameRecord& frame = frame_at(trace, c);
    std::string text = "frame " + std::to_string(frame.frame) + " · ";
    if (c.stage == Stage::preparation)
        text += "preparation";
    else
        text += std::string(stage_name(c.stage)) + " phase · iteration " + std::to_string(c.item);
    const VelocityIteration* it =
        c.stage == Stage::velocity ? &frame.velocity.iterations[static_cast<std::size_t>(c.item)] : nullptr;
    if (it && it->body_visit)  // AVBD's body visit: about a body and the contacts it gathered
        text += " · body " + std::to_string(it->body_visit->body);
    else
        text += " · contact " + std::to_string(contact_at(trace, c));
    const std::string step = step_name(trace, c);
    if (!step.empty()) text += " · " + step;
    return text;
}

}  // namespace impulse::model
