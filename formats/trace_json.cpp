#include "formats/trace_json.hpp"

#include "formats/trace_items_json.hpp"
#include "formats/trace_checks.hpp"
#include "formats/trace_format1.hpp"

#include "formats/scene_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/schemas.hpp"
#include "formats/settings_json.hpp"
#include "formats/settings_names.hpp"

#include <utility>

namespace impulse::formats {

namespace {

constexpr std::string_view stop_names[] = {"resolved", "iteration_limit", "passes_complete", "unmovable_left",
                                           "sweeps_complete"};

// --- phases and frames ----------------------------------------------------------------------------------

template <typename Iteration, typename Write>
json phase_json(std::string_view phase, std::string_view method, const PhaseLog<Iteration>& log, Write write) {
    json iterations = json::array();
    for (const Iteration& it : log.iterations) iterations.push_back(write(it));
    return {{"phase", phase},
            {"method", method},
            {"iteration_limit", log.outcome.iteration_limit},
            {"iterations_used", log.outcome.iterations_used},
            {"stop", stop_names[static_cast<int>(log.outcome.stop)]},
            {"iterations", iterations}};
}

template <typename Iteration, typename Read>
PhaseLog<Iteration> read_phase(const json& j, Read read) {
    PhaseLog<Iteration> log;
    log.outcome.iteration_limit = j["iteration_limit"].get<int>();
    log.outcome.iterations_used = j["iterations_used"].get<int>();
    const std::string stop = j["stop"].get<std::string>();
    for (int i = 0; i < static_cast<int>(std::size(stop_names)); ++i)
        if (stop_names[i] == stop) log.outcome.stop = static_cast<StopReason>(i);
    for (const json& it : j["iterations"]) log.iterations.push_back(read(it));
    return log;
}

json body_state_json(const BodyState& s) {
    return {{"position", vec3_json(s.position)},
            {"orientation", quat_json(s.orientation)},
            {"velocity", vec3_json(s.velocity)},
            {"angular_velocity", vec3_json(s.angular_velocity)}};
}

BodyState read_body_state(const json& j) {
    return {read_vec3(j["position"]), read_quat(j["orientation"]), read_vec3(j["velocity"]),
            read_vec3(j["angular_velocity"])};
}

json frame_json(const FrameRecord& f, const ResolverSettings& settings) {
    json before = json::array();
    for (std::size_t i = 0; i < f.bodies_before.size(); ++i) {
        json body = body_state_json(f.bodies_before[i]);
        body["inverse_inertia_world"] = mat3_json(f.inverse_inertia_world[i]);
        before.push_back(body);
    }
    json contacts = json::array();
    for (const ContactPreparation& c : f.contacts) contacts.push_back(item_json(c));
    const json position = phase_json("position", name_of(position_method_names, position_method_in_effect(settings)),
                                     f.position, [](const PositionIteration& it) { return item_json(it); });
    const json velocity = phase_json("velocity", name_of(velocity_method_names, settings.velocity_method), f.velocity,
                                     [](const VelocityIteration& it) { return item_json(it); });
    json after = json::array();
    for (const BodyState& s : f.bodies_after) after.push_back(body_state_json(s));
    const bool positions_first = f.phase_order == PhaseOrder::positions_first;
    return {{"frame", f.frame},
            {"phase_order", name_of(phase_order_names, f.phase_order)},
            {"bodies_before", before},
            {"contact_count", f.contact_count},
            {"contacts", contacts},
            {"phases", positions_first ? json::array({position, velocity}) : json::array({velocity, position})},
            {"bodies_after", after}};
}

FrameRecord read_frame(const json& j) {
    FrameRecord f;
    f.frame = j["frame"].get<int>();
    f.phase_order = *value_of(phase_order_names, j["phase_order"].get<std::string>());  // the schema checked it
    f.contact_count = j["contact_count"].get<int>();
    for (const json& body : j["bodies_before"]) {
        f.bodies_before.push_back(read_body_state(body));
        f.inverse_inertia_world.push_back(read_mat3(body["inverse_inertia_world"]));
    }
    for (const json& c : j["contacts"]) f.contacts.push_back(read_preparation(c));
    for (const json& phase : j["phases"]) {
        if (phase["phase"] == "position") {
            f.position = read_phase<PositionIteration>(phase, read_position_iteration);
            // A trace written before the split impulse's slop had its word (format 1, and format 2 until then) keeps
            // it as the iteration's epsilon: read it as the slop it is.
            if (phase["method"] == name_of(position_method_names, PositionMethod::split_impulse))
                for (PositionIteration& it : f.position.iterations)
                    if (!it.slop) it.slop = std::exchange(it.epsilon, 0.0);
        } else
            f.velocity = read_phase<VelocityIteration>(phase, read_velocity_iteration);
    }
    for (const json& body : j["bodies_after"]) f.bodies_after.push_back(read_body_state(body));
    return f;
}

json conventions_json() {
    return {
        {"units", "SI: m, kg, s, rad"},
        {"axes", "right-handed, +y up"},
        {"vector", "[x, y, z]"},
        {"quaternion", "[w, x, y, z], unit, body to world"},
        {"matrix", "row-major [[row0], [row1], [row2]]"},
        {"normal", "from body 1 towards body 0: the direction body 0 must move to separate"},
        {"penetration", "> 0 when the bodies overlap"},
        {"basis", "columns (normal, tangent1, tangent2): contact to world; its transpose maps world to contact"},
        {"tangent_construction",
         "tangent1 = normalise(world Y x n) if |n.x| > |n.y|, else normalise(world X x n); tangent2 = n x tangent1"},
        {"relative_position", "contact point minus body position, world"},
        {"contact_velocity", "body 0's contact point velocity minus body 1's, contact coordinates; x < 0 = closing"},
        {"desired_delta_velocity", "> 0 pushes body 0 along +normal"},
        {"impulse", "+impulse_world on body 0, -impulse_world on body 1"},
        {"per_body", "[body0, body1], null for the world"},
    };
}

}  // namespace

json trace_json(const Trace& trace) {
    json frames = json::array();
    for (const FrameRecord& f : trace.frames) frames.push_back(frame_json(f, trace.scene.settings));
    json document = trace_header_json(trace);
    document["frames"] = std::move(frames);
    return document;
}

std::string trace_head_text(const Trace& trace) {
    // The header as format_json writes a whole trace with no frames, cut before its empty frame list.
    json document = trace_header_json(trace);
    document["frames"] = json::array();
    std::string text = format_json(document);
    text.resize(text.size() - trace_no_frames.size());
    return text;
}

std::string trace_frame_text(const FrameRecord& frame, const ResolverSettings& settings) {
    std::string text;
    append_json(frame_json(frame, settings), 2, text);  // an element of "frames": two levels deep
    return text;
}

json trace_header_json(const Trace& trace) {
    const TraceFilter& r = trace.recording;
    return {{"format", trace_format_name},
            {"version", trace_format_version},
            {"conventions", conventions_json()},
            {"settings", settings_json(trace.scene.settings, trace.scene.world)},
            {"recording",
             {{"first_frame", r.first_frame},
              {"last_frame", r.last_frame == INT_MAX ? json(nullptr) : json(r.last_frame)},
              {"contacts", r.contacts ? json(*r.contacts) : json(nullptr)}}},
            {"scene", scene_json(trace.scene, false)}};
}

Trace read_trace(const json& given) {
    if (given.is_object() && given.contains("settings")) refuse_renamed_settings(given["settings"], "settings");
    json upgraded;
    const json* read = &given;
    if (given.is_object() && given.contains("version") && given["version"] == 1) {
        upgraded = given;
        upgrade_trace_document(upgraded);
        read = &upgraded;
    }
    const json& document = *read;
    validate_trace_document(document);
    Trace trace;
    trace.version = given["version"].get<int>();
    try {
        trace.scene = read_scene(document["scene"]);
    } catch (const InputError& e) {
        throw InputError(e.where().empty() ? "scene" : "scene." + e.where(), e.problem());
    }
    read_settings(trace.scene, &document["settings"], "settings");
    const json& r = document["recording"];
    trace.recording.first_frame = r["first_frame"].get<int>();
    trace.recording.last_frame = r["last_frame"].is_null() ? INT_MAX : r["last_frame"].get<int>();
    if (!r["contacts"].is_null()) trace.recording.contacts = r["contacts"].get<std::vector<int>>();
    check_counts(document);
    const json& frames = document["frames"];
    for (std::size_t i = 0; i < frames.size(); ++i) {
        check_references(frames[i], json_path_index("frames", i), trace.scene.bodies.size());
        trace.frames.push_back(read_frame(frames[i]));
        check_frame_values(trace.frames.back(), json_path_index("frames", i));
    }
    return trace;
}

Trace read_trace_text(std::string_view text) {
    return read_trace(parse_json_text(text));
}

}  // namespace impulse::formats
