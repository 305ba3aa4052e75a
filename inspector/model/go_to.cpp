#include "model/navigator.hpp"

#include "formats/words.hpp"

#include "formats/input_error.hpp"
#include "formats/suggest.hpp"

#include <algorithm>
#include <charconv>

// A place named by a person (--goto, a script's goto, a lesson's step): parsed, then resolved against a trace, a
// step by its name or by a word of the list (navigator.hpp says how).

namespace impulse::model {

namespace {

using explain::Row;
using explain::StepTable;

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
            for (const formats::words::StepRename& r : formats::words::step_renames())
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
    std::vector<const formats::words::Word*> candidates;
    for (const bool whole : {true, false}) {
        for (const formats::words::Word& w : formats::words::all())
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
    for (const formats::words::Word& w : formats::words::all()) {
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

}  // namespace impulse::model
