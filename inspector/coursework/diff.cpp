#include "coursework/diff.hpp"

#include "coursework/step_keys.hpp"
#include "coursework/worksheet.hpp"
#include "io/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace impulse::coursework {

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
std::optional<std::vector<io::json>> identities(const io::json& array, std::string_view key) {
    if (key.empty()) return std::nullopt;
    std::vector<io::json> ids;
    for (const io::json& element : array) {
        if (!element.is_object() || !element.contains(key)) return std::nullopt;
        const io::json& id = element[std::string(key)];
        if (std::find(ids.begin(), ids.end(), id) != ids.end()) return std::nullopt;
        ids.push_back(id);
    }
    return ids;
}

class Comparison {
public:
    Comparison(const io::json& reference, const Tolerance& tolerance, bool blank_allowed)
        : reference_(reference), tolerance_(tolerance), blank_allowed_(blank_allowed) {}

    // `area` is the kind a differing value is reported as; `name` the key that holds `expected`.
    void compare(const io::json& expected, const io::json& found, const std::string& path, FindingKind area,
                 std::string_view name) {
        if (expected.is_object() && found.is_object()) {
            for (auto it = expected.begin(); it != expected.end(); ++it) {
                const std::string child = io::json_path_child(path, it.key());
                const auto there = found.find(it.key());
                if (there == found.end())
                    add(FindingKind::missing, child, it.value(), nullptr);
                else
                    compare(it.value(), *there, child, area, it.key());
            }
            for (auto it = found.begin(); it != found.end(); ++it)
                if (!expected.contains(it.key()))
                    add(FindingKind::extra, io::json_path_child(path, it.key()), nullptr, it.value());
            return;
        }
        if (expected.is_array() && found.is_array()) {
            compare_arrays(expected, found, path, area, name);
            return;
        }
        if (blank_allowed_ && found.is_null() && !expected.is_null()) {
            for_each_scalar(expected, path, [this](const std::string& at, const io::json& value) {
                add(FindingKind::blank, at, value, nullptr);
                ++report_.blank;
            });
            return;
        }
        if (expected.is_number() && found.is_number()) {
            const double a = expected.get<double>(), b = found.get<double>();
            const double difference = std::abs(a - b);
            if (difference <= tolerance_.atol + tolerance_.rtol * std::abs(a)) {
                matched();
                return;
            }
            add(area, path, expected, found).relative_error = a == 0.0 ? difference : difference / std::abs(a);
            return;
        }
        if (expected == found && !expected.is_structured()) {
            matched();
            return;
        }
        add(area, path, expected, found);
    }

    Finding& add(FindingKind kind, const std::string& path, const io::json& expected, const io::json& found) {
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
        } catch (const io::InputError&) {
            // A scene's material names are keys of any text: such a path has no vocabulary name anyway.
        }
        report_.findings.push_back(std::move(f));
        return report_.findings.back();
    }

    void count_matches(bool on) { counting_ = on; }
    DiffReport& report() { return report_; }

private:
    void matched() {
        if (counting_) ++report_.matched;
    }

    void compare_arrays(const io::json& expected, const io::json& found, const std::string& path, FindingKind area,
                        std::string_view name) {
        const std::string_view key = identity_key(name);
        const auto expected_ids = identities(expected, key), found_ids = identities(found, key);
        if (expected_ids && found_ids) {
            std::vector<bool> paired(found.size(), false);
            for (std::size_t i = 0; i < expected.size(); ++i) {
                const auto there = std::find(found_ids->begin(), found_ids->end(), (*expected_ids)[i]);
                const std::string at = io::json_path_index(path, i);
                if (there == found_ids->end()) {
                    add(FindingKind::missing, at, expected[i], nullptr);
                    continue;
                }
                const auto j = static_cast<std::size_t>(there - found_ids->begin());
                paired[j] = true;
                compare(expected[i], found[j], at, area, name);
            }
            for (std::size_t j = 0; j < found.size(); ++j)
                if (!paired[j]) add(FindingKind::extra, io::json_path_index(path, j), nullptr, found[j]);
            return;
        }
        for (std::size_t i = 0; i < std::max(expected.size(), found.size()); ++i) {
            const std::string at = io::json_path_index(path, i);
            if (i >= found.size())
                add(FindingKind::missing, at, expected[i], nullptr);
            else if (i >= expected.size())
                add(FindingKind::extra, at, nullptr, found[i]);
            else
                compare(expected[i], found[i], at, area, name);
        }
    }

    const io::json& reference_;
    Tolerance tolerance_;
    bool blank_allowed_;
    bool counting_ = true;
    DiffReport report_;
};

FindingKind area_of(std::string_view top_key) {
    if (top_key == "settings") return FindingKind::setting;
    if (top_key == "scene") return FindingKind::scene;
    return FindingKind::value;
}

void mark_first_divergence(DiffReport& report) {
    for (Finding& f : report.findings)
        if (f.kind != FindingKind::blank) {
            f.first_divergence = true;
            return;
        }
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
    }
    return "";
}

const Finding* DiffReport::first_divergence() const {
    for (const Finding& f : findings)
        if (f.first_divergence) return &f;
    return nullptr;
}

DiffReport diff_traces(const io::json& reference, const io::json& other, const Tolerance& tolerance) {
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

DiffReport diff_worksheet(const io::json& reference, const FilledWorksheet& sheet, const Tolerance& tolerance) {
    Comparison comparison(reference, tolerance, true);
    for (const FilledCell& cell : sheet.cells) {
        const io::json* expected = value_at(reference, cell.tokens);
        if (!expected) {
            comparison.add(FindingKind::not_in_reference, cell.path, nullptr, cell.value);
            continue;
        }
        const auto* top = std::get_if<std::string>(&cell.tokens.front());
        const auto* last = std::get_if<std::string>(&cell.tokens.back());
        comparison.compare(*expected, cell.value, cell.path, area_of(top ? *top : ""), last ? *last : "");
    }
    // What the sheet was made from: a difference explains every wrong cell after it. Its matches are not
    // the student's, so they are not counted.
    comparison.count_matches(false);
    if (sheet.settings)
        comparison.compare(reference["settings"], *sheet.settings, "settings", FindingKind::setting, "settings");
    if (sheet.scene) comparison.compare(reference["scene"], *sheet.scene, "scene", FindingKind::scene, "scene");

    DiffReport report = std::move(comparison.report());
    report.other_kind = "worksheet";
    // Into trace order: by where each path comes in the reference document.
    std::vector<std::pair<std::vector<std::size_t>, std::size_t>> order;
    for (std::size_t i = 0; i < report.findings.size(); ++i) {
        std::vector<std::size_t> position;
        try {
            position = document_position(reference, parse_json_path(report.findings[i].path, ""));
        } catch (const io::InputError&) {
            position = {SIZE_MAX};
        }
        order.emplace_back(std::move(position), i);
    }
    std::stable_sort(order.begin(), order.end());
    std::vector<Finding> sorted;
    for (const auto& [position, i] : order) sorted.push_back(std::move(report.findings[i]));
    report.findings = std::move(sorted);
    mark_first_divergence(report);
    return report;
}

}  // namespace impulse::coursework
