#include "course/diff.hpp"

#include "course/step_keys.hpp"
#include "course/trace_items.hpp"
#include "course/worksheet.hpp"
#include "formats/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace impulse::course {

namespace {

// Arrays whose elements carry their own number: paired by it, not by position.
std::string_view identity_key(std::string_view array_name) {
    if (array_name == "frames") return "frame";
    if (array_name == "contacts") return "contact";
    if (array_name == "phases") return "phase";
    if (array_name == "iterations") return "iteration";
    return {};
}

// Each element's identity, when every element is an object carrying a distinct one.
std::optional<std::vector<formats::json>> identities(const formats::json& array, std::string_view key) {
    if (key.empty()) return std::nullopt;
    std::vector<formats::json> ids;
    for (const formats::json& element : array) {
        if (!element.is_object() || !element.contains(key)) return std::nullopt;
        const formats::json& id = element[std::string(key)];
        if (std::find(ids.begin(), ids.end(), id) != ids.end()) return std::nullopt;
        ids.push_back(id);
    }
    return ids;
}

class Comparison {
public:
    Comparison(const formats::json& reference, const Tolerance& tolerance, bool blank_allowed)
        : reference_(reference), tolerance_(tolerance), blank_allowed_(blank_allowed), grading_(blank_allowed) {}

    // `area` is the kind a differing value is reported as; `name` the key that holds `expected`.
    void compare(const formats::json& expected, const formats::json& found, const std::string& path, FindingKind area,
                 std::string_view name) {
        if (expected.is_object() && found.is_object()) {
            for (auto it = expected.begin(); it != expected.end(); ++it) {
                const std::string child = formats::json_path_child(path, it.key());
                const auto there = found.find(it.key());
                if (there == found.end())
                    add(FindingKind::missing, child, it.value(), nullptr);
                else
                    compare(it.value(), *there, child, area, it.key());
            }
            for (auto it = found.begin(); it != found.end(); ++it)
                if (!expected.contains(it.key()))
                    add(FindingKind::extra, formats::json_path_child(path, it.key()), nullptr, it.value());
            return;
        }
        if (expected.is_array() && found.is_array()) {
            compare_arrays(expected, found, path, area, name);
            return;
        }
        if (blank_allowed_ && found.is_null() && !expected.is_null()) {
            for_each_scalar(expected, path,
                            [this](const std::string& at, const formats::json& value) { blank(at, value); });
            return;
        }
        if (expected.is_number() && found.is_number()) {
            const double a = expected.get<double>(), b = found.get<double>();
            const double difference = std::abs(a - b);
            const double relative = a == 0.0 ? difference : difference / std::abs(a);
            if (difference <= tolerance_.atol + tolerance_.rtol * std::abs(a)) {
                matched();
                grade(path, expected, found, relative, Verdict::right);
                return;
            }
            add(area, path, expected, found).relative_error = relative;
            grade(path, expected, found, relative, Verdict::wrong);
            return;
        }
        if (expected == found && !expected.is_structured()) {
            matched();
            grade(path, expected, found, std::nullopt, Verdict::right);
            return;
        }
        add(area, path, expected, found);
        grade(path, expected, found, std::nullopt, Verdict::wrong);
    }

    // A number of an asked cell left blank (or left out of the file).
    void blank(const std::string& path, const formats::json& expected) {
        add(FindingKind::blank, path, expected, nullptr);
        ++report_.blank;
        grade(path, expected, nullptr, std::nullopt, Verdict::blank);
    }

    // Records each number of the cells as graded (worksheets only, not the header they were made with).
    void grade(const std::string& path, const formats::json& expected, const formats::json& found,
               std::optional<double> relative_error, Verdict verdict) {
        if (grading_) report_.graded.push_back({path, expected, found, relative_error, verdict, "", "", ""});
    }

    Finding& add(FindingKind kind, const std::string& path, const formats::json& expected, const formats::json& found) {
        Finding f;
        f.kind = kind;
        f.path = path;
        f.expected = expected;
        f.found = found;
        if (kind != FindingKind::blank) ++report_.mismatched;
        try {
            const Described d = describe_path(reference_, parse_json_path(path, ""));
            f.quantity = d.quantity;
            f.formula = d.formula;
            f.equation = d.equation;
        } catch (const formats::InputError&) {
            // A scene's material names are keys of any text: such a path has no vocabulary name anyway.
        }
        report_.findings.push_back(std::move(f));
        return report_.findings.back();
    }

    void count_matches(bool on) { counting_ = grading_ = on; }
    DiffReport& report() { return report_; }

private:
    void matched() {
        if (counting_) ++report_.matched;
    }

    void compare_arrays(const formats::json& expected, const formats::json& found, const std::string& path,
                        FindingKind area, std::string_view name) {
        const std::string_view key = identity_key(name);
        const auto expected_ids = identities(expected, key), found_ids = identities(found, key);
        if (expected_ids && found_ids) {
            std::vector<bool> paired(found.size(), false);
            for (std::size_t i = 0; i < expected.size(); ++i) {
                const auto there = std::find(found_ids->begin(), found_ids->end(), (*expected_ids)[i]);
                const std::string at = formats::json_path_index(path, i);
                if (there == found_ids->end()) {
                    add(FindingKind::missing, at, expected[i], nullptr);
                    continue;
                }
                const auto j = static_cast<std::size_t>(there - found_ids->begin());
                paired[j] = true;
                compare(expected[i], found[j], at, area, name);
            }
            for (std::size_t j = 0; j < found.size(); ++j)
                if (!paired[j]) add(FindingKind::extra, formats::json_path_index(path, j), nullptr, found[j]);
            return;
        }
        for (std::size_t i = 0; i < std::max(expected.size(), found.size()); ++i) {
            const std::string at = formats::json_path_index(path, i);
            if (i >= found.size())
                add(FindingKind::missing, at, expected[i], nullptr);
            else if (i >= expected.size())
                add(FindingKind::extra, at, nullptr, found[i]);
            else
                compare(expected[i], found[i], at, area, name);
        }
    }

    const formats::json& reference_;
    Tolerance tolerance_;
    bool blank_allowed_;
    bool counting_ = true;
    bool grading_;
    DiffReport report_;
};

FindingKind area_of(std::string_view top_key) {
    if (top_key == "settings") return FindingKind::setting;
    if (top_key == "scene") return FindingKind::scene;
    return FindingKind::value;
}

// The first value that differs from the reference's: a blank, a repeat or a cell not asked for diverges from
// nothing.
void mark_first_divergence(DiffReport& report) {
    for (Finding& f : report.findings)
        if (f.kind != FindingKind::blank && f.kind != FindingKind::duplicate && f.kind != FindingKind::not_asked &&
            f.kind != FindingKind::empty) {
            f.first_divergence = true;
            return;
        }
}

// Where a path comes in the order the derivation computes: by where it is in the reference document, except
// that inside an item (a prepared contact, an iteration) its key is placed by the step table (step_keys), which
// lists them in the derivation's order — an iteration's record writes its desired velocity change before the
// contact velocity it comes from — and then by its indices (the update, the body, the component), as the
// worksheet lists its cells.
std::vector<std::size_t> derivation_position(const formats::json& reference, const std::vector<PathToken>& path) {
    std::size_t rest = 0;
    ItemKind kind = ItemKind::contact;
    if (key_at(path, 0, "frames") && index_at(path, 1) && key_at(path, 2, "contacts") && index_at(path, 3)) {
        rest = 4;
    } else if (key_at(path, 0, "frames") && index_at(path, 1) && key_at(path, 2, "phases") && index_at(path, 3) &&
               key_at(path, 4, "iterations") && index_at(path, 5)) {
        const formats::json* phase = value_at(reference, {path.begin(), path.begin() + 4});
        kind = phase && phase->is_object() && phase->value("phase", "") == "position" ? ItemKind::position_iteration
                                                                                      : ItemKind::velocity_iteration;
        rest = 6;
    }
    std::vector<std::size_t> position = document_position(reference, path);
    if (rest == 0 || rest >= path.size()) return position;
    std::string key;
    std::vector<std::size_t> indices;
    for (std::size_t i = rest; i < path.size(); ++i) {
        if (const auto* k = std::get_if<std::string>(&path[i])) {
            key += (key.empty() ? "" : ".") + *k;
        } else {
            indices.push_back(std::get<std::size_t>(path[i]));
            if (key == "updates" || key == "gathered" || key.ends_with(".features")) key += "[]";
        }
    }
    const StepKey* step_key = find_step_key(kind, key);
    if (!step_key) return position;
    position.resize(rest);
    position.push_back(static_cast<std::size_t>(step_key - step_keys().data()));
    position.insert(position.end(), indices.begin(), indices.end());
    return position;
}

// Into the derivation's order (stable for equal places).
template <typename Item>
void sort_into_trace_order(const formats::json& reference, std::vector<Item>& items) {
    std::vector<std::pair<std::vector<std::size_t>, std::size_t>> order;
    for (std::size_t i = 0; i < items.size(); ++i) {
        std::vector<std::size_t> position;
        try {
            position = derivation_position(reference, parse_json_path(items[i].path, ""));
        } catch (const formats::InputError&) {
            position = {SIZE_MAX};
        }
        order.emplace_back(std::move(position), i);
    }
    std::stable_sort(order.begin(), order.end());
    std::vector<Item> sorted;
    for (const auto& [position, i] : order) sorted.push_back(std::move(items[i]));
    items = std::move(sorted);
}

// One number a worksheet gives: a cell's value, or one component of it.
struct GivenNumber {
    std::string path;     // its own: "frames[0].phases[1].iterations[0].impulse_world[1]"
    formats::json value;  // null: blank
    FindingKind area;     // what a difference in it is reported as
    std::string name;     // the key that holds it
};

// The numbers of `cell` at the paths of `expected`'s: a blank vector is blank in each component, a vector given
// is read component by component (so a component given twice, or one too many, is seen as such).
void append_numbers(const FilledCell& cell, const formats::json& expected, std::vector<GivenNumber>& out) {
    const auto* top = std::get_if<std::string>(&cell.tokens.front());
    const auto* last = std::get_if<std::string>(&cell.tokens.back());
    const FindingKind area = area_of(top ? *top : "");
    const std::string name = last ? *last : "";
    const formats::json& shape = cell.value.is_null() ? expected : cell.value;
    for_each_scalar(shape, cell.path, [&](const std::string& at, const formats::json& value) {
        out.push_back({at, cell.value.is_null() ? formats::json(nullptr) : value, area, name});
    });
}

// Every number of the values at `paths` in the reference, by its own path.
std::map<std::string, formats::json> numbers_of(const formats::json& reference, const std::vector<std::string>& paths) {
    std::map<std::string, formats::json> numbers;
    for (const std::string& path : paths)
        if (const formats::json* expected = value_at(reference, parse_json_path(path, "")))
            for_each_scalar(*expected, path, [&numbers](const std::string& at, const formats::json& value) {
                numbers.emplace(at, value);
            });
    return numbers;
}

// The item (a prepared contact or an iteration) a path into a trace document lies in, and where its key starts.
std::optional<std::pair<ItemAt, std::size_t>> item_of(const formats::json& reference,
                                                      const std::vector<PathToken>& path) {
    if (!key_at(path, 0, "frames") || !index_at(path, 1)) return std::nullopt;
    const formats::json* frame = value_at(reference, {path.begin(), path.begin() + 2});
    if (!frame) return std::nullopt;
    const std::string frame_path = formats::json_path_index("frames", *index_at(path, 1));
    if (key_at(path, 2, "contacts") && index_at(path, 3)) {
        const formats::json* contact = value_at(reference, {path.begin(), path.begin() + 4});
        if (!contact) return std::nullopt;
        return std::pair{
            ItemAt{ItemKind::contact,
                   formats::json_path_index(formats::json_path_child(frame_path, "contacts"), *index_at(path, 3)),
                   contact, frame_path, frame},
            std::size_t{4}};
    }
    if (key_at(path, 2, "phases") && index_at(path, 3) && key_at(path, 4, "iterations") && index_at(path, 5)) {
        const formats::json* phase = value_at(reference, {path.begin(), path.begin() + 4});
        const formats::json* iteration = value_at(reference, {path.begin(), path.begin() + 6});
        if (!phase || !iteration || !phase->is_object()) return std::nullopt;
        const std::string phase_path =
            formats::json_path_index(formats::json_path_child(frame_path, "phases"), *index_at(path, 3));
        return std::pair{
            ItemAt{
                phase->value("phase", "") == "position" ? ItemKind::position_iteration : ItemKind::velocity_iteration,
                formats::json_path_index(formats::json_path_child(phase_path, "iterations"), *index_at(path, 5)),
                iteration, frame_path, frame, *index_at(path, 3)},
            std::size_t{6}};
    }
    return std::nullopt;
}

// The cells, as `worksheet` makes them, of every step the sheet answers a cell of: the places a sheet made from a
// case, a scene or a trace is graded at when the reference does not say which cells it handed out.
std::vector<std::string> cells_of_answered_steps(const formats::json& reference, const FilledWorksheet& sheet) {
    std::set<std::pair<std::string, std::string>> steps;  // (item path, step)
    std::vector<std::string> paths;
    for (const FilledCell& cell : sheet.cells) {
        const auto item = item_of(reference, cell.tokens);
        if (!item) continue;
        const StepKey* key = find_step_key(item->first.kind, step_key_of(cell.tokens, item->second));
        if (!key || key->role != Role::computed) continue;
        if (!steps.emplace(item->first.path, std::string(key->step)).second) continue;
        std::vector<WorksheetEntry> cells;
        for (const StepKey& k : step_keys())
            if (k.item == item->first.kind && k.role == Role::computed && k.step == key->step)
                expand_key(item->first, k, std::string(k.step), cells);
        for (const WorksheetEntry& e : cells) paths.push_back(e.path);
    }
    return paths;
}

}  // namespace

std::string_view finding_kind_name(FindingKind kind) {
    switch (kind) {
        case FindingKind::value:
            return "value";
        case FindingKind::setting:
            return "setting";
        case FindingKind::scene:
            return "scene";
        case FindingKind::missing:
            return "missing";
        case FindingKind::extra:
            return "extra";
        case FindingKind::blank:
            return "blank";
        case FindingKind::not_in_reference:
            return "not_in_reference";
        case FindingKind::duplicate:
            return "duplicate";
        case FindingKind::not_asked:
            return "not_asked";
        case FindingKind::empty:
            return "empty";
    }
    return "";
}

const Finding* DiffReport::first_divergence() const {
    for (const Finding& f : findings)
        if (f.first_divergence) return &f;
    return nullptr;
}

DiffReport diff_traces(const formats::json& reference, const formats::json& other, const Tolerance& tolerance) {
    Comparison comparison(reference, tolerance, false);
    for (auto it = reference.begin(); it != reference.end(); ++it) {
        const auto there = other.find(it.key());
        if (there == other.end())
            comparison.add(FindingKind::missing, it.key(), it.value(), nullptr);
        else
            comparison.compare(it.value(), *there, it.key(), area_of(it.key()), it.key());
    }
    for (auto it = other.begin(); it != other.end(); ++it)
        if (!reference.contains(it.key())) comparison.add(FindingKind::extra, it.key(), nullptr, it.value());
    DiffReport report = std::move(comparison.report());
    report.other_kind = "trace";
    mark_first_divergence(report);
    return report;
}

DiffReport diff_worksheet(const formats::json& reference, const FilledWorksheet& sheet, const Tolerance& tolerance,
                          const std::vector<std::string>* asked) {
    Comparison comparison(reference, tolerance, true);
    // The numbers the sheet gives, each at its own path ("…impulse_world[1]"), in the sheet's order.
    std::vector<GivenNumber> given;
    for (const FilledCell& cell : sheet.cells) {
        const formats::json* expected = value_at(reference, cell.tokens);
        if (!expected) {
            comparison.add(FindingKind::not_in_reference, cell.path, nullptr, cell.value);
            for_each_scalar(cell.value, cell.path, [&comparison](const std::string& at, const formats::json& value) {
                comparison.grade(at, nullptr, value, std::nullopt, Verdict::wrong);
            });
            continue;
        }
        append_numbers(cell, *expected, given);
    }
    // The places' numbers, each graded once.
    const std::map<std::string, formats::json> places =
        asked ? numbers_of(reference, *asked) : numbers_of(reference, cells_of_answered_steps(reference, sheet));
    std::set<std::string> graded;
    for (const GivenNumber& number : given) {
        const auto place = places.find(number.path);
        if (!graded.insert(number.path).second) {
            comparison.add(FindingKind::duplicate, number.path, place == places.end() ? nullptr : place->second,
                           number.value);
            comparison.grade(number.path, place == places.end() ? nullptr : place->second, number.value, std::nullopt,
                             Verdict::wrong);
        } else if (place == places.end()) {
            const formats::json* there = value_at(reference, parse_json_path(number.path, ""));
            comparison.add(there ? FindingKind::not_asked : FindingKind::not_in_reference, number.path,
                           there ? *there : formats::json(nullptr), number.value);
            comparison.grade(number.path, there ? *there : formats::json(nullptr), number.value, std::nullopt,
                             Verdict::wrong);
        } else {
            comparison.compare(place->second, number.value, number.path, number.area, number.name);
        }
    }
    // What the sheet leaves out: blank, as an empty cell is.
    for (const auto& [path, expected] : places)
        if (!graded.count(path)) comparison.blank(path, expected);
    if (sheet.cells.empty()) comparison.add(FindingKind::empty, "", nullptr, nullptr);
    // What the sheet was made from: a difference explains every wrong cell after it. Its matches are not
    // the student's, so they are not counted.
    comparison.count_matches(false);
    if (sheet.settings)
        comparison.compare(reference["settings"], *sheet.settings, "settings", FindingKind::setting, "settings");
    if (sheet.scene) comparison.compare(reference["scene"], *sheet.scene, "scene", FindingKind::scene, "scene");

    DiffReport report = std::move(comparison.report());
    report.other_kind = "worksheet";
    sort_into_trace_order(reference, report.findings);
    sort_into_trace_order(reference, report.graded);
    mark_first_divergence(report);
    return report;
}

void word_findings(DiffReport& report, const Trace& trace, const formats::json& reference) {
    WordingCache cache;
    const auto word = [&](const std::string& path, std::string& place, std::string& quantity, std::string& unit) {
        try {
            const Wording w = word_path(trace, reference, parse_json_path(path, ""), &cache);
            place = w.place;
            quantity = w.quantity;
            unit = w.unit;
        } catch (const formats::InputError&) {
            place.clear();  // a scene's material names may be any text: such a path is shown as it is
            quantity = path;
        }
    };
    for (Finding& f : report.findings) word(f.path, f.place, f.quantity, f.unit);
    for (GradedNumber& g : report.graded) word(g.path, g.place, g.quantity, g.unit);
}

void word_findings_by_key(DiffReport& report, const FilledWorksheet& key) {
    std::map<std::string, const FilledCell*> cells;
    for (const FilledCell& cell : key.cells) cells.emplace(cell.path, &cell);
    const auto word = [&](const std::string& path, std::string& place, std::string& quantity, std::string& unit) {
        // The key's cell holding the number: its own path, or a vector's or matrix's with the indices cut off.
        std::string at = path;
        auto found = cells.find(at);
        while (found == cells.end() && at.ends_with(']')) {
            at.resize(at.rfind('['));
            found = cells.find(at);
        }
        if (found == cells.end()) {
            place.clear();
            quantity = path;
            return;
        }
        const FilledCell& cell = *found->second;
        const std::size_t item_end = cell.path.rfind('.');
        place = (item_end == std::string::npos ? cell.path : cell.path.substr(0, item_end)) +
                (cell.step.empty() ? "" : " · " + cell.step);
        quantity = (cell.quantity.empty() ? cell.path.substr(item_end + 1) : cell.quantity) + path.substr(at.size());
        unit = cell.unit;
    };
    for (Finding& f : report.findings) word(f.path, f.place, f.quantity, f.unit);
    for (GradedNumber& g : report.graded) word(g.path, g.place, g.quantity, g.unit);
}

std::string_view verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::right:
            return "right";
        case Verdict::wrong:
            return "wrong";
        case Verdict::blank:
            return "blank";
    }
    return "";
}

Score score_of(const DiffReport& report) {
    Score s;
    if (report.other_kind == "worksheet") {
        for (const GradedNumber& g : report.graded)
            ++(g.verdict == Verdict::right ? s.right : g.verdict == Verdict::wrong ? s.wrong : s.blank);
    } else {
        s.right = report.matched;
        s.wrong = report.mismatched;
        s.blank = report.blank;
    }
    s.cells = s.right + s.wrong + s.blank;
    if (s.cells > 0) s.percent = 100.0 * static_cast<double>(s.right) / static_cast<double>(s.cells);
    // A sheet with nothing on it earns nothing (it used to "all match").
    if (s.cells == 0 && report.other_kind == "worksheet") s.percent = 0.0;
    return s;
}

}  // namespace impulse::course
