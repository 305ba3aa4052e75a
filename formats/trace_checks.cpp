// What a trace's schema cannot say, checked after it: references between its parts and its values' physics.
#include "formats/trace_checks.hpp"

#include "formats/input_error.hpp"
#include "formats/physical_values.hpp"
#include "formats/word_table.hpp"

#include <algorithm>
#include <climits>
#include <string_view>

namespace impulse::formats {

namespace {

// An update changes its contact through the body in its slot: that body must be the contact's, in that slot.
void check_update_body(const json& records, const json& update, const std::string& where) {
    const json& number = update["contact"];
    const auto record =
        std::find_if(records.begin(), records.end(), [&number](const json& c) { return c["contact"] == number; });
    if (record == records.end()) return;  // not recorded (a contact filter): nothing to hold it to
    const json& body = (*record)["bodies"][update["slot"].get<std::size_t>()];
    if (body != update["body"])
        throw InputError(where, "is " + update["body"].dump() + ", but contact " + number.dump() + " has " +
                                    (body.is_null() ? std::string("the world") : "body " + body.dump()) + " in slot " +
                                    update["slot"].dump());
}

std::string count_text(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

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
                check_update_body(records, updates[u], json_path_child(update, "body"));
            }
        }
    }
    if (phases[0]["phase"] == phases[1]["phase"])
        throw InputError(json_path_child(path, "phases"), "needs one position phase and one velocity phase");
}

void check_counts(const json& document) {
    const json& recording = document["recording"];
    const auto first = recording["first_frame"].get<long long>();
    const bool open_ended = recording["last_frame"].is_null();
    const long long last = open_ended ? LLONG_MAX : recording["last_frame"].get<long long>();
    // A run stopped before its first recorded frame records none: its range ends just before it starts
    // (end_recording_before writes first 1, last 0). Further back, the range contradicts itself.
    if (last < first - 1)
        throw InputError("recording.last_frame", "must be >= first_frame (" + std::to_string(first) +
                                                     "), or first_frame - 1 for a recording of no frames, got " +
                                                     std::to_string(last));
    const json& filter = recording["contacts"];
    const json& frames = document["frames"];
    long long previous = -1;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const std::string path = json_path_index("frames", f);
        const auto number = frames[f]["frame"].get<long long>();
        if (number <= previous)
            throw InputError(json_path_child(path, "frame"), "frame " + std::to_string(number) + " comes after frame " +
                                                                 std::to_string(previous) +
                                                                 ": frames are listed in increasing order, each once");
        if (number < first || number > last)
            throw InputError(json_path_child(path, "frame"),
                             "frame " + std::to_string(number) + " is outside the recording's frames " +
                                 std::to_string(first) + ".." + (open_ended ? "" : std::to_string(last)));
        previous = number;

        const json& contacts = frames[f]["contacts"];
        const auto contact_count = frames[f]["contact_count"].get<std::size_t>();
        long long previous_contact = -1;
        for (std::size_t k = 0; k < contacts.size(); ++k) {
            const std::string at = json_path_child(json_path_index(json_path_child(path, "contacts"), k), "contact");
            const auto contact = contacts[k]["contact"].get<long long>();
            if (contact <= previous_contact)
                throw InputError(at, "contact " + std::to_string(contact) + " comes after contact " +
                                         std::to_string(previous_contact) +
                                         ": contacts are listed in increasing order, each once");
            if (!filter.is_null() && std::find(filter.begin(), filter.end(), contacts[k]["contact"]) == filter.end())
                throw InputError(at, "contact " + std::to_string(contact) +
                                         " is not one of the contacts the recording keeps (recording.contacts)");
            previous_contact = contact;
        }
        if (filter.is_null() && contacts.size() != contact_count)
            throw InputError(json_path_child(path, "contacts"),
                             "lists " + count_text(contacts.size(), "contact", "contacts") + ", but contact_count is " +
                                 std::to_string(contact_count) + " and the recording keeps every contact");

        const json& phases = frames[f]["phases"];
        for (std::size_t p = 0; p < phases.size(); ++p) {
            const std::string phase_path = json_path_index(json_path_child(path, "phases"), p);
            const json& phase = phases[p];
            const json& iterations = phase["iterations"];
            const auto used = phase["iterations_used"].get<long long>();
            if (used != static_cast<long long>(iterations.size()))
                throw InputError(json_path_child(phase_path, "iterations_used"),
                                 "is " + std::to_string(used) + ", but the phase lists " +
                                     count_text(iterations.size(), "iteration", "iterations"));
            if (!phase["iteration_limit"].is_null() && used > phase["iteration_limit"].get<long long>())
                throw InputError(json_path_child(phase_path, "iterations_used"),
                                 "is " + std::to_string(used) + ", more than its iteration_limit " +
                                     phase["iteration_limit"].dump());
            for (std::size_t i = 0; i < iterations.size(); ++i)
                if (iterations[i]["iteration"].get<long long>() != static_cast<long long>(i))
                    throw InputError(
                        json_path_child(json_path_index(json_path_child(phase_path, "iterations"), i), "iteration"),
                        "must be " + std::to_string(i) + " (iterations are numbered in order from 0), got " +
                            iterations[i]["iteration"].dump());
        }
    }
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
