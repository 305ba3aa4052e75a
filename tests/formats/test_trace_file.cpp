// Trace files: written, read back and equal value for value; the written file passes its schema; keys are
// the derivation vocabulary; indices that point nowhere are rejected.

#include "formats/scene_file.hpp"
#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/settings_json.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "resolver/resolver.hpp"
#include "support/shipped.hpp"
#include "world/world.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <sstream>

using namespace impulse;

namespace {

Trace resolved(const Scene& c, const std::vector<std::string>& settings = {}) {
    Trace trace;
    trace.scene = c;
    for (const std::string& s : settings) formats::apply_setting(trace.scene, s, "--set");
    std::vector<RigidBody> bodies = c.bodies;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, trace.scene.contacts, trace.scene.settings, recorder);
    return trace;
}

std::string written(const Trace& t) {
    return formats::format_json(formats::trace_json(t));
}

}  // namespace

TEST_CASE("a trace written and read back is equal to the last bit, for every method and impulse model") {
    const std::vector<std::pair<std::string, std::vector<std::string>>> runs{
        {"ruler", {}},
        {"sphere_ground", {"preset=chapter"}},
        {"three_objects", {}},  // a swapped contact
        {"two_body_oblique", {"position_method=linear_projection"}},
        {"sliding_box", {}},  // friction: static and sliding solves
        {"deep_corner", {"position_method=velocity_based"}},
        {"deep_corner", {"position_method=relaxation", "relaxation.passes=3"}},
        {"deep_corner", {"angular_limit.policy=none"}},
        {"deep_corner", {"angular_limit.policy=angle", "orientation_update=exact"}},
        {"three_objects", {"preset=sweep"}},                                          // sweep places
        {"sliding_box", {"preset=pgs"}},                                              // accumulated, clamps, bias
        {"deep_corner", {"preset=pgs_split"}},                                        // split-impulse pushes
        {"deep_corner", {"preset=sweep", "position_method=none", "baumgarte=true"}},  // bias under the book's impulse
    };
    for (const auto& [name, settings] : runs) {
        const auto& case_name = name;  // clang 14 cannot capture a structured binding in CAPTURE's lambda
        CAPTURE(case_name);
        const Trace trace = resolved(test::shipped("cases/" + name), settings);
        const std::string text = written(trace);
        const Trace again = formats::read_trace_text(text);  // also checks the schema
        CHECK(again == trace);
        CHECK(written(again) == text);
    }
}

TEST_CASE("a contact whose bodies are touched at two points (recycled) round-trips with body 1's point") {
    Scene scene = test::shipped("cases/two_body_oblique");
    Contact& contact = scene.contacts.front();
    contact.body1_point = contact.point + Vec3(0.002, -0.001, 0.0);  // the anchors a recycled contact keeps
    Trace trace = resolved(scene);
    // The world makes recycled contacts, a scene or case file never holds one: the trace's scene is as read.
    trace.scene.contacts.front().body1_point.reset();
    const ContactPreparation& record = trace.frames.front().contacts.front();
    REQUIRE(record.body1_point);
    const Vec3 centre = scene.bodies[static_cast<std::size_t>(record.bodies[1])].position;
    CHECK(*record.relative_position[1] == *record.body1_point - centre);
    const formats::json j = formats::trace_json(trace);
    const formats::json& written_contact = j["frames"][0]["contacts"][0];
    CHECK(std::next(written_contact.find("point")).key() == "body1_point");  // beside the point, in step order
    CHECK(formats::read_trace_text(written(trace)) == trace);
}

TEST_CASE("a filtered trace round-trips with its filter") {
    Trace trace;
    trace.scene = test::shipped("cases/sliding_box");
    trace.recording.contacts = std::vector<int>{2};
    std::vector<RigidBody> bodies = trace.scene.bodies;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, trace.scene.contacts, trace.scene.settings, recorder);
    CHECK(formats::read_trace_text(written(trace)) == trace);
}

TEST_CASE("a contact's keys in the trace are the derivation vocabulary, in the order of the steps") {
    const formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
    std::vector<std::string> keys;
    for (const auto& [key, value] : j["frames"][0]["contacts"][0].items()) keys.push_back(key);
    const std::vector<std::string> expected{"contact",
                                            "bodies",
                                            "swapped",
                                            "inert",
                                            "point",
                                            "normal",
                                            "penetration",
                                            "restitution",
                                            "friction",
                                            "origin",
                                            "basis",
                                            "tangent_seed",
                                            "relative_position",
                                            "torque_per_unit_impulse",
                                            "rotation_per_unit_impulse",
                                            "point_velocity_per_unit_impulse",
                                            "angular_component",
                                            "linear_component",
                                            "delta_velocity_per_unit_impulse",
                                            "point_velocity",
                                            "tangential_acceleration_velocity",
                                            "contact_velocity",
                                            "separating_velocity",
                                            "restitution_cutoff",
                                            "restitution_cutoff_applied",
                                            "restitution_used",
                                            "velocity_from_acceleration_applied",
                                            "velocity_from_acceleration",
                                            "desired_delta_velocity"};
    CHECK(keys == expected);
    const formats::json& position = j["frames"][0]["phases"][0]["iterations"][0];
    for (const char* key : {"linear_inertia", "angular_inertia", "penetration_inertia", "move_split", "angular_limit",
                            "position_change", "updates"})
        CHECK_MESSAGE(position.contains(key), key);
    const formats::json& velocity = j["frames"][0]["phases"][1]["iterations"][0];
    for (const char* key : {"contact_velocity", "desired_delta_velocity", "impulse", "impulse_world", "velocity_change",
                            "rotation_change", "updates"})
        CHECK_MESSAGE(velocity.contains(key), key);
}

TEST_CASE("the header says what ran: format, version, conventions, full settings and the scene") {
    const formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
    CHECK(j["format"] == "impulse-lab-trace");
    CHECK(j["version"] == 2);
    CHECK(j["conventions"]["quaternion"] == "[w, x, y, z], unit, body to world");
    CHECK(j["settings"] == formats::settings_json(*preset("book"), WorldSettings{}));
    CHECK(j["scene"]["bodies"][0]["name"] == "ruler");
    CHECK(j["scene"]["bodies"][0].contains("inverse_inertia"));
}

TEST_CASE("a trace whose indices point outside its scene is rejected with the path") {
    formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
    j["frames"][0]["phases"][1]["iterations"][0]["contact"] = 5;
    try {
        formats::read_trace(j);
        FAIL("accepted a trace with an iteration on contact 5");
    } catch (const formats::InputError& e) {
        CHECK(std::string(e.what()) ==
              "frames[0].phases[1].iterations[0].contact: no contact 5 in this frame (it has 1)");
    }
}

TEST_CASE("a trace from a future format version is refused") {
    formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
    j["version"] = 3;
    CHECK_THROWS_WITH_AS(formats::read_trace(j), "version: must be 2, got 3", formats::InputError);
}

TEST_CASE("a misspelt derivation key in a trace is named with its path") {
    formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
    formats::json& contact = j["frames"][0]["contacts"][0];
    contact["relative_positon"] = contact["relative_position"];
    contact.erase("relative_position");
    CHECK_THROWS_WITH_AS(formats::read_trace(j),
                         "frames[0].contacts[0].relative_positon: unknown field (did you mean \"relative_position\"?)",
                         formats::InputError);
}

TEST_CASE("a trace whose states or records cannot describe a body or a contact is rejected with the path") {
    struct Broken {
        const char* what;
        std::function<void(formats::json&)> change;
        std::string message;
    };
    const std::vector<Broken> table{
        {"a quaternion of length 2 before",
         [](formats::json& f) {
             f["bodies_before"][0]["orientation"] = {2, 0, 0, 0};
         },
         "frames[0].bodies_before[0].orientation: must be a unit quaternion [w, x, y, z] (length 1 within 1e-6), got "
         "length 2"},
        {"a zero quaternion after",
         [](formats::json& f) {
             f["bodies_after"][0]["orientation"] = {0, 0, 0, 0};
         },
         "frames[0].bodies_after[0].orientation: must be a unit quaternion [w, x, y, z] (length 1 within 1e-6), got "
         "length 0"},
        {"an inverse inertia that is not symmetric",
         [](formats::json& f) { f["bodies_before"][0]["inverse_inertia_world"][0][1] = 1.0; },
         "frames[0].bodies_before[0].inverse_inertia_world: must be symmetric (row i, column j equal to row j, column "
         "i)"},
        {"a negative inverse inertia",
         [](formats::json& f) {
             f["bodies_before"][0]["inverse_inertia_world"] = {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
         },
         "frames[0].bodies_before[0].inverse_inertia_world: must be positive semi-definite (zero = cannot rotate), "
         "but its eigenvalues are -1, 1, 1"},
        {"a zero normal",
         [](formats::json& f) {
             f["contacts"][0]["normal"] = {0, 0, 0};
         },
         "frames[0].contacts[0].normal: must be a unit vector (length 1 within 1e-6), got length 0"},
        {"a basis that is not a rotation",
         [](formats::json& f) {
             f["contacts"][0]["basis"] = {{1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
         },
         "frames[0].contacts[0].basis: must have unit columns at right angles (within 1e-6); its columns' dot "
         "products are off by up to 1"},
    };
    for (const Broken& b : table) {
        CAPTURE(b.what);
        formats::json j = formats::trace_json(resolved(test::shipped("cases/ruler")));
        b.change(j["frames"][0]);
        CHECK_THROWS_WITH_AS(formats::read_trace(j), b.message.c_str(), formats::InputError);
    }
}

TEST_CASE("the recorder's size estimate stays within a third of the written trace for every shipped scene and preset") {
    // --max-trace-mb bounds the recording by this estimate, so the bound holds to within this factor. Cases are
    // resolved once; scenes run three frames; a filtered recording checks the estimate of the lines of iterations
    // on contacts outside the set. With pyramid_10 and brick_wall too (left out for time) it ran from 0.91 to 1.29.
    const char* const scenes[] = {
        "cases/ruler", "cases/three_objects", "cases/corner_hit", "cases/sliding_box", "stack_3",        "stack_10",
        "box_tipping", "sphere_drop",         "two_spheres",      "spinning_box",      "mass_ratio_100", "deep_plank"};
    for (const char* name : scenes)
        for (const std::string_view preset : preset_names())
            for (const bool filtered : {false, true}) {
                CAPTURE(name);
                CAPTURE(preset);
                CAPTURE(filtered);
                std::ifstream in(IMPULSE_SOURCE_DIR "/scenes/" + std::string(name) + ".json");
                std::stringstream text;
                text << in.rdbuf();
                Trace trace;
                trace.scene = formats::read_scene_text(text.str(), std::string(preset));
                if (filtered) trace.recording.contacts = std::vector<int>{0, 1};
                std::vector<RigidBody> bodies = trace.scene.bodies;
                TraceRecorder recorder(trace, SIZE_MAX);
                if (!trace.scene.contacts.empty()) {
                    resolve_contacts(bodies, trace.scene.contacts, trace.scene.settings, recorder);
                } else {
                    trace.scene.world.frames = 3;
                    World world(trace.scene);
                    for (int frame = 0; frame < trace.scene.world.frames; ++frame) world.step(recorder);
                }
                const double written = static_cast<double>(formats::format_json(formats::trace_json(trace)).size());
                const double ratio = static_cast<double>(recorder.estimated_bytes()) / written;
                CHECK(ratio > 0.75);
                CHECK(ratio < 1.33);
            }
}

TEST_CASE("a trace written in parts, frame by frame, is byte for byte the trace written whole") {
    // `run` streams its trace (head, each frame's text, end) so that its frames need not stay in memory.
    Trace trace;
    trace.scene = test::shipped("stack_3");
    const auto parts = [](const Trace& t) {
        if (t.frames.empty()) return formats::trace_head_text(t) + std::string(formats::trace_no_frames);
        std::string text = formats::trace_head_text(t);
        for (std::size_t f = 0; f < t.frames.size(); ++f) {
            text += f == 0 ? formats::trace_frames_open : formats::trace_frames_between;
            text += formats::trace_frame_text(t.frames[f], t.scene.settings);
        }
        return text + std::string(formats::trace_frames_close);
    };
    CHECK(parts(trace) == formats::format_json(formats::trace_json(trace)));
    World world(trace.scene);
    TraceRecorder recorder(trace);
    for (int frame = 0; frame < 3; ++frame) {
        world.step(recorder);
        CHECK(parts(trace) == formats::format_json(formats::trace_json(trace)));
    }
}
