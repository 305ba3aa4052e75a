#include "model/navigator.hpp"

#include "record/words.hpp"

#include "explain/format.hpp"
#include "formats/input_error.hpp"
#include "formats/suggest.hpp"
#include "methods/method_table.hpp"

#include <algorithm>
#include <charconv>

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
        std::vector<Row> rows{
            {"iteration", count, "", "", "contact visits count from 0 within the phase", {}, "iteration", count},
            {"sweep", place, "", "", explain::sweep_meaning(sweep->stage), {}, "sweep", place},
            {"contact",
             chosen,
             "next in index order",
             "",
             "a sweep visits every contact in turn, whatever its value",
             {},
             "contact",
             chosen},
            {what, v, "", "", "its value now, after the visits before this one", {}, what, v_exact},
        };
        return {std::string(words::step::choice), "choice — " + place + " visits contact " + chosen, std::move(rows)};
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
    return {std::string(words::step::choice), "choice — iteration " + count + " picks contact " + chosen,
            std::move(rows)};
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

int parse_int(std::string_view text, std::string_view part, std::string_view where) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || value < 0)
        throw formats::InputError(std::string(where),
                                  std::string(part) + " must be a whole number ≥ 0, got \"" + std::string(text) + "\"");
    return value;
}

std::string recorded_frames(const Trace& trace) {
    if (trace.frames.empty()) return "no frames are recorded";
    return "recorded frames: " + std::to_string(trace.frames.front().frame) + ".." +
           std::to_string(trace.frames.back().frame);
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
        tables.push_back(choice_table("penetration", it.iteration, it.contact, it.penetration, it.epsilon, "m",
                                      pass_text(it, trace.scene.settings), std::nullopt, trace.scene.settings));
        for (StepTable& t : explain::position_iteration_tables(it, basis)) tables.push_back(std::move(t));
    } else {
        const VelocityIteration& it = frame.velocity.iterations[item];
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
    std::vector<std::string_view> steps{words::step::choice};
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

GotoSpec parse_goto(std::string_view text, std::string_view where) {
    GotoSpec spec;
    if (text.empty())
        throw formats::InputError(std::string(where), "empty place; expected e.g. frame=0,phase=velocity");
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view part = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        const std::size_t equals = part.find('=');
        if (equals == std::string_view::npos)
            throw formats::InputError(std::string(where), "\"" + std::string(part) +
                                                              "\" is not NAME=VALUE (names: frame, phase, iteration, "
                                                              "contact, step)");
        const std::string_view name = part.substr(0, equals), value = part.substr(equals + 1);
        if (name == "frame")
            spec.frame = parse_int(value, "frame", where);
        else if (name == "iteration")
            spec.iteration = parse_int(value, "iteration", where);
        else if (name == "contact")
            spec.contact = parse_int(value, "contact", where);
        else if (name == "phase") {
            if (value == "preparation")
                spec.stage = Stage::preparation;
            else if (value == "position")
                spec.stage = Stage::position;
            else if (value == "velocity")
                spec.stage = Stage::velocity;
            else
                throw formats::InputError(
                    std::string(where),
                    "phase must be preparation, position or velocity, got \"" + std::string(value) + "\"");
        } else if (name == "step") {
            if (value.empty()) throw formats::InputError(std::string(where), "step needs a name, e.g. step=impulse");
            spec.step = std::string(value);
            // A step's name from before trace format 2 (velocity_per_unit_impulse, accumulated_impulse) reads as
            // today's (docs/trace-format.md).
            for (const words::StepRename& r : words::step_renames())
                if (*spec.step == r.old_name) spec.step = std::string(r.new_name);
        } else
            throw formats::InputError(std::string(where), "unknown part \"" + std::string(name) +
                                                              "\" (parts: frame, phase, iteration, contact, step)");
    }
    return spec;
}

namespace {

// Where a place points before its step: the frame, the stage and the item. Throws formats::InputError(at, ...).
Cursor place_of(const Trace& trace, const GotoSpec& spec, const std::string& at) {
    if (!first_cursor(trace)) throw formats::InputError(at, "the trace records nothing to step through");
    int f = first_cursor(trace)->frame;
    if (spec.frame) {
        const auto found = std::find_if(trace.frames.begin(), trace.frames.end(),
                                        [&](const FrameRecord& r) { return r.frame == *spec.frame; });
        if (found == trace.frames.end())
            throw formats::InputError(
                at, "frame " + std::to_string(*spec.frame) + " is not in the trace (" + recorded_frames(trace) + ")");
        f = static_cast<int>(found - trace.frames.begin());
    }
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
    const std::vector<Stage> present = stages(frame);
    if (present.empty()) throw formats::InputError(at, "frame " + std::to_string(frame.frame) + " records nothing");
    // Naming an iteration without a phase means the first phase that has it.
    Stage stage = spec.stage ? *spec.stage : present.front();
    if (!spec.stage && spec.iteration) {
        const auto phase =
            std::find_if(present.begin(), present.end(), [](Stage s) { return s != Stage::preparation; });
        if (phase != present.end()) stage = *phase;
        for (Stage s : present)
            if (s != Stage::preparation && *spec.iteration < item_count(frame, s)) {
                stage = s;
                break;
            }
    }
    if (std::find(present.begin(), present.end(), stage) == present.end())
        throw formats::InputError(at, "frame " + std::to_string(frame.frame) + " has no " +
                                          std::string(stage_name(stage)) +
                                          (stage == Stage::preparation ? " (no contact was recorded)" : " iterations"));

    Cursor cursor{f, stage, 0, 0};
    const int count = item_count(frame, stage);
    if (stage == Stage::preparation) {
        if (spec.iteration) throw formats::InputError(at, "the preparation has no iterations; use contact=C");
        if (spec.contact) {
            const ContactPreparation* p = preparation_of(frame, *spec.contact);
            if (!p)
                throw formats::InputError(at, "contact " + std::to_string(*spec.contact) +
                                                  " is not recorded in frame " + std::to_string(frame.frame) +
                                                  " (it has " + std::to_string(frame.contact_count) +
                                                  " contacts, numbered from 0)");
            cursor.item = static_cast<int>(p - frame.contacts.data());
        }
    } else {
        if (spec.iteration) {
            if (*spec.iteration >= count)
                throw formats::InputError(at, "the " + std::string(stage_name(stage)) + " phase of frame " +
                                                  std::to_string(frame.frame) + " has iterations 0.." +
                                                  std::to_string(count - 1) + ", not " +
                                                  std::to_string(*spec.iteration));
            cursor.item = *spec.iteration;
        }
        if (spec.contact) {
            // The first iteration from here on that chose the contact.
            int i = cursor.item;
            while (i < count && contact_at(trace, Cursor{f, stage, i, 0}) != *spec.contact) ++i;
            if (i == count)
                throw formats::InputError(
                    at, "no iteration of the " + std::string(stage_name(stage)) + " phase" +
                            (spec.iteration ? " from iteration " + std::to_string(*spec.iteration) : std::string()) +
                            " chose contact " + std::to_string(*spec.contact));
            cursor.item = i;
        }
    }
    return cursor;
}

// A word's name as a --goto may give it: its key path without the list marks ("updates[].after" -> "updates.after")
// and its last part ("after").
std::string plain_name(std::string_view quantity) {
    std::string name(quantity);
    for (std::size_t at = name.find("[]"); at != std::string::npos; at = name.find("[]")) name.erase(at, 2);
    return name;
}
std::string last_part(std::string_view quantity) {
    const std::string name = plain_name(quantity);
    return name.substr(name.rfind('.') == std::string::npos ? 0 : name.rfind('.') + 1);
}

// The step of the item at `cursor` named by `name`: a step's own name; else a word of the list by its full name, or
// by its last part when no word has that full name (an index after it ignored: "impulse_world[1]"): the table that
// shows it (of two words sharing a last part, the later: position_change.angular_change before
// rewind.angular_change), else the step that computes it (updates[].after: the updates).
std::optional<int> step_named(const Trace& trace, const Cursor& cursor, const std::string& name) {
    const std::vector<std::string_view> steps = step_names(trace, cursor);
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (steps[i] == name) return static_cast<int>(i);
    const std::string wanted = name.substr(0, name.find('['));
    std::vector<const words::Word*> candidates;
    for (const bool whole : {true, false}) {
        for (const words::Word& w : words::all())
            if ((whole ? plain_name(w.quantity) : last_part(w.quantity)) == wanted) candidates.push_back(&w);
        if (!candidates.empty()) break;
    }
    if (candidates.empty()) return std::nullopt;
    const std::vector<StepTable> tables = step_tables(trace, cursor);
    for (auto w = candidates.rbegin(); w != candidates.rend(); ++w)
        for (std::size_t i = 0; i < tables.size(); ++i)
            for (const Row& r : tables[i].rows)
                if (r.key == (*w)->quantity) return static_cast<int>(i);
    for (auto w = candidates.rbegin(); w != candidates.rend(); ++w)
        for (std::size_t i = 0; i < steps.size(); ++i)
            if (steps[i] == (*w)->step) return static_cast<int>(i);
    return std::nullopt;
}

// "the preparation", "the position phase".
std::string stage_phrase(Stage stage) {
    return stage == Stage::preparation ? "the preparation" : "the " + std::string(stage_name(stage)) + " phase";
}

}  // namespace

Cursor resolve_goto(const Trace& trace, const GotoSpec& spec, std::string_view where) {
    const std::string at(where);
    Cursor cursor = place_of(trace, spec, at);
    if (!spec.step) return cursor;
    if (const std::optional<int> found = step_named(trace, cursor, *spec.step)) {
        cursor.step = *found;
        return cursor;
    }
    // Not in this stage. The same place in the frame's other stages: without a phase named, the first that shows
    // the step is meant (as for an iteration); with one, the error says where the step is.
    std::vector<Cursor> elsewhere;
    for (const Stage stage : stages(trace.frames[static_cast<std::size_t>(cursor.frame)])) {
        if (stage == cursor.stage) continue;
        GotoSpec there = spec;
        there.stage = stage;
        try {
            elsewhere.push_back(place_of(trace, there, at));
        } catch (const formats::InputError&) {
            // this stage has no such place (e.g. no iteration chose the contact)
        }
    }
    for (Cursor& other : elsewhere)
        if (const std::optional<int> found = step_named(trace, other, *spec.step)) {
            if (spec.stage)
                throw formats::InputError(
                    at, "no step or quantity \"" + *spec.step + "\" in " + stage_phrase(cursor.stage) + "; it is in " +
                            stage_phrase(other.stage) + " (phase=" + std::string(stage_name(other.stage)) + ")");
            other.step = *found;
            return other;
        }
    // Misspelt: the nearest step here or elsewhere in the frame, or word of the list (full or last part).
    std::vector<std::string> names;
    std::vector<std::optional<Stage>> stage_of;
    for (const Cursor& c : elsewhere.empty() ? std::vector<Cursor>{cursor} : [&] {
             std::vector<Cursor> all{cursor};
             all.insert(all.end(), elsewhere.begin(), elsewhere.end());
             return all;
         }())
        for (const std::string_view s : step_names(trace, c)) names.emplace_back(s), stage_of.push_back(c.stage);
    for (const words::Word& w : words::all()) {
        names.push_back(plain_name(w.quantity)), stage_of.push_back(std::nullopt);
        names.push_back(last_part(w.quantity)), stage_of.push_back(std::nullopt);
    }
    std::string steps;
    for (const std::string_view s : step_names(trace, cursor)) steps += (steps.empty() ? "" : ", ") + std::string(s);
    std::string problem =
        "no step or quantity \"" + *spec.step + "\" in " + stage_phrase(cursor.stage) + " (its steps: " + steps + ")";
    if (const std::optional<std::string> meant = formats::closest_name(*spec.step, names)) {
        const std::optional<Stage> stage =
            stage_of[static_cast<std::size_t>(std::find(names.begin(), names.end(), *meant) - names.begin())];
        problem += "; did you mean \"" + *meant + "\"" +
                   (!stage || *stage == cursor.stage
                        ? std::string()
                        : ", in " + stage_phrase(*stage) + " (phase=" + std::string(stage_name(*stage)) + ")") +
                   "?";
    }
    throw formats::InputError(at, problem);
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
    text += " · contact " + std::to_string(contact_at(trace, c));
    const std::string step = step_name(trace, c);
    if (!step.empty()) text += " · " + step;
    return text;
}

}  // namespace impulse::model
