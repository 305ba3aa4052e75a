#include "explain/annotations.hpp"

#include <algorithm>
#include <cassert>
#include <set>
#include <unordered_map>

namespace impulse::explain {

namespace {

// Every name once, in the word list's order: where items of different kinds hold different words of one name
// (a contact's `penetration` is given, a position iteration's is the one it chose), the first stands for it.
const std::vector<Annotation> rows = [] {
    std::vector<Annotation> names;
    std::set<std::string_view> seen;
    for (const formats::words::Word& w : formats::words::all())
        if (seen.insert(w.quantity).second) names.push_back(w);
    return names;
}();

}  // namespace

const std::vector<Annotation>& vocabulary() {
    return rows;
}

const Annotation* find_annotation(std::string_view quantity) {
    // Looked up for every row of every table the window draws: indexed once.
    static const std::unordered_map<std::string_view, const Annotation*> index = [] {
        std::unordered_map<std::string_view, const Annotation*> names;
        for (const Annotation& a : rows) names.emplace(a.quantity, &a);
        return names;
    }();
    const auto found = index.find(quantity);
    return found == index.end() ? nullptr : found->second;
}

const Annotation& annotation(std::string_view quantity) {
    const Annotation* found = find_annotation(quantity);
    assert(found && "every vocabulary name has an annotation");
    return found ? *found : rows.front();
}

std::vector<std::string_view> inputs_of(const Annotation& a) {
    std::vector<std::string_view> names;
    std::string_view rest = a.inputs;
    while (!rest.empty()) {
        const std::size_t space = rest.find(' ');
        if (space != 0) names.push_back(rest.substr(0, space));
        if (space == std::string_view::npos) break;
        rest.remove_prefix(space + 1);
    }
    return names;
}

std::vector<std::string_view> consumers(std::string_view quantity) {
    // The rows are in derivation order, but a row may name a later one (impulse_model reads the friction
    // solve it chooses between), so the closure is grown until it stops changing.
    std::set<std::string_view> reached{quantity};
    std::vector<std::string_view> found;
    for (bool grew = true; grew;) {
        grew = false;
        for (const Annotation& a : rows) {
            if (reached.count(a.quantity)) continue;
            for (std::string_view input : inputs_of(a))
                if (reached.count(input)) {
                    reached.insert(a.quantity);
                    found.push_back(a.quantity);
                    grew = true;
                    break;
                }
        }
    }
    return found;
}

const Annotation* quantity_of_path(std::string_view path, ItemKind item) {
    // The path's keys without indices ("updates[0].after[0]" -> "updates.after"), and with a list's element as the
    // word list names it ("gathered[2].force[0]" -> "gathered[].force").
    std::string keys, listed;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path[i] == '[') {
            i = path.find(']', i);
            if (i == std::string_view::npos) break;
            if (i + 1 < path.size() && path[i + 1] == '.') listed += "[]";
            continue;
        }
        keys += path[i];
        listed += path[i];
    }
    const char kind = item == ItemKind::contact ? 'C' : item == ItemKind::position_iteration ? 'P' : 'V';
    // An update is shown as one row per contact it changed: the whole record is that row's quantity.
    if (keys == "updates" || keys.starts_with("updates."))
        return kind == 'C' ? nullptr : find_annotation(kind == 'P' ? "penetration_update" : "velocity_update");
    // Every key inside an item is a word of its own, nested ones by their whole path ("rewind.time"); an element
    // of a list a table shows row by row (AVBD's gathered contacts) by its list's path.
    const formats::words::Word* element = listed != keys ? formats::words::find(listed, kind) : nullptr;
    if (element && element->role != formats::words::Role::context) return element;
    return formats::words::find(keys, kind);
}

}  // namespace impulse::explain
