// What a trace's schema cannot say, checked after it: references between its parts and its values' physics.
#include "formats/trace_checks.hpp"

#include "formats/input_error.hpp"
#include "formats/physical_values.hpp"
#include "record/word_table.hpp"

#include <string_view>

namespace impulse::formats {

void check_references(const json& frame, const std::string& path, std::size_t bodies) {
    const std::size_t contacts = frame["contact_count"].get<std::size_t>();
    const auto in_range = [](const json& index, std::size_t count, const std::string& where, const char* what) {
        if (!index.is_null() && index.get<std::size_t>() >= count)
            throw InputError(where, std::string("no ") + what + " " + index.dump() +
                                        (what[0] == 'b' ? " in the scene" : " in this frame") + " (it has " +
                                        std::to_string(count) + ")");
    };
    for (const char* key : {"bodies_before", "bodies_after"})
        if (frame[key].size() != bodies)
            throw InputError(json_path_child(path, key), "lists " + std::to_string(frame[key].size()) +
                                                             " bodies, the scene has " + std::to_string(bodies));
    const json& records = frame["contacts"];
    for (std::size_t i = 0; i < records.size(); ++i) {
        const std::string at = json_path_index(json_path_child(path, "contacts"), i);
        in_range(records[i]["contact"], contacts, json_path_child(at, "contact"), "contact");
        for (std::size_t b = 0; b < 2; ++b)
            in_range(records[i]["bodies"][b], bodies, json_path_index(json_path_child(at, "bodies"), b), "body");
    }
    const json& phases = frame["phases"];
    for (std::size_t p = 0; p < phases.size(); ++p) {
        const std::string phase_path = json_path_index(json_path_child(path, "phases"), p);
        const json& iterations = phases[p]["iterations"];
        for (std::size_t i = 0; i < iterations.size(); ++i) {
            const std::string at = json_path_index(json_path_child(phase_path, "iterations"), i);
            in_range(iterations[i]["contact"], contacts, json_path_child(at, "contact"), "contact");
            // A distance or an impulse: which of the two words the move records follows from its method.
            constexpr std::string_view push_impulse = words::key("push_impulse", "P"),
                                       amount = words::key("amount", "P");
            if (iterations[i].contains("method")) {
                const bool split = iterations[i]["method"] == "split_impulse";
                if (!iterations[i].contains(split ? push_impulse : amount))
                    throw InputError(json_path_child(at, std::string(split ? amount : push_impulse)),
                                     split ? "a split_impulse move records push_impulse (N·s), not amount"
                                           : "only a split_impulse move records push_impulse; this one records "
                                             "amount (m)");
            }
            const json& updates = iterations[i]["updates"];
            for (std::size_t u = 0; u < updates.size(); ++u) {
                const std::string update = json_path_index(json_path_child(at, "updates"), u);
                in_range(updates[u]["contact"], contacts, json_path_child(update, "contact"), "contact");
                in_range(updates[u]["body"], bodies, json_path_child(update, "body"), "body");
            }
        }
    }
    if (phases[0]["phase"] == phases[1]["phase"])
        throw InputError(json_path_child(path, "phases"), "needs one position phase and one velocity phase");
}

void check_frame_values(const FrameRecord& f, const std::string& path) {
    const auto check_states = [&path](const std::vector<BodyState>& states, const char* key) {
        for (std::size_t i = 0; i < states.size(); ++i)
            unit_quaternion(states[i].orientation,
                            json_path_child(json_path_index(json_path_child(path, key), i), "orientation"));
    };
    check_states(f.bodies_before, "bodies_before");
    check_states(f.bodies_after, "bodies_after");
    for (std::size_t i = 0; i < f.inverse_inertia_world.size(); ++i)
        check_inverse_inertia(
            f.inverse_inertia_world[i],
            json_path_child(json_path_index(json_path_child(path, "bodies_before"), i), "inverse_inertia_world"));
    for (std::size_t i = 0; i < f.contacts.size(); ++i) {
        const std::string at = json_path_index(json_path_child(path, "contacts"), i);
        require_unit_vector(f.contacts[i].normal, json_path_child(at, "normal"));
        require_orthonormal(f.contacts[i].basis.contact_to_world, json_path_child(at, "basis"));
    }
}

}  // namespace impulse::formats
