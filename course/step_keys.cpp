#include "course/step_keys.hpp"

#include "explain/annotations.hpp"

#include <array>
#include <utility>
#include <vector>
#include <optional>

namespace impulse::course {

namespace {

// The trace's item keys, one per word of the word list (formats/words.hpp) that an item holds, in the
// list's order: the words say which step computes each and what it is to that step.
std::vector<StepKey> keys_from_words() {
    std::vector<StepKey> keys;
    const std::span<const formats::words::Word> all = formats::words::all();
    for (const auto& [item, kind] : {std::pair{ItemKind::contact, 'C'}, std::pair{ItemKind::position_iteration, 'P'},
                                     std::pair{ItemKind::velocity_iteration, 'V'}})
        for (const formats::words::Word& w : all) {
            // Objects and lists hold words of their own ("rewind.time", "updates[].after"): those are the keys.
            if (!formats::words::held_by(w, kind) || w.kind == formats::words::Kind::object ||
                w.kind == formats::words::Kind::list || w.kind == formats::words::Kind::none)
                continue;
            std::string_view step = w.step;
            if (w.role == formats::words::Role::context ||
                (w.role == formats::words::Role::given && w.step != formats::words::step::updates))
                step = {};  // what the item starts from: an input of every step
            if (w.role == formats::words::Role::setting) {
                // A setting belongs to the first step that reads it.
                step = {};
                for (const formats::words::Word& reader : all) {
                    if (!formats::words::held_by(reader, kind) || reader.role != formats::words::Role::computed)
                        continue;
                    const std::string_view in = reader.inputs;
                    for (std::size_t at = in.find(w.quantity); at != std::string_view::npos && step.empty();
                         at = in.find(w.quantity, at + 1)) {
                        const std::size_t end = at + w.quantity.size();
                        if ((at == 0 || in[at - 1] == ' ') && (end == in.size() || in[end] == ' ')) step = reader.step;
                    }
                    if (!step.empty()) break;
                }
            }
            const Role role = w.role == formats::words::Role::given     ? Role::given
                              : w.role == formats::words::Role::setting ? Role::setting
                              : w.role == formats::words::Role::context ? Role::context
                                                                        : Role::computed;
            keys.push_back(StepKey{item, w.quantity, role, step, formats::words::is_per_body(w.kind), &w});
        }
    return keys;
}

const std::vector<StepKey> keys = keys_from_words();

constexpr std::array outside{
    OutsideKey{"scene_bodies", "inverse_mass", true, true, true, "1/kg", "m⁻¹", "the body's inverse mass"},
    OutsideKey{"bodies_before", "inverse_inertia_world", true, true, true, "1/(kg·m²)", "R I⁻¹ Rᵀ",
               "inverse inertia tensor in world coordinates, for the whole frame"},
    OutsideKey{"bodies_before", "position", true, false, false, "m", "p", "the body's centre"},
    OutsideKey{"bodies_before", "velocity", true, false, false, "m/s", "ṗ", "the body's velocity"},
    OutsideKey{"bodies_before", "angular_velocity", true, false, false, "rad/s", "θ̇", "the body's angular velocity"},
    OutsideKey{"contact", "bodies", false, true, true},
    OutsideKey{"contact", "normal", false, true, false},
    OutsideKey{"contact", "basis", false, false, true},
    OutsideKey{"contact", "relative_position", false, true, true},
    OutsideKey{"contact", "friction", false, false, true, "", "μ", "friction coefficient (0: frictionless)"},
    OutsideKey{"contact", "delta_velocity_per_unit_impulse", false, false, true},
};

Described from_annotation(const explain::Annotation& a) {
    return {std::string(a.quantity), std::string(a.unit), std::string(a.formula), std::string(a.equation),
            std::string(a.meaning)};
}

}  // namespace

std::span<const StepKey> step_keys() {
    return keys;
}

std::span<const OutsideKey> outside_keys() {
    return outside;
}

const StepKey* find_step_key(ItemKind item, std::string_view key) {
    for (const StepKey& k : keys)
        if (k.item == item && k.key == key) return &k;
    return nullptr;
}

Described describe_key(const StepKey& key) {
    const formats::words::Word& w = *key.word;
    return {std::string(w.quantity), std::string(w.unit), std::string(w.formula), std::string(w.equation),
            std::string(w.meaning)};
}

Described describe_outside(const OutsideKey& key) {
    if (key.where == "contact")
        if (const StepKey* k = find_step_key(ItemKind::contact, key.key)) return describe_key(*k);
    return {std::string(key.key), std::string(key.unit), std::string(key.formula), "", std::string(key.meaning)};
}

std::string step_key_of(const std::vector<PathToken>& path, std::size_t from) {
    // Nested keys joined by '.', "[]" after updates, features and AVBD's gathered contacts; other indices (a body, a
    // component) dropped.
    std::string key;
    for (std::size_t i = from; i < path.size(); ++i) {
        if (const auto* k = std::get_if<std::string>(&path[i])) {
            if (!key.empty()) key += '.';
            key += *k;
        } else if (key == "updates" || key == "gathered" || key.ends_with(".features")) {
            key += "[]";
        }
    }
    return key;
}

Described describe_path(const formats::json& document, const std::vector<PathToken>& path) {
    // Inside an item: frames[f].contacts[k].… or frames[f].phases[p].iterations[i].…
    std::optional<ItemKind> item;
    std::size_t rest = 0;
    if (key_at(path, 0, "frames") && index_at(path, 1) && key_at(path, 2, "contacts") && index_at(path, 3)) {
        item = ItemKind::contact;
        rest = 4;
    } else if (key_at(path, 0, "frames") && index_at(path, 1) && key_at(path, 2, "phases") && index_at(path, 3) &&
               key_at(path, 4, "iterations") && index_at(path, 5)) {
        const formats::json* phase = value_at(document, {path.begin(), path.begin() + 4});
        if (phase && phase->is_object() && phase->contains("phase"))
            item = (*phase)["phase"] == "position" ? ItemKind::position_iteration : ItemKind::velocity_iteration;
        rest = 6;
    }
    if (item && rest < path.size()) {
        if (const StepKey* k = find_step_key(*item, step_key_of(path, rest))) return describe_key(*k);
    }
    // Elsewhere: the last key that is a vocabulary name.
    for (auto it = path.rbegin(); it != path.rend(); ++it)
        if (const auto* k = std::get_if<std::string>(&*it))
            if (const explain::Annotation* a = explain::find_annotation(*k)) return from_annotation(*a);
    return {};
}

}  // namespace impulse::course
