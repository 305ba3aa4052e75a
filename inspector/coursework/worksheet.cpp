#include "coursework/worksheet.hpp"

#include "explain/csv.hpp"
#include "coursework/step_keys.hpp"
#include "io/input_error.hpp"
#include "io/scene_file.hpp"
#include "io/schemas.hpp"
#include "io/settings_json.hpp"
#include "io/trace_json.hpp"
#include "model/runs.hpp"

#include <algorithm>
#include <set>

namespace impulse::coursework {

namespace {

using inspect::Cursor;
using inspect::Stage;

// The item a cursor stands on, in the trace document.
struct ItemAt {
    ItemKind kind;
    std::string path;  // frames[f].contacts[k] or frames[f].phases[p].iterations[i]
    const io::json* object;
    std::string frame_path;  // frames[f]
    const io::json* frame;
};

ItemAt item_at(const io::json& document, const Cursor& c) {
    const std::string frame_path = io::json_path_index("frames", static_cast<std::size_t>(c.frame));
    const io::json& frame = document["frames"][static_cast<std::size_t>(c.frame)];
    const auto item = static_cast<std::size_t>(c.item);
    if (c.stage == Stage::preparation)
        return {ItemKind::contact, io::json_path_index(io::json_path_child(frame_path, "contacts"), item),
                &frame["contacts"][item], frame_path, &frame};
    const std::string_view phase = inspect::stage_name(c.stage);
    std::size_t p = 0;
    while (p + 1 < frame["phases"].size() && frame["phases"][p]["phase"] != phase) ++p;
    const std::string phase_path = io::json_path_index(io::json_path_child(frame_path, "phases"), p);
    return {c.stage == Stage::position ? ItemKind::position_iteration : ItemKind::velocity_iteration,
            io::json_path_index(io::json_path_child(phase_path, "iterations"), item),
            &frame["phases"][p]["iterations"][item], frame_path, &frame};
}

WorksheetEntry entry(std::string path, std::string step, std::string quantity, const Described& d, io::json value) {
    return {std::move(path), std::move(step), std::move(quantity), d.unit,
            d.formula,       d.equation,      d.meaning,           std::move(value)};
}

// The entries `key` makes in `object` (at `path`, named `quantity` so far): one per value present, one per body
// present for a per-body key, one per element of an array of objects ("updates[].after").
void expand(const io::json& object, const std::string& path, const std::string& quantity, std::string_view key,
            bool per_body, const Described& d, const std::string& step, std::vector<WorksheetEntry>& out) {
    const std::size_t dot = key.find('.');
    const std::string_view head = key.substr(0, dot);
    const bool each_element = head.ends_with("[]");
    const std::string name(each_element ? head.substr(0, head.size() - 2) : head);
    if (!object.is_object() || !object.contains(name)) return;
    const io::json& value = object[name];
    const std::string at = io::json_path_child(path, name);
    const std::string called = quantity.empty() ? name : quantity + "." + name;
    if (each_element) {
        for (std::size_t i = 0; i < value.size(); ++i)
            expand(value[i], io::json_path_index(at, i), called + "[" + std::to_string(i) + "]", key.substr(dot + 1),
                   per_body, d, step, out);
    } else if (dot != std::string_view::npos) {
        expand(value, at, called, key.substr(dot + 1), per_body, d, step, out);
    } else if (per_body) {
        for (std::size_t b = 0; b < value.size(); ++b)
            if (!value[b].is_null())
                out.push_back(
                    entry(io::json_path_index(at, b), step, called + "[" + std::to_string(b) + "]", d, value[b]));
    } else if (!value.is_null()) {
        out.push_back(entry(at, step, called, d, value));
    }
}

void expand_key(const ItemAt& item, const StepKey& key, const std::string& step, std::vector<WorksheetEntry>& out) {
    expand(*item.object, item.path, "", key.key, key.per_body, describe_key(key), step, out);
}

// The step names of the cursor's item, in the order its tables show them.
std::vector<std::string> step_order(const Trace& trace, const Cursor& c) {
    std::vector<std::string> names;
    for (const explain::StepTable& t : inspect::step_tables(trace, c)) names.push_back(t.step);
    return names;
}

std::vector<WorksheetEntry> cells_of(const ItemAt& item, const std::string& step) {
    std::vector<WorksheetEntry> cells;
    for (const StepKey& key : step_keys())
        if (key.item == item.kind && key.role == Role::computed && key.step == step) expand_key(item, key, step, cells);
    return cells;
}

// The chosen (or this) contact's preparation in the frame's document, or null when it was not recorded.
const io::json* prepared_contact(const ItemAt& item, std::string* path) {
    const io::json& contacts = (*item.frame)["contacts"];
    if (item.kind == ItemKind::contact) {
        *path = item.path;
        return item.object;
    }
    const io::json& chosen = (*item.object)["contact"];
    for (std::size_t k = 0; k < contacts.size(); ++k)
        if (contacts[k]["contact"] == chosen) {
            *path = io::json_path_index(io::json_path_child(item.frame_path, "contacts"), k);
            return &contacts[k];
        }
    return nullptr;
}

std::vector<WorksheetEntry> inputs_of(const ItemAt& item, const std::vector<std::string>& order, std::size_t here,
                                      const io::json& document) {
    std::vector<WorksheetEntry> inputs;
    const std::string given = "given";
    for (const StepKey& key : step_keys())
        if (key.item == item.kind && key.role == Role::given && key.step.empty()) expand_key(item, key, given, inputs);

    // What the item's bodies and (for an iteration) its chosen contact bring in.
    std::string contact_path;
    if (const io::json* contact = prepared_contact(item, &contact_path)) {
        for (const OutsideKey& key : outside_keys()) {
            const bool wanted = item.kind == ItemKind::contact              ? key.for_contact
                                : item.kind == ItemKind::position_iteration ? key.for_position_iteration
                                                                            : key.for_velocity_iteration;
            if (!wanted) continue;
            const Described d = describe_outside(key);
            if (key.where == "contact") {
                const StepKey* k = find_step_key(ItemKind::contact, key.key);
                expand(*contact, contact_path, contact_path.substr(item.frame_path.size() + 1), key.key,
                       k && k->per_body, d, given, inputs);
                continue;
            }
            for (const io::json& body : (*contact)["bodies"]) {
                if (body.is_null()) continue;
                const auto b = body.get<std::size_t>();
                if (key.where == "scene_bodies") {
                    const std::string at = io::json_path_index("scene.bodies", b);
                    expand(document["scene"]["bodies"][b], at, at, key.key, false, d, given, inputs);
                } else {
                    const std::string name = io::json_path_index("bodies_before", b);
                    expand((*item.frame)["bodies_before"][b], io::json_path_child(item.frame_path, name), name, key.key,
                           false, d, given, inputs);
                }
            }
        }
    }

    // The settings of the steps up to this one and the values of the steps before it.
    for (std::size_t s = 0; s <= here && s < order.size(); ++s)
        for (const StepKey& key : step_keys()) {
            if (key.item != item.kind || key.step != order[s]) continue;
            if (key.role == Role::setting || key.role == Role::given) expand_key(item, key, given, inputs);
            if (key.role == Role::computed && s < here) expand_key(item, key, order[s], inputs);
        }
    return inputs;
}

std::string at_spec(const Trace& trace, const Cursor& c, const std::string& step) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(c.frame)];
    std::string spec = "frame=" + std::to_string(frame.frame) + ",phase=" + std::string(inspect::stage_name(c.stage));
    if (c.stage == Stage::preparation)
        spec += ",contact=" + std::to_string(inspect::contact_at(trace, c));
    else
        spec += ",iteration=" + std::to_string(c.item);
    return spec + ",step=" + step;
}

io::json blanked(const io::json& value) {
    if (!value.is_array()) return nullptr;
    io::json out = io::json::array();
    for (const io::json& v : value) out.push_back(blanked(v));
    return out;
}

io::json entry_json(const WorksheetEntry& e, bool blank) {
    return {{"path", e.path},         {"step", e.step},
            {"quantity", e.quantity}, {"unit", e.unit},
            {"formula", e.formula},   {"equation", e.equation},
            {"meaning", e.meaning},   {"value", blank ? blanked(e.value) : e.value}};
}

// Whether a cursor's step has anything to fill in, and the names of the item's steps that have.
std::vector<std::string> steps_with_cells(const io::json& document, const Trace& trace, const Cursor& c) {
    const ItemAt item = item_at(document, c);
    std::vector<std::string> names;
    for (const std::string& name : step_order(trace, c))
        if (!cells_of(item, name).empty()) names.push_back(name);
    return names;
}

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
    return text.empty() ? "none" : text;
}

}  // namespace

std::string scalar_text(const io::json& value) {
    if (value.is_null()) return "";
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_float()) return io::number_text(value.get<double>());
    return value.dump();
}

Worksheet make_worksheet(const inspect::Session& session, const std::vector<Cursor>& places) {
    const Trace& trace = session.trace();
    const io::json document = io::trace_json(trace);
    Worksheet sheet;
    sheet.source = session.path();
    sheet.conventions = document["conventions"];
    sheet.settings = document["settings"];
    const bool resolved = session.kind() == inspect::SourceKind::case_file ||
                          (session.kind() == inspect::SourceKind::trace_file && !trace.scene.contacts.empty());
    io::json run = {{"mode", resolved ? "resolve" : "simulate"}};
    if (!resolved) run["frames"] = trace.scene.world.frames;  // a run's header says how many frames it ran
    sheet.reference = {{"run", run}, {"recording", document["recording"]}, {"scene", document["scene"]}};

    std::vector<Cursor> seen;
    for (const Cursor& c : places) {
        if (std::find(seen.begin(), seen.end(), c) != seen.end()) continue;
        seen.push_back(c);
        const std::vector<std::string> order = step_order(trace, c);
        const std::string& step = order[static_cast<std::size_t>(c.step)];
        const ItemAt item = item_at(document, c);
        WorksheetStep s{inspect::describe(trace, c), at_spec(trace, c, step), {}, cells_of(item, step)};
        if (s.cells.empty())
            throw io::InputError("--steps", s.at + ": the step computes nothing to fill in (steps that do here: " +
                                                joined(steps_with_cells(document, trace, c)) + ")");
        s.inputs = inputs_of(item, order, static_cast<std::size_t>(c.step), document);
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
    }
    return sheet;
}

std::vector<Cursor> default_places(const Trace& trace) {
    std::vector<Cursor> places;
    const std::optional<Cursor> first = inspect::first_cursor(trace);
    if (!first) return places;
    const io::json document = io::trace_json(trace);
    for (std::optional<Cursor> c = first; c && c->frame == first->frame; c = inspect::next_step(trace, *c)) {
        const std::vector<std::string> order = step_order(trace, *c);
        if (!cells_of(item_at(document, *c), order[static_cast<std::size_t>(c->step)]).empty()) places.push_back(*c);
    }
    return places;
}

std::vector<Cursor> places_from_specs(const Trace& trace, const std::vector<std::string>& specs,
                                      std::string_view where) {
    std::vector<Cursor> places;
    const io::json document = io::trace_json(trace);
    for (const std::string& text : specs) {
        const inspect::GotoSpec spec = inspect::parse_goto(text, where);
        const Cursor c = inspect::resolve_goto(trace, spec, where);
        const std::vector<std::string> order = step_order(trace, c);
        const std::vector<std::string> filled = steps_with_cells(document, trace, c);
        if (spec.step) {
            const std::string& step = order[static_cast<std::size_t>(c.step)];
            if (std::find(filled.begin(), filled.end(), step) == filled.end())
                throw io::InputError(std::string(where),
                                     "\"" + text + "\": step " + step +
                                         " computes nothing to fill in (steps that do here: " + joined(filled) + ")");
            places.push_back(c);
            continue;
        }
        if (filled.empty())
            throw io::InputError(std::string(where),
                                 "\"" + text + "\": " + inspect::describe(trace, c) + " has nothing to fill in");
        for (std::size_t s = 0; s < order.size(); ++s)
            if (std::find(filled.begin(), filled.end(), order[s]) != filled.end())
                places.push_back(Cursor{c.frame, c.stage, c.item, static_cast<int>(s)});
    }
    return places;
}

Trace rerun_reference(const io::json& document) {
    io::validate_worksheet_document(document);
    for (const char* key : {"settings", "reference"})
        if (!document.contains(key))
            throw io::InputError(key, "missing: the worksheet does not say what it was made from");
    const io::json& reference = document["reference"];
    Scene scene;
    try {
        scene = io::read_scene(reference["scene"]);
    } catch (const io::InputError& e) {
        throw io::InputError(e.where().empty() ? "reference.scene" : "reference.scene." + e.where(), e.problem());
    }
    io::read_settings(scene, &document["settings"], "settings");
    const io::json& r = reference["recording"];
    TraceFilter recording;
    recording.first_frame = r["first_frame"].get<int>();
    recording.last_frame = r["last_frame"].is_null() ? INT_MAX : r["last_frame"].get<int>();
    if (!r["contacts"].is_null()) recording.contacts = r["contacts"].get<std::vector<int>>();
    const io::json& run = reference["run"];
    std::optional<inspect::BrokenRun> broken;
    Trace trace;
    if (run["mode"] == "resolve") {
        trace = inspect::resolve_once(scene, recording, {}, &broken);
    } else {
        if (!run.contains("frames"))
            throw io::InputError("reference.run.frames", "missing: a simulated reference needs its number of frames");
        trace = inspect::run_frames(scene, recording, run["frames"].get<int>(), {}, &broken);
    }
    // `worksheet` never writes one from a broken run, so this reference was not made by it.
    if (broken)
        throw io::InputError("reference.run", "re-running it stops at " + inspect::broken_run_text(scene, *broken));
    return trace;
}

io::json worksheet_json(const Worksheet& sheet) {
    io::json steps = io::json::array();
    for (const WorksheetStep& s : sheet.steps) {
        io::json inputs = io::json::array(), cells = io::json::array();
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

std::string worksheet_csv(const Worksheet& sheet) {
    std::string text = std::string(worksheet_csv_header) + "\n";
    std::set<std::string> shown;
    const auto rows = [&text](const char* kind, const WorksheetEntry& e, bool blank) {
        for_each_scalar(e.value, e.path, [&](const std::string& path, const io::json& v) {
            const std::string quantity = e.quantity + path.substr(e.path.size());
            const std::string value = blank ? "" : v.is_null() ? "null" : scalar_text(v);
            text += explain::csv_row({kind, path, e.step, quantity, value, e.unit, e.formula, e.equation, e.meaning});
        });
    };
    for (const WorksheetStep& s : sheet.steps) {
        for (const WorksheetEntry& e : s.inputs)
            if (shown.insert(e.path).second) rows("input", e, false);
        for (const WorksheetEntry& e : s.cells) rows("cell", e, true);
    }
    return text;
}

}  // namespace impulse::coursework
