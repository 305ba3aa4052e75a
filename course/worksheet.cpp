#include "course/worksheet.hpp"

#include "formats/csv.hpp"
#include "course/tolerance.hpp"
#include "course/step_keys.hpp"
#include "course/trace_items.hpp"
#include "formats/input_error.hpp"
#include "formats/scene_file.hpp"
#include "course/course_schemas.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "model/runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace impulse::course {

namespace {

using model::Cursor;
using model::Stage;

// The step names of the cursor's item, in the order its tables show them.
std::vector<std::string> step_order(const Trace& trace, const Cursor& c) {
    std::vector<std::string> names;
    for (const explain::StepTable& t : model::step_tables(trace, c)) names.push_back(t.step);
    return names;
}

std::vector<WorksheetEntry> cells_of(const ItemAt& item, const std::string& step) {
    std::vector<WorksheetEntry> cells;
    for (const StepKey& key : step_keys())
        if (key.item == item.kind && key.role == Role::computed && key.step == step) expand_key(item, key, step, cells);
    return cells;
}

std::string at_spec(const Trace& trace, const Cursor& c, const std::string& step) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(c.frame)];
    std::string spec = "frame=" + std::to_string(frame.frame) + ",phase=" + std::string(model::stage_name(c.stage));
    if (c.stage == Stage::preparation)
        spec += ",contact=" + std::to_string(model::contact_at(trace, c));
    else
        spec += ",iteration=" + std::to_string(c.item);
    return spec + ",step=" + step;
}

formats::json blanked(const formats::json& value) {
    if (!value.is_array()) return nullptr;
    formats::json out = formats::json::array();
    for (const formats::json& v : value) out.push_back(blanked(v));
    return out;
}

formats::json entry_json(const WorksheetEntry& e, bool blank) {
    return {{"path", e.path},         {"step", e.step},
            {"quantity", e.quantity}, {"unit", e.unit},
            {"formula", e.formula},   {"equation", e.equation},
            {"meaning", e.meaning},   {"value", blank ? blanked(e.value) : e.value}};
}

// Whether a cursor's step has anything to fill in, and the names of the item's steps that have.
std::vector<std::string> steps_with_cells(const formats::json& document, const Trace& trace, const Cursor& c) {
    const ItemAt item = item_at(document, c);
    std::vector<std::string> names;
    for (const std::string& name : step_order(trace, c))
        if (!cells_of(item, name).empty()) names.push_back(name);
    return names;
}

// Each token after `from` as a path continues: ".key" or "[i]" (no dot at the start).
std::string path_text(const std::vector<PathToken>& path, std::size_t from) {
    std::string text;
    for (std::size_t i = from; i < path.size(); ++i) {
        if (const auto* key = std::get_if<std::string>(&path[i]))
            text += (text.empty() ? "" : ".") + *key;
        else
            text += "[" + std::to_string(std::get<std::size_t>(path[i])) + "]";
    }
    return text;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text.empty() ? "none" : text;
}

}  // namespace

double rounded_for_hand_work(double value) {
    return rounded_for_hand_work(value, Tolerance{});  // diff's defaults
}

double rounded_for_hand_work(double value, const Tolerance& grading) {
    const double allowed = (grading.atol + grading.rtol * std::abs(value)) * hand_rounding_share;
    if (!std::isfinite(value)) return value;
    if (std::abs(value) <= allowed) return 0.0;  // rounding noise around 0 (and −0) is 0
    for (int digits = 1; digits < 17; ++digits) {
        char text[40];
        std::snprintf(text, sizeof text, "%.*g", digits, value);
        const double shorter = std::strtod(text, nullptr);
        if (std::abs(shorter - value) <= allowed) return shorter;
    }
    return value;
}

formats::json rounded_for_hand_work(const formats::json& value) {
    if (value.is_number_float()) return rounded_for_hand_work(value.get<double>());
    if (!value.is_array()) return value;
    formats::json out = formats::json::array();
    for (const formats::json& v : value) out.push_back(rounded_for_hand_work(v));
    return out;
}

Wording word_path(const Trace& trace, const formats::json& document, const std::vector<PathToken>& path,
                  WordingCache* cache) {
    Wording w{"", path_text(path, 0), describe_path(document, path).unit};
    if (key_at(path, 0, "settings") || key_at(path, 0, "scene") || key_at(path, 0, "recording") ||
        key_at(path, 0, "conventions")) {
        w.place = std::get<std::string>(path[0]);
        w.quantity = path_text(path, 1);
        return w;
    }
    const std::optional<std::size_t> f = index_at(path, 1);
    if (!key_at(path, 0, "frames") || !f || *f >= trace.frames.size()) return w;
    w.place = "frame " + std::to_string(trace.frames[*f].frame);
    w.quantity = path_text(path, 2);

    // Inside an item: the step that computes (or first uses) the key, as the worksheet names it.
    std::optional<Cursor> c;
    std::size_t rest = 0;
    if (key_at(path, 2, "contacts") && index_at(path, 3) && *index_at(path, 3) < trace.frames[*f].contacts.size()) {
        c = Cursor{static_cast<int>(*f), Stage::preparation, static_cast<int>(*index_at(path, 3)), 0};
        rest = 4;
    } else if (key_at(path, 2, "phases") && index_at(path, 3) && key_at(path, 4, "iterations") && index_at(path, 5)) {
        const formats::json* phase = value_at(document, {path.begin(), path.begin() + 4});
        const formats::json* iteration = value_at(document, {path.begin(), path.begin() + 6});
        if (phase && iteration && phase->contains("phase"))
            c = Cursor{static_cast<int>(*f), (*phase)["phase"] == "position" ? Stage::position : Stage::velocity,
                       static_cast<int>(*index_at(path, 5)), 0};
        rest = 6;
    }
    if (!c || rest >= path.size()) return w;
    const ItemKind kind = c->stage == Stage::preparation ? ItemKind::contact
                          : c->stage == Stage::position  ? ItemKind::position_iteration
                                                         : ItemKind::velocity_iteration;
    const std::string key = step_key_of(path, rest);
    const std::tuple<int, int, int> item{c->frame, static_cast<int>(c->stage), c->item};
    std::vector<std::string> made;
    if (!cache) made = step_order(trace, *c);
    const std::vector<std::string>& order =
        cache ? cache->step_orders.try_emplace(item, step_order(trace, *c)).first->second : made;
    const auto place = [&](const Cursor& at) {
        if (!cache) return model::describe(trace, at);
        const std::tuple<int, int, int, int> step{at.frame, static_cast<int>(at.stage), at.item, at.step};
        const auto found = cache->places.find(step);
        return found != cache->places.end() ? found->second
                                            : cache->places.emplace(step, model::describe(trace, at)).first->second;
    };
    const StepKey* step_key = find_step_key(kind, key);
    const auto at = step_key ? std::find(order.begin(), order.end(), std::string(step_key->step)) : order.end();
    w.quantity = path_text(path, rest);
    if (at != order.end()) {
        c->step = static_cast<int>(at - order.begin());
        w.place = place(*c);
    } else {
        // A given of the item (the contact as detected, the iteration's choice): the item without a step.
        w.place = place(*c);
        const std::string first = order.empty() ? "" : " · " + order.front();
        if (!first.empty() && w.place.ends_with(first)) w.place.resize(w.place.size() - first.size());
    }
    return w;
}

std::vector<Cursor> places_with_cells(const model::Session& session, const std::vector<Cursor>& candidates,
                                      const formats::json* given_document) {
    const Trace& trace = session.trace();
    const formats::json made = given_document ? formats::json() : formats::trace_json(trace);
    const formats::json& document = given_document ? *given_document : made;
    std::vector<Cursor> places;
    for (const Cursor& c : candidates) {
        const std::vector<std::string> order = step_order(trace, c);
        if (!cells_of(item_at(document, c), order[static_cast<std::size_t>(c.step)]).empty()) places.push_back(c);
    }
    return places;
}

std::string scalar_text(const formats::json& value) {
    if (value.is_null()) return "";
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_float()) return formats::number_text(value.get<double>());
    return value.dump();
}

Worksheet make_worksheet(const model::Session& session, const std::vector<Cursor>& places,
                         const formats::json* given_document) {
    const Trace& trace = session.trace();
    const formats::json made = given_document ? formats::json() : formats::trace_json(trace);
    const formats::json& document = given_document ? *given_document : made;
    Worksheet sheet;
    sheet.source = session.path();
    sheet.conventions = document["conventions"];
    sheet.settings = document["settings"];
    const bool resolved = session.kind() == model::SourceKind::case_file ||
                          (session.kind() == model::SourceKind::trace_file && !trace.scene.contacts.empty());
    formats::json run = {{"mode", resolved ? "resolve" : "simulate"}};
    if (!resolved) run["frames"] = trace.scene.world.frames;  // a run's header says how many frames it ran
    sheet.reference = {{"run", run}, {"recording", document["recording"]}, {"scene", document["scene"]}};

    std::vector<Cursor> seen;
    for (const Cursor& c : places) {
        if (std::find(seen.begin(), seen.end(), c) != seen.end()) continue;
        seen.push_back(c);
        const std::vector<std::string> order = step_order(trace, c);
        const std::string& step = order[static_cast<std::size_t>(c.step)];
        const ItemAt item = item_at(document, c);
        WorksheetStep s{model::describe(trace, c), at_spec(trace, c, step), {}, cells_of(item, step)};
        if (s.cells.empty())
            throw formats::InputError("--steps", s.at + ": the step computes nothing to fill in (steps that do here: " +
                                                     joined(steps_with_cells(document, trace, c)) + ")");
        s.inputs = inputs_of(item, order, static_cast<std::size_t>(c.step), document, resolved);
        sheet.steps.push_back(std::move(s));
    }

    // A value asked for anywhere on the sheet is not given away as another step's input; each input once per step.
    std::set<std::string> asked;
    for (const WorksheetStep& s : sheet.steps)
        for (const WorksheetEntry& cell : s.cells) asked.insert(cell.path);
    for (WorksheetStep& s : sheet.steps) {
        std::set<std::string> listed;
        std::erase_if(s.inputs,
                      [&](const WorksheetEntry& e) { return asked.count(e.path) || !listed.insert(e.path).second; });
        for (WorksheetEntry& e : s.inputs) e.value = rounded_for_hand_work(e.value);
    }
    return sheet;
}

std::vector<Cursor> default_places(const Trace& trace, const formats::json* given_document) {
    std::vector<Cursor> places;
    const std::optional<Cursor> first = model::first_cursor(trace);
    if (!first) return places;
    const formats::json made = given_document ? formats::json() : formats::trace_json(trace);
    const formats::json& document = given_document ? *given_document : made;
    for (std::optional<Cursor> c = first; c && c->frame == first->frame; c = model::next_step(trace, *c)) {
        const std::vector<std::string> order = step_order(trace, *c);
        if (!cells_of(item_at(document, *c), order[static_cast<std::size_t>(c->step)]).empty()) places.push_back(*c);
    }
    return places;
}

std::vector<Cursor> places_from_specs(const Trace& trace, const std::vector<std::string>& specs, std::string_view where,
                                      const formats::json* given_document) {
    std::vector<Cursor> places;
    const formats::json made = given_document ? formats::json() : formats::trace_json(trace);
    const formats::json& document = given_document ? *given_document : made;
    for (const std::string& text : specs) {
        const model::GotoSpec spec = model::parse_goto(text, where);
        const Cursor c = model::resolve_goto(trace, spec, where);
        const std::vector<std::string> order = step_order(trace, c);
        const std::vector<std::string> filled = steps_with_cells(document, trace, c);
        if (spec.step) {
            const std::string& step = order[static_cast<std::size_t>(c.step)];
            if (std::find(filled.begin(), filled.end(), step) == filled.end())
                throw formats::InputError(std::string(where), "\"" + text + "\": step " + step +
                                                                  " computes nothing to fill in (steps that do here: " +
                                                                  joined(filled) + ")");
            places.push_back(c);
            continue;
        }
        if (filled.empty())
            throw formats::InputError(std::string(where),
                                      "\"" + text + "\": " + model::describe(trace, c) + " has nothing to fill in");
        for (std::size_t s = 0; s < order.size(); ++s)
            if (std::find(filled.begin(), filled.end(), order[s]) != filled.end())
                places.push_back(Cursor{c.frame, c.stage, c.item, static_cast<int>(s)});
    }
    return places;
}

Trace rerun_reference(const formats::json& document) {
    course::validate_worksheet_document(document);
    for (const char* key : {"settings", "reference"})
        if (!document.contains(key))
            throw formats::InputError(key, "missing: the worksheet does not say what it was made from");
    const formats::json& reference = document["reference"];
    Scene scene;
    try {
        scene = formats::read_scene(reference["scene"]);
    } catch (const formats::InputError& e) {
        throw formats::InputError(e.where().empty() ? "reference.scene" : "reference.scene." + e.where(), e.problem());
    }
    formats::read_settings(scene, &document["settings"], "settings");
    const formats::json& r = reference["recording"];
    TraceFilter recording;
    recording.first_frame = r["first_frame"].get<int>();
    recording.last_frame = r["last_frame"].is_null() ? INT_MAX : r["last_frame"].get<int>();
    if (!r["contacts"].is_null()) recording.contacts = r["contacts"].get<std::vector<int>>();
    const formats::json& run = reference["run"];
    std::optional<model::BrokenRun> broken;
    Trace trace;
    if (run["mode"] == "resolve") {
        trace = model::resolve_once(scene, recording, {}, &broken);
    } else {
        if (!run.contains("frames"))
            throw formats::InputError("reference.run.frames",
                                      "missing: a simulated reference needs its number of frames");
        trace = model::run_frames(scene, recording, run["frames"].get<int>(), {}, &broken);
    }
    // `worksheet` never writes one from a broken run, so this reference was not made by it.
    if (broken)
        throw formats::InputError("reference.run", "re-running it stops at " + model::broken_run_text(scene, *broken));
    return trace;
}

formats::json worksheet_json(const Worksheet& sheet) {
    formats::json steps = formats::json::array();
    for (const WorksheetStep& s : sheet.steps) {
        formats::json inputs = formats::json::array(), cells = formats::json::array();
        for (const WorksheetEntry& e : s.inputs) inputs.push_back(entry_json(e, false));
        for (const WorksheetEntry& e : s.cells) cells.push_back(entry_json(e, true));
        steps.push_back({{"place", s.place}, {"at", s.at}, {"inputs", inputs}, {"cells", cells}});
    }
    return {{"format", worksheet_format_name},
            {"version", worksheet_format_version},
            {"source", sheet.source},
            {"conventions", sheet.conventions},
            {"settings", sheet.settings},
            {"reference", sheet.reference},
            {"steps", steps}};
}

namespace {

std::size_t numbers_in(const formats::json& value) {
    std::size_t n = 0;
    for_each_scalar(value, "", [&n](const std::string&, const formats::json&) { ++n; });
    return n;
}

}  // namespace

WorksheetCounts json_counts(const Worksheet& sheet) {
    WorksheetCounts counts;
    for (const WorksheetStep& s : sheet.steps) {
        counts.cells += s.cells.size();
        counts.inputs += s.inputs.size();
        for (const WorksheetEntry& e : s.cells) counts.numbers += numbers_in(e.value);
    }
    return counts;
}

WorksheetCounts csv_counts(const Worksheet& sheet) {
    WorksheetCounts counts;
    std::set<std::string> shown;  // as worksheet_csv writes them: an input once, before the first step using it
    for (const WorksheetStep& s : sheet.steps) {
        for (const WorksheetEntry& e : s.inputs)
            if (shown.insert(e.path).second) counts.inputs += numbers_in(e.value);
        counts.cells += s.cells.size();
        for (const WorksheetEntry& e : s.cells) counts.numbers += numbers_in(e.value);
    }
    return counts;
}

std::string worksheet_csv(const Worksheet& sheet) {
    std::string text = std::string(worksheet_csv_header) + "\n";
    std::set<std::string> shown;
    const auto rows = [&text](const char* kind, const WorksheetEntry& e, bool blank) {
        for_each_scalar(e.value, e.path, [&](const std::string& path, const formats::json& v) {
            const std::string quantity = e.quantity + path.substr(e.path.size());
            const std::string value = blank ? "" : v.is_null() ? "null" : scalar_text(v);
            text += formats::csv_row({kind, path, e.step, quantity, value, e.unit, e.formula, e.equation, e.meaning});
        });
    };
    for (const WorksheetStep& s : sheet.steps) {
        for (const WorksheetEntry& e : s.inputs)
            if (shown.insert(e.path).second) rows("input", e, false);
        for (const WorksheetEntry& e : s.cells) rows("cell", e, true);
    }
    return text;
}

}  // namespace impulse::course
