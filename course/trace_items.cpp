#include "course/trace_items.hpp"

#include "formats/input_error.hpp"

namespace impulse::course {

using model::Cursor;
using model::Stage;

ItemAt item_at(const formats::json& document, const Cursor& c) {
    const std::string frame_path = formats::json_path_index("frames", static_cast<std::size_t>(c.frame));
    const formats::json& frame = document["frames"][static_cast<std::size_t>(c.frame)];
    const auto item = static_cast<std::size_t>(c.item);
    if (c.stage == Stage::preparation)
        return {ItemKind::contact, formats::json_path_index(formats::json_path_child(frame_path, "contacts"), item),
                &frame["contacts"][item], frame_path, &frame};
    const std::string_view phase = model::stage_name(c.stage);
    std::size_t p = 0;
    while (p + 1 < frame["phases"].size() && frame["phases"][p]["phase"] != phase) ++p;
    const std::string phase_path = formats::json_path_index(formats::json_path_child(frame_path, "phases"), p);
    return {c.stage == Stage::position ? ItemKind::position_iteration : ItemKind::velocity_iteration,
            formats::json_path_index(formats::json_path_child(phase_path, "iterations"), item),
            &frame["phases"][p]["iterations"][item],
            frame_path,
            &frame,
            p};
}

WorksheetEntry make_entry(std::string path, std::string step, std::string quantity, const Described& d,
                          formats::json value) {
    return {std::move(path), std::move(step), std::move(quantity), d.unit,
            d.formula,       d.equation,      d.meaning,           std::move(value)};
}

void expand(const formats::json& object, const std::string& path, const std::string& quantity, std::string_view key,
            bool per_body, const Described& d, const std::string& step, std::vector<WorksheetEntry>& out) {
    const std::size_t dot = key.find('.');
    const std::string_view head = key.substr(0, dot);
    const bool each_element = head.ends_with("[]");
    const std::string name(each_element ? head.substr(0, head.size() - 2) : head);
    if (!object.is_object() || !object.contains(name)) return;
    const formats::json& value = object[name];
    const std::string at = formats::json_path_child(path, name);
    const std::string called = quantity.empty() ? name : quantity + "." + name;
    if (each_element) {
        for (std::size_t i = 0; i < value.size(); ++i)
            expand(value[i], formats::json_path_index(at, i), called + "[" + std::to_string(i) + "]",
                   key.substr(dot + 1), per_body, d, step, out);
    } else if (dot != std::string_view::npos) {
        expand(value, at, called, key.substr(dot + 1), per_body, d, step, out);
    } else if (per_body) {
        for (std::size_t b = 0; b < value.size(); ++b)
            if (!value[b].is_null())
                out.push_back(make_entry(formats::json_path_index(at, b), step, called + "[" + std::to_string(b) + "]",
                                         d, value[b]));
    } else if (!value.is_null()) {
        out.push_back(make_entry(at, step, called, d, value));
    }
}

void expand_key(const ItemAt& item, const StepKey& key, const std::string& step, std::vector<WorksheetEntry>& out) {
    expand(*item.object, item.path, "", key.key, key.per_body, describe_key(key), step, out);
}

long recorded_contact_index(const formats::json& frame, const formats::json& contact) {
    const formats::json& contacts = frame["contacts"];
    for (std::size_t k = 0; k < contacts.size(); ++k)
        if (contacts[k]["contact"] == contact) return static_cast<long>(k);
    return -1;
}

}  // namespace impulse::course
