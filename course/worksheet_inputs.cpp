// What a worksheet step starts from: the item's givens, the settings and values of its earlier steps, the
// bodies' mass properties and state, and what the step's formula needs from outside the item — the frame's
// duration and the bodies' last-frame acceleration (velocity_from_acceleration, ch. 15), the chosen contact's
// penetration or velocity as the earlier iterations left it, and the geometry of every contact an update
// changes. A test (tests/course/test_blank_cells.cpp) works every blank of every shipped lesson and case
// out from these inputs alone.

#include "course/trace_items.hpp"

#include "formats/input_error.hpp"

#include <algorithm>

namespace impulse::course {

namespace {

bool reached(const std::vector<std::string>& order, std::size_t here, std::string_view step) {
    for (std::size_t s = 0; s <= here && s < order.size(); ++s)
        if (order[s] == step) return true;
    return false;
}

// A value of a contact's state that iterations change: the penetration (position phase), the contact velocity
// and the desired velocity change (velocity phase).
enum class Current { penetration, contact_velocity, desired_delta_velocity };

std::string_view after_key(Current what) {
    switch (what) {
        case Current::penetration:
        case Current::contact_velocity:
            return "after";
        case Current::desired_delta_velocity:
            return "desired_delta_velocity_after";
    }
    return "";
}

std::string_view item_key(Current what) {
    switch (what) {
        case Current::penetration:
            return "penetration";
        case Current::contact_velocity:
            return "contact_velocity";
        case Current::desired_delta_velocity:
            return "desired_delta_velocity";
    }
    return "";
}

// The step that computes the value at the chosen iteration or in the preparation.
std::string_view own_step(Current what, bool prepared) {
    switch (what) {
        case Current::penetration:
            return prepared ? "given" : "choice";
        case Current::contact_velocity:
            return "contact_velocity";
        case Current::desired_delta_velocity:
            return "desired_delta_velocity";
    }
    return "";
}

struct Source {
    std::string path;
    std::string step;
    std::string how;  // "as iteration 2 left it", "as prepared"
};

// Where contact `contact`'s `what` was last written before update `update` of `iteration` (of the item's phase),
// or before the iteration began when `update` is npos: an earlier update's `after`, the iteration's own value
// (the chosen contact, from its first update on), or the contact as prepared.
std::optional<Source> current_source(const ItemAt& item, std::size_t iteration, std::size_t update,
                                     const formats::json& contact, Current what) {
    const std::string phase_path =
        formats::json_path_index(formats::json_path_child(item.frame_path, "phases"), item.phase);
    const formats::json& iterations = (*item.frame)["phases"][item.phase]["iterations"];
    const auto iteration_path = [&](std::size_t i) {
        return formats::json_path_index(formats::json_path_child(phase_path, "iterations"), i);
    };
    const auto last_update_of = [&](std::size_t i, std::size_t before) -> std::optional<Source> {
        const formats::json& updates = iterations[i]["updates"];
        for (std::size_t u = std::min(before, updates.size()); u-- > 0;)
            if (updates[u]["contact"] == contact)
                return Source{formats::json_path_child(
                                  formats::json_path_index(formats::json_path_child(iteration_path(i), "updates"), u),
                                  after_key(what)),
                              "updates",
                              i == iteration ? "as update " + std::to_string(u) + " of this iteration left it"
                                             : "as iteration " + std::to_string(i) + " left it"};
        return std::nullopt;
    };
    if (update != std::string::npos) {
        if (auto s = last_update_of(iteration, update)) return s;
        if (iterations[iteration]["contact"] == contact)
            return Source{formats::json_path_child(iteration_path(iteration), item_key(what)),
                          std::string(own_step(what, false)), "when this iteration chose it"};
    }
    for (std::size_t i = iteration; i-- > 0;)
        if (auto s = last_update_of(i, SIZE_MAX)) return s;
    const long k = recorded_contact_index(*item.frame, contact);
    if (k < 0) return std::nullopt;
    return Source{
        formats::json_path_child(formats::json_path_index(formats::json_path_child(item.frame_path, "contacts"),
                                                          static_cast<std::size_t>(k)),
                                 item_key(what)),
        std::string(own_step(what, true)), "as prepared"};
}

class Needs {
public:
    Needs(const ItemAt& item, const formats::json& document, bool resolved, std::vector<WorksheetEntry>& inputs)
        : item_(item), document_(document), resolved_(resolved), inputs_(inputs) {}

    // A setting of the trace header: "duration", "relaxation.fraction".
    void setting(std::string_view name, std::string_view unit, std::string_view formula, std::string_view meaning) {
        const formats::json* value = &document_["settings"];
        std::string path = "settings";
        std::size_t start = 0;
        while (start <= name.size()) {
            const std::size_t dot = std::min(name.find('.', start), name.size());
            const std::string key(name.substr(start, dot - start));
            if (!value->is_object() || !value->contains(key)) return;
            value = &(*value)[key];
            path = formats::json_path_child(path, key);
            start = dot + 1;
        }
        inputs_.push_back(make_entry(
            path, "given", path, {path, std::string(unit), std::string(formula), "", std::string(meaning)}, *value));
    }

    // What accelerated body `body` during the frame before this resolution (its last_frame_acceleration): a case
    // gives it in its scene; a simulation's integration has just applied gravity to every body that can move.
    void acceleration(const formats::json& body) {
        if (body.is_null()) return;
        const auto b = body.get<std::size_t>();
        if (resolved_) {
            const std::string path =
                formats::json_path_child(formats::json_path_index("scene.bodies", b), "last_frame_acceleration");
            if (const formats::json* a = value_at(document_, parse_json_path(path, "")))
                inputs_.push_back(make_entry(path, "given", path,
                                             {path, "m/s²", "a, from the scene", "",
                                              "the acceleration the body had during the last frame (ch. 15)"},
                                             *a));
        } else if (document_["scene"].contains("gravity")) {
            inputs_.push_back(make_entry(
                "scene.gravity", "given", "scene.gravity",
                {"scene.gravity", "m/s²", "a = g, or 0 when m⁻¹ = 0", "",
                 "the frame's integration accelerated every body that can move by g just before this resolution: "
                 "that is each body's last_frame_acceleration"},
                document_["scene"]["gravity"]));
        }
    }

    // A key of a contact as prepared (frames[f].contacts[k].key, or one body's element of a per-body key).
    void contact_key(const formats::json& contact, std::string_view key,
                     std::optional<std::size_t> body = std::nullopt) {
        const long k = recorded_contact_index(*item_.frame, contact);
        if (k < 0) return;
        const std::string contact_path = formats::json_path_index(
            formats::json_path_child(item_.frame_path, "contacts"), static_cast<std::size_t>(k));
        const StepKey* described = find_step_key(ItemKind::contact, key);
        const Described d = described ? describe_key(*described) : Described{};
        const formats::json& object = (*item_.frame)["contacts"][static_cast<std::size_t>(k)];
        if (!object.contains(std::string(key))) return;
        std::string path = formats::json_path_child(contact_path, key);
        formats::json value = object[std::string(key)];
        if (body) {
            if (!value.is_array() || *body >= value.size() || value[*body].is_null()) return;
            path = formats::json_path_index(path, *body);
            value = value[*body];
        }
        inputs_.push_back(
            make_entry(path, described && described->role == Role::computed ? std::string(described->step) : "given",
                       path.substr(item_.frame_path.size() + 1), d, value));
    }

    // The contact's `what` as it stood before `update` of this iteration (npos: before the iteration).
    void current(const formats::json& contact, std::size_t iteration, std::size_t update, Current what) {
        const std::optional<Source> s = current_source(item_, iteration, update, contact, what);
        if (!s) return;
        Described d = describe_path(document_, parse_json_path(s->path, ""));
        const std::string name = what == Current::penetration        ? "penetration"
                                 : what == Current::contact_velocity ? "contact velocity"
                                                                     : "desired velocity change";
        d.meaning = "contact " + contact.dump() + "'s " + name + " " + s->how;
        inputs_.push_back(make_entry(s->path, s->step, s->path.substr(item_.frame_path.size() + 1), d,
                                     *value_at(document_, parse_json_path(s->path, ""))));
    }

    // The chosen contact's bodies: the item's own for a contact; for an iteration, the chosen contact's.
    const formats::json& bodies() const {
        if (item_.kind == ItemKind::contact) return (*item_.object)["bodies"];
        const long k = recorded_contact_index(*item_.frame, (*item_.object)["contact"]);
        static const formats::json none = formats::json::array({nullptr, nullptr});
        return k < 0 ? none : (*item_.frame)["contacts"][static_cast<std::size_t>(k)]["bodies"];
    }

    // The bodies' motion as the iteration finds it: bodies_before when the position phase runs first (it does not
    // change velocities), else bodies_after (the velocity phase has finished).
    void motion() {
        const bool first = item_.phase == 0;
        for (const formats::json& body : bodies()) {
            if (body.is_null()) continue;
            const auto b = body.get<std::size_t>();
            const std::string where = first ? "bodies_before" : "bodies_after";
            const std::string name = formats::json_path_index(where, b);
            for (const char* key : {"velocity", "angular_velocity"}) {
                const std::string path =
                    formats::json_path_child(formats::json_path_child(item_.frame_path, name), key);
                const formats::json* value = value_at(document_, parse_json_path(path, ""));
                if (!value) continue;
                const bool linear = std::string_view(key) == "velocity";
                inputs_.push_back(make_entry(path, "given", name + "." + key,
                                             {key, linear ? "m/s" : "rad/s", linear ? "ṗ" : "θ̇", "",
                                              std::string("the body's ") + (linear ? "velocity" : "angular velocity") +
                                                  (first ? " (the position phase runs first: as the frame began)"
                                                         : " (after the velocity phase)")},
                                             *value));
            }
        }
    }

private:
    const ItemAt& item_;
    const formats::json& document_;
    bool resolved_;
    std::vector<WorksheetEntry>& inputs_;
};

void add_needs(const ItemAt& item, const std::vector<std::string>& order, std::size_t here,
               const formats::json& document, bool resolved, std::vector<WorksheetEntry>& inputs) {
    Needs needs(item, document, resolved, inputs);
    const formats::json& object = *item.object;
    const auto duration = [&needs] {
        needs.setting("duration", "s", "Δt", "the frame's duration: how long last frame's acceleration acted");
    };
    if (item.kind == ItemKind::contact) {
        // Step 4 adds the sliding that last frame's acceleration caused, step 5 takes its normal part out of the
        // bounce: both read a·Δt.
        if (reached(order, here, "contact_velocity")) {
            duration();
            needs.setting("tangential_acceleration_velocity", "", "setting tangential_acceleration_velocity",
                          "whether the sliding last frame's acceleration caused is added to the contact velocity");
            for (const formats::json& body : object["bodies"]) needs.acceleration(body);
        }
        return;
    }
    const formats::json& chosen = object["contact"];
    const auto iteration = object["iteration"].get<std::size_t>();
    if (item.kind == ItemKind::position_iteration) {
        needs.current(chosen, iteration, std::string::npos, Current::penetration);
        if (reached(order, here, "penetration_inertia") && object.value("method", "") == "relaxation")
            needs.setting("relaxation.fraction", "", "setting relaxation.fraction",
                          "the share of the current penetration each visit removes");
        if (reached(order, here, "rewind")) needs.motion();
        if (reached(order, here, "move_split") && object.contains("angular_limit") &&
            object["angular_limit"].value("policy", "") == "angle")
            needs.setting("orientation_update", "", "setting orientation_update",
                          "how a rotation vector turns a body (the angle limit inverts it)");
    } else {
        if (reached(order, here, "contact_velocity"))
            needs.current(chosen, iteration, std::string::npos, Current::contact_velocity);
        if (reached(order, here, "desired_delta_velocity")) {
            duration();
            for (const formats::json& body : needs.bodies()) needs.acceleration(body);
        }
    }
    // Each update changes another contact through its own geometry, from the value it had just before.
    if (!reached(order, here, "updates") || !object.contains("updates")) return;
    const formats::json& updates = object["updates"];
    for (std::size_t u = 0; u < updates.size(); ++u) {
        const formats::json& other = updates[u]["contact"];
        const auto slot = updates[u]["slot"].get<std::size_t>();
        if (item.kind == ItemKind::position_iteration) {
            needs.current(other, iteration, u, Current::penetration);
            if (other == chosen) continue;
            needs.contact_key(other, "normal");
            needs.contact_key(other, "relative_position", slot);
        } else {
            needs.current(other, iteration, u, Current::contact_velocity);
            needs.current(other, iteration, u, Current::desired_delta_velocity);
            if (other == chosen) continue;
            needs.contact_key(other, "bodies");
            needs.contact_key(other, "basis");
            needs.contact_key(other, "relative_position", slot);
            needs.contact_key(other, "restitution");
            const long k = recorded_contact_index(*item.frame, other);
            if (k >= 0)
                for (const formats::json& body : (*item.frame)["contacts"][static_cast<std::size_t>(k)]["bodies"])
                    needs.acceleration(body);
        }
    }
}

// Given keys that the sources above replace: an update's value before is an earlier value of the sheet.
bool replaced_by_source(std::string_view key) {
    return key == "updates[].before" || key == "updates[].desired_delta_velocity_before";
}

// The chosen (or this) contact's preparation in the frame's document, or null when it was not recorded.
const formats::json* prepared_contact(const ItemAt& item, std::string* path) {
    if (item.kind == ItemKind::contact) {
        *path = item.path;
        return item.object;
    }
    const long k = recorded_contact_index(*item.frame, (*item.object)["contact"]);
    if (k < 0) return nullptr;
    *path =
        formats::json_path_index(formats::json_path_child(item.frame_path, "contacts"), static_cast<std::size_t>(k));
    return &(*item.frame)["contacts"][static_cast<std::size_t>(k)];
}

}  // namespace

std::vector<WorksheetEntry> inputs_of(const ItemAt& item, const std::vector<std::string>& order, std::size_t here,
                                      const formats::json& document, bool resolved) {
    std::vector<WorksheetEntry> inputs;
    const std::string given = "given";
    for (const StepKey& key : step_keys())
        if (key.item == item.kind && key.role == Role::given && key.step.empty()) expand_key(item, key, given, inputs);

    // What the item's bodies and (for an iteration) its chosen contact bring in.
    std::string contact_path;
    if (const formats::json* contact = prepared_contact(item, &contact_path)) {
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
            for (const formats::json& body : (*contact)["bodies"]) {
                if (body.is_null()) continue;
                const auto b = body.get<std::size_t>();
                if (key.where == "scene_bodies") {
                    const std::string at = formats::json_path_index("scene.bodies", b);
                    expand(document["scene"]["bodies"][b], at, at, key.key, false, d, given, inputs);
                } else {
                    const std::string name = formats::json_path_index("bodies_before", b);
                    expand((*item.frame)["bodies_before"][b], formats::json_path_child(item.frame_path, name), name,
                           key.key, false, d, given, inputs);
                }
            }
        }
    }

    // The settings of the steps up to this one and the values of the steps before it.
    for (std::size_t s = 0; s <= here && s < order.size(); ++s)
        for (const StepKey& key : step_keys()) {
            if (key.item != item.kind || key.step != order[s]) continue;
            if ((key.role == Role::setting || key.role == Role::given) && !replaced_by_source(key.key))
                expand_key(item, key, given, inputs);
            if (key.role == Role::computed && s < here) expand_key(item, key, order[s], inputs);
        }
    add_needs(item, order, here, document, resolved, inputs);
    return inputs;
}

}  // namespace impulse::course
