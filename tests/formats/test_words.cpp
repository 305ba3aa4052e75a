// The word list (formats/words.hpp) against everything that spells its words: the committed JSON Schema
// (every key in both, of the same kind), the keys and kinds a trace writes, the committed docs, and format 1's
// traces, which still open with the renames.

#include "formats/input_error.hpp"
#include "formats/json_text.hpp"
#include "formats/scene_file.hpp"
#include "formats/schemas.hpp"
#include "formats/trace_docs.hpp"
#include "formats/trace_format1.hpp"
#include "formats/trace_json.hpp"
#include "record/trace_recorder.hpp"
#include "formats/words.hpp"
#include "resolver/resolver.hpp"
#include "formats/settings_names.hpp"
#include "settings/settings.hpp"
#include "formats/settings_json.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace impulse;

namespace {

std::string file_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

using KeyKinds = std::map<std::string, formats::words::Kind>;

// The kind the schema gives a property: its $ref's definition, or its type.
formats::words::Kind schema_kind(const formats::json& property) {
    if (property.contains("$ref")) {
        const std::string ref = property["$ref"].get<std::string>();
        const std::string name = ref.substr(ref.rfind('/') + 1);
        if (name == "vec3") return formats::words::Kind::vec3;
        if (name == "vec2") return formats::words::Kind::vec2;
        if (name == "mat3") return formats::words::Kind::mat3;
        if (name == "vec6") return formats::words::Kind::vec6;
        if (name == "mat6") return formats::words::Kind::mat6;
        if (name.starts_with("per_body_vec3")) return formats::words::Kind::per_body_vec3;
        if (name.starts_with("per_body_number")) return formats::words::Kind::per_body_number;
        if (name == "per_body_bool") return formats::words::Kind::per_body_bool;
        return formats::words::Kind::object;  // rewind, angular_limit, friction_solve, origin: objects of words
    }
    if (property.contains("enum")) {
        const formats::json& first = property["enum"][0];
        return first.is_string()    ? formats::words::Kind::word
               : first.is_boolean() ? formats::words::Kind::boolean
                                    : formats::words::Kind::integer;
    }
    const formats::json& type = property["type"];
    if (type == "integer") return formats::words::Kind::integer;
    if (type == "number") return formats::words::Kind::number;
    if (type == "boolean") return formats::words::Kind::boolean;
    if (type == "string") return formats::words::Kind::word;
    if (type == "object") return formats::words::Kind::object;
    if (type == "array") {
        const formats::json& items = property.contains("items") ? property["items"] : formats::json();
        if (items.contains("$ref") || items.contains("type")) {
            const bool objects = items.contains("$ref") || items["type"] == "object";
            if (objects) return formats::words::Kind::list;
        }
        return formats::words::Kind::bodies;  // [body_index, body_index]
    }
    return formats::words::Kind::none;
}

const formats::json& resolved(const formats::json& schema, const formats::json& property) {
    if (!property.contains("$ref")) return property;
    const std::string ref = property["$ref"].get<std::string>();
    return schema["$defs"][ref.substr(ref.rfind('/') + 1)];
}

// Every key of an item's schema, nested ones by their path ("rewind.time", "updates[].after").
void schema_keys(const formats::json& schema, const formats::json& object, const std::string& prefix, KeyKinds& out) {
    for (const auto& [key, property] : object["properties"].items()) {
        const std::string path = prefix + key;
        const formats::words::Kind kind = schema_kind(property);
        out[path] = kind;
        if (kind == formats::words::Kind::object) schema_keys(schema, resolved(schema, property), path + ".", out);
        if (kind == formats::words::Kind::list)
            schema_keys(schema, resolved(schema, property["items"]), path + "[].", out);
    }
}

KeyKinds word_keys(char item) {
    KeyKinds out;
    for (const formats::words::Word& w : formats::words::all())
        if (formats::words::held_by(w, item) && w.kind != formats::words::Kind::none)
            out[std::string(w.quantity)] = w.kind;
    return out;
}

// The kind of a written value, as the word list names kinds (per body: two elements, one maybe null).
bool value_is(const formats::json& v, formats::words::Kind kind) {
    const auto vec = [](const formats::json& x, std::size_t n) {
        return x.is_array() && x.size() == n &&
               std::all_of(x.begin(), x.end(), [](const formats::json& e) { return e.is_number(); });
    };
    const auto per_body = [&v](auto element) {
        return v.is_array() && v.size() == 2 &&
               std::all_of(v.begin(), v.end(), [&](const formats::json& e) { return e.is_null() || element(e); });
    };
    switch (kind) {
        case formats::words::Kind::integer:
            return v.is_number_integer();
        case formats::words::Kind::number:
            return v.is_number();
        case formats::words::Kind::boolean:
            return v.is_boolean();
        case formats::words::Kind::word:
            return v.is_string();
        case formats::words::Kind::vec2:
            return vec(v, 2);
        case formats::words::Kind::vec3:
            return vec(v, 3);
        case formats::words::Kind::mat3:
            return v.is_array() && v.size() == 3 &&
                   std::all_of(v.begin(), v.end(), [&](const formats::json& r) { return vec(r, 3); });
        case formats::words::Kind::vec6:
            return vec(v, 6);
        case formats::words::Kind::mat6:
            return v.is_array() && v.size() == 6 &&
                   std::all_of(v.begin(), v.end(), [&](const formats::json& r) { return vec(r, 6); });
        case formats::words::Kind::per_body_number:
            return per_body([](const formats::json& e) { return e.is_number(); });
        case formats::words::Kind::per_body_vec3:
            return per_body([&](const formats::json& e) { return vec(e, 3); });
        case formats::words::Kind::per_body_bool:
            return per_body([](const formats::json& e) { return e.is_boolean(); });
        case formats::words::Kind::bodies:
            return per_body([](const formats::json& e) { return e.is_number_integer(); });
        case formats::words::Kind::object:
            return v.is_object();
        case formats::words::Kind::list:
            return v.is_array();
        case formats::words::Kind::none:
            return false;
    }
    return false;
}

void check_item(const formats::json& item, char kind, const std::string& prefix, std::set<std::string>& seen) {
    for (const auto& [key, value] : item.items()) {
        const std::string path = prefix + key;
        const formats::words::Word* w = formats::words::find(path, kind);
        CAPTURE(kind);
        CAPTURE(path);
        REQUIRE(w != nullptr);
        CHECK(value_is(value, w->kind));
        seen.insert(path);
        if (w->kind == formats::words::Kind::object) check_item(value, kind, path + ".", seen);
        if (w->kind == formats::words::Kind::list)
            for (const formats::json& element : value) check_item(element, kind, path + "[].", seen);
    }
}

Trace resolved_case(const std::string& name, const std::string& preset, const std::vector<std::string>& set = {}) {
    Trace trace;
    trace.scene = formats::read_scene(
        formats::parse_json_text(file_text(IMPULSE_SOURCE_DIR "/scenes/" + name + ".json")), preset);
    for (const std::string& s : set) formats::apply_setting(trace.scene, s, "--set");
    std::vector<RigidBody> bodies = trace.scene.bodies;
    TraceRecorder recorder(trace);
    resolve_contacts(bodies, trace.scene.contacts, trace.scene.settings, recorder);
    return trace;
}

}  // namespace

TEST_CASE("the committed trace schema and the word list name the same keys, of the same kinds") {
    const formats::json schema = formats::parse_json_text(file_text(IMPULSE_SOURCE_DIR "/schemas/trace.schema.json"));
    CHECK(schema["properties"]["version"]["const"] == trace_format_version);
    for (const auto& entry :
         {std::pair{'C', "contact"}, std::pair{'P', "position_iteration"}, std::pair{'V', "velocity_iteration"}}) {
        const char item = entry.first;  // (clang 14 cannot CAPTURE a structured binding)
        const char* const definition = entry.second;
        KeyKinds in_schema;
        schema_keys(schema, schema["$defs"][definition], "", in_schema);
        const KeyKinds in_words = word_keys(item);
        CAPTURE(item);
        for (const auto& key_kind : in_schema) {
            const auto& key = key_kind.first;
            const auto& kind = key_kind.second;
            CAPTURE(key);
            REQUIRE(in_words.count(key) == 1);
            CHECK(static_cast<int>(in_words.at(key)) == static_cast<int>(kind));
        }
        for (const auto& key_kind : in_words) {
            const auto& key = key_kind.first;
            CAPTURE(key);
            CHECK(in_schema.count(key) == 1);
        }
    }
}

namespace {

// A method table's names in its order, as a schema's enum spells them (`skip`: a name the enum leaves out).
template <typename Table>
formats::json names_in_schema_order(const Table& names, std::string_view skip = {}) {
    formats::json list = formats::json::array();
    for (const auto& entry : names)
        if (entry.second != skip) list.push_back(std::string(entry.second));
    return list;
}

}  // namespace

TEST_CASE("the schemas take the method table's methods, in its order, and the committed ones name none by hand") {
    const formats::json scene = formats::scene_schema();
    const formats::json trace = formats::trace_schema();
    const formats::json positions = names_in_schema_order(formats::position_method_names);
    const formats::json velocities = names_in_schema_order(formats::velocity_method_names);
    const formats::json& settings = scene["$defs"]["settings"]["properties"];
    CHECK(settings["position_method"]["enum"] == positions);
    CHECK(settings["velocity_method"]["enum"] == velocities);
    CHECK(trace["$defs"]["position_phase"]["properties"]["method"]["enum"] == positions);
    CHECK(trace["$defs"]["velocity_phase"]["properties"]["method"]["enum"] == velocities);
    // A position iteration is made by a method that iterates: every one but `none`.
    CHECK(trace["$defs"]["position_iteration"]["properties"]["method"]["enum"] ==
          names_in_schema_order(formats::position_method_names, "none"));
    // The committed files leave the names to the table: a new method is its file and its row, not a schema edit.
    for (const char* file : {"/schemas/scene.schema.json", "/schemas/trace.schema.json"}) {
        CAPTURE(file);
        const std::string text = file_text(IMPULSE_SOURCE_DIR + std::string(file));
        CHECK(text.find("\"projected_gauss_seidel\"") == std::string::npos);
        CHECK(text.find("\"nonlinear_projection\"") == std::string::npos);
    }
}

TEST_CASE("every key a trace writes is a word of its item, its value of the word's kind") {
    std::set<std::string> seen;
    for (const std::string& name : {std::string("cases/ruler"), std::string("cases/sliding_box"),
                                    std::string("cases/tilted_box"), std::string("cases/oblique_friction")})
        for (std::string_view preset : preset_names())
            for (const std::vector<std::string>& set :
                 {std::vector<std::string>{}, std::vector<std::string>{"position_method=velocity_based"}}) {
                const formats::json document = formats::trace_json(resolved_case(name, std::string(preset), set));
                for (const formats::json& frame : document["frames"]) {
                    for (const formats::json& contact : frame["contacts"]) check_item(contact, 'C', "", seen);
                    for (const formats::json& phase : frame["phases"])
                        for (const formats::json& it : phase["iterations"])
                            check_item(it, phase["phase"] == "position" ? 'P' : 'V', "", seen);
                }
            }
    CHECK(seen.count("push_impulse") == 1);  // split impulse ran
    CHECK(seen.count("rewind.time") == 1);   // velocity-based ran
}

TEST_CASE("every word's inputs are words, and a step's name is a word of the item it belongs to") {
    for (const formats::words::Word& w : formats::words::all()) {
        CAPTURE(w.quantity);
        CHECK_FALSE(w.step.empty());
        std::string_view rest = w.inputs;
        while (!rest.empty()) {
            const std::size_t space = rest.find(' ');
            const std::string_view input = rest.substr(0, space);
            CAPTURE(input);
            CHECK(formats::words::find(input) != nullptr);
            if (space == std::string_view::npos) break;
            rest.remove_prefix(space + 1);
        }
    }
    for (std::string_view step :
         {formats::words::step::basis, formats::words::step::relative_position,
          formats::words::step::delta_velocity_per_unit_impulse, formats::words::step::contact_velocity,
          formats::words::step::desired_delta_velocity, formats::words::step::accumulated,
          formats::words::step::impulse, formats::words::step::velocity_change, formats::words::step::rewind,
          formats::words::step::penetration_inertia, formats::words::step::move_split,
          formats::words::step::position_change, formats::words::step::updates}) {
        CAPTURE(step);
        const formats::words::Word* w = formats::words::find(step);
        REQUIRE(w != nullptr);
        CHECK(w->kind != formats::words::Kind::none);  // stored: the trace has a key of the step's name
    }
}

TEST_CASE("docs/trace-format.md lists the words as the word list has them") {
    // IMPULSE_WRITE_DOCS=1 impulse_formats_tests -tc='docs/trace-format.md*' writes the section from the list.
    const std::string path = IMPULSE_SOURCE_DIR "/docs/trace-format.md";
    const std::string committed = file_text(path);
    const std::string generated = formats::with_trace_word_docs(committed, formats::trace_word_docs());
    if (generated != committed && std::getenv("IMPULSE_WRITE_DOCS")) {
        std::ofstream(path, std::ios::binary) << generated;
        MESSAGE("wrote the word tables of " << path);
        return;
    }
    REQUIRE(committed.find(formats::trace_docs_begin) != std::string::npos);
    CHECK_MESSAGE(generated == committed,
                  "docs/trace-format.md's word tables differ from formats/word_table.hpp; regenerate them with "
                  "IMPULSE_WRITE_DOCS=1 impulse_formats_tests -tc='docs/trace-format.md*'");
}

namespace {

// A committed trace of format 1 (tests/data/format1, written by the last format-1 build) and the same run today.
struct Format1Pair {
    formats::json old_document;
    Trace read;     // the format-1 file read
    Trace current;  // the same case and settings resolved now
};

Format1Pair format1_pair(const std::string& file, const std::string& name, const std::string& preset,
                         const std::vector<std::string>& set = {}) {
    Format1Pair pair;
    pair.old_document = formats::parse_json_text(file_text(IMPULSE_SOURCE_DIR "/tests/data/format1/" + file));
    pair.read = formats::read_trace(pair.old_document);
    pair.current = resolved_case(name, preset, set);
    return pair;
}

}  // namespace

TEST_CASE("a format-1 trace opens: every value where format 2 keeps it, and the version says it was format 1") {
    // tilted_box with velocity-based resolution: the rewind, the angular limit, the move split and the position
    // change of format 1's flat keys (linear_move, total_inertia, linear_change ...), and an impulse_contact.
    const Format1Pair velocity_based = format1_pair("tilted_box.velocity_based.trace.json", "cases/tilted_box", "book",
                                                    {"position_method=velocity_based"});
    CHECK(velocity_based.old_document["version"] == 1);
    CHECK(velocity_based.read.version == 1);
    CHECK(velocity_based.read.frames == velocity_based.current.frames);
    // Written again, it is format 2, key for key what today's run writes.
    CHECK(formats::trace_json(velocity_based.read) == formats::trace_json(velocity_based.current));

    // The split impulse's push was `amount` in format 1: it is read as push_impulse, in N·s.
    const Format1Pair split = format1_pair("tilted_box.pgs_split.trace.json", "cases/tilted_box", "pgs_split");
    CHECK(split.read.frames == split.current.frames);
    CHECK(formats::trace_json(split.read) == formats::trace_json(split.current));
    const formats::json upgraded = formats::trace_json(split.read);
    bool pushed = false;
    for (const formats::json& phase : upgraded["frames"][0]["phases"])
        for (const formats::json& it : phase["iterations"])
            if (it.contains("method") && it["method"] == "split_impulse") {
                CHECK(it.contains("push_impulse"));
                CHECK_FALSE(it.contains("amount"));
                pushed = true;
            }
    CHECK(pushed);
}

TEST_CASE("upgrading a format-1 document moves exactly the renamed keys and sets the version") {
    formats::json document = formats::parse_json_text(
        file_text(IMPULSE_SOURCE_DIR "/tests/data/format1/tilted_box.velocity_based.trace.json"));
    const formats::json& old_position = document["frames"][0]["phases"][0]["iterations"][0];
    const formats::json linear_move = old_position["linear_move"];
    const formats::json total = old_position["total_inertia"];
    const formats::json impulse = document["frames"][0]["phases"][1]["iterations"][0]["impulse_contact"];
    const formats::json point_velocity = document["frames"][0]["contacts"][0]["velocity_per_unit_impulse"];
    REQUIRE(formats::upgrade_trace_document(document) == std::optional<int>(1));
    CHECK(document["version"] == trace_format_version);
    const formats::json& position = document["frames"][0]["phases"][0]["iterations"][0];
    CHECK(position["move_split"]["linear_move"] == linear_move);
    CHECK(position["penetration_inertia"] == total);
    CHECK_FALSE(position.contains("linear_move"));
    CHECK_FALSE(position.contains("total_inertia"));
    CHECK(position.contains("amount"));  // velocity-based: a distance, still `amount`
    CHECK(document["frames"][0]["phases"][1]["iterations"][0]["impulse"] == impulse);
    CHECK(document["frames"][0]["contacts"][0]["point_velocity_per_unit_impulse"] == point_velocity);
    // A current document is left alone.
    CHECK_FALSE(formats::upgrade_trace_document(document).has_value());
    // The note names the file and the two formats in one line.
    const std::string note = formats::format1_note("old.json");
    CHECK(note.find("old.json") != std::string::npos);
    CHECK(note.find("format 1") != std::string::npos);
    CHECK(note.find('\n') == std::string::npos);
}

TEST_CASE("a format-2 trace that records a split impulse's push as amount is refused with the path") {
    formats::json document = formats::trace_json(resolved_case("cases/tilted_box", "pgs_split"));
    for (formats::json& phase : document["frames"][0]["phases"])
        for (formats::json& it : phase["iterations"])
            if (it.contains("push_impulse")) {
                it["amount"] = it["push_impulse"];
                it.erase("push_impulse");
                break;
            }
    try {
        formats::read_trace(document);
        FAIL("read");
    } catch (const formats::InputError& e) {
        CHECK(e.where().find("frames[0].phases[") == 0);
        CHECK(e.problem().find("push_impulse") != std::string::npos);
    }
}
