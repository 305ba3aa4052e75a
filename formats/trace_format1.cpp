// Trace format 1, the keys before the word list renamed them, read as the current format (docs/trace-format.md).
#include "formats/trace_format1.hpp"

#include "record/trace.hpp"
#include "formats/words.hpp"

namespace impulse::formats {

namespace {

// The value at a word's key path inside an item ("move_split.linear_move"), or null.
json* at_key(json& item, std::string_view path) {
    json* at = &item;
    for (std::size_t start = 0;;) {
        const std::size_t dot = path.find('.', start);
        const std::string key(path.substr(start, dot == std::string_view::npos ? path.npos : dot - start));
        if (!at->is_object() || !at->contains(key)) return nullptr;
        at = &(*at)[key];
        if (dot == std::string_view::npos) return at;
        start = dot + 1;
    }
}

// Moves a format-1 key to its word's path, creating the objects on the way ("linear_move" -> "move_split").
void rename_key(json& item, std::string_view from, std::string_view to) {
    json* value = at_key(item, from);
    if (!value) return;
    json moved = std::move(*value);
    item.erase(std::string(from));  // format 1's renamed keys were all top-level keys of their item
    json* at = &item;
    for (std::size_t start = 0;;) {
        const std::size_t dot = to.find('.', start);
        const std::string key(to.substr(start, dot == std::string_view::npos ? to.npos : dot - start));
        if (dot == std::string_view::npos) {
            (*at)[key] = std::move(moved);
            return;
        }
        at = &(*at)[key];
        start = dot + 1;
    }
}

// Format 1 -> 2 for one item: every word of the list whose format-1 key was another is moved to its name.
void upgrade_item(json& item, char kind) {
    if (!item.is_object()) return;  // the schema names what is wrong with it
    // Format 1 wrote the split impulse's push (N·s) under the projections' `amount` (m): format 2 has a word
    // for each, so `amount` moves only in a split impulse's iteration.
    const bool split = kind == 'P' && item.contains("method") && item["method"] == "split_impulse";
    for (const words::Word& w : words::all()) {
        if (w.format1.empty() || !words::held_by(w, kind)) continue;
        if (w.quantity == "push_impulse" && !split) continue;
        rename_key(item, w.format1, w.quantity);
    }
}

}  // namespace

std::optional<int> upgrade_trace_document(json& document) {
    if (!document.is_object() || !document.contains("version") || document["version"] != 1 ||
        !document.contains("frames") || !document["frames"].is_array())
        return std::nullopt;  // current, or not a trace: the schema says which
    for (json& frame : document["frames"]) {
        if (!frame.is_object()) continue;
        if (frame.contains("contacts") && frame["contacts"].is_array())
            for (json& contact : frame["contacts"]) upgrade_item(contact, 'C');
        if (frame.contains("phases") && frame["phases"].is_array())
            for (json& phase : frame["phases"]) {
                if (!phase.is_object() || !phase.contains("iterations") || !phase["iterations"].is_array()) continue;
                const char kind = phase.contains("phase") && phase["phase"] == "position" ? 'P' : 'V';
                for (json& iteration : phase["iterations"]) upgrade_item(iteration, kind);
            }
    }
    document["version"] = trace_format_version;
    return 1;
}

std::string format1_note(std::string_view file) {
    return "impulse-lab: note: " + std::string(file) + " was written in trace format 1; read with format " +
           std::to_string(trace_format_version) + "'s renamed keys (docs/trace-format.md lists them)";
}

}  // namespace impulse::formats
