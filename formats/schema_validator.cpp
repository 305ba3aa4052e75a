#include "formats/schema_validator.hpp"

#include "formats/input_error.hpp"
#include "formats/suggest.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

namespace impulse::formats {

namespace {

using json = nlohmann::ordered_json;  // keeps document and schema key order
using Documents = SchemaValidator::Documents;

constexpr int max_document_depth = 64;  // Also written out in the message for exceeding it.
// Only a $ref can make a schema loop back on itself. A chain of this many $refs applied to one value
// without moving into the document is a cycle in the schema, not something a real schema would need.
constexpr int max_ref_hops = 64;
constexpr std::size_t max_shown_length = 40;

bool is_in(std::string_view word, std::initializer_list<std::string_view> words) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

// The keyword's value, or null when the schema does not use it.
const json* keyword(const json& schema, const char* name) {
    const auto it = schema.find(name);
    return it == schema.end() ? nullptr : &*it;
}

std::optional<std::size_t> count_keyword(const json& schema, const char* name) {
    const json* value = keyword(schema, name);
    return value ? std::optional(value->get<std::size_t>()) : std::nullopt;
}

// The schema itself is checked once, when it is loaded, so that validation can trust every keyword's shape.
[[noreturn]] void schema_error(const std::string& at, const std::string& what) {
    throw std::logic_error("schema at " + at + ": " + what);
}

// A schema and the document it belongs to: a local $ref inside it resolves against that document.
struct Located {
    const json& schema;
    const json& root;
};

// References are "#", "#/$defs/name", or the same after the name of one of the sibling documents the
// validator was given ("scene.schema.json#/$defs/settings"), so one schema can reuse another's parts.
Located resolve_ref(const json& root, const Documents& siblings, const json& ref, const std::string& at) {
    if (!ref.is_string()) schema_error(at, "must be a string");
    const auto& text = ref.get_ref<const std::string&>();
    const std::size_t hash = text.find('#');
    const std::string document = text.substr(0, hash);
    const std::string fragment = hash == std::string::npos ? "#" : text.substr(hash);
    const json* target_root = &root;
    if (!document.empty()) {
        const auto sibling = siblings.find(document);
        if (sibling == siblings.end()) schema_error(at, "$ref \"" + text + "\" names an unknown document");
        target_root = &sibling->second;
    }
    if (fragment == "#") return {*target_root, *target_root};
    const std::string prefix = "#/$defs/";
    const std::string name = fragment.substr(std::min(prefix.size(), fragment.size()));
    if (fragment.rfind(prefix, 0) != 0 || name.empty() || name.find('/') != std::string::npos) {
        schema_error(at, "unsupported $ref \"" + text + "\" (only \"#\" and \"#/$defs/name\" fragments are supported)");
    }
    const json* defs = keyword(*target_root, "$defs");
    if (!defs || !defs->contains(name)) schema_error(at, "$ref \"" + text + "\" does not resolve");
    return {(*defs)[name], *target_root};
}

bool is_type_name(const json& name) {
    return name.is_string() &&
           is_in(name.get<std::string>(), {"object", "array", "string", "number", "integer", "boolean", "null"});
}

void check_schema(const json& root, const Documents& siblings, const json& schema, const std::string& at) {
    if (schema.is_boolean()) return;
    if (!schema.is_object()) schema_error(at, "a schema must be an object or a boolean");
    for (auto it = schema.begin(); it != schema.end(); ++it) {
        const std::string& key = it.key();
        const json& value = it.value();
        const std::string here = at + "/" + key;
        if (is_in(key, {"$schema", "$id", "$comment", "title", "description", "default", "examples", "deprecated",
                        "readOnly", "const"})) {
            continue;  // Annotations, and `const`, hold data rather than schemas: any value is well-formed.
        } else if (key == "$defs" || key == "properties") {
            if (!value.is_object()) schema_error(here, "must be an object of schemas");
            for (const auto& [name, sub] : value.items()) check_schema(root, siblings, sub, here + "/" + name);
        } else if (key == "items" && value.is_array()) {
            schema_error(here, "must be a single schema (draft 2020-12 uses prefixItems for tuples)");
        } else if (is_in(key, {"additionalProperties", "items", "not"})) {
            check_schema(root, siblings, value, here);
        } else if (is_in(key, {"prefixItems", "anyOf", "oneOf"})) {
            if (!value.is_array() || value.empty()) schema_error(here, "must be a non-empty array of schemas");
            for (std::size_t i = 0; i < value.size(); ++i) {
                check_schema(root, siblings, value[i], here + "/" + std::to_string(i));
            }
        } else if (key == "type") {
            const json names = value.is_array() ? value : json::array({value});
            if (names.empty() || !std::all_of(names.begin(), names.end(), is_type_name)) {
                schema_error(here, "must be a type name or a non-empty array of them");
            }
        } else if (key == "required") {
            if (!value.is_array() || !std::all_of(value.begin(), value.end(), std::mem_fn(&json::is_string))) {
                schema_error(here, "must be an array of strings");
            }
        } else if (key == "dependentRequired") {
            const auto names = [](const json& list) {
                return list.is_array() && std::all_of(list.begin(), list.end(), std::mem_fn(&json::is_string));
            };
            if (!value.is_object() || !std::all_of(value.begin(), value.end(), names))
                schema_error(here, "must be an object of arrays of strings");
        } else if (is_in(key, {"minItems", "maxItems", "minLength", "maxLength", "minProperties"})) {
            if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0)) {
                schema_error(here, "must be a non-negative integer");
            }
        } else if (is_in(key, {"minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"})) {
            if (!value.is_number()) schema_error(here, "must be a number");
        } else if (key == "enum") {
            if (!value.is_array() || value.empty()) schema_error(here, "must be a non-empty array");
        } else if (key == "$ref") {
            resolve_ref(root, siblings, value, here);  // Checked now so that a typo fails when the schema loads.
        } else {
            schema_error(here, "unsupported keyword \"" + key + "\"");
        }
    }
}

// Values are shown as JSON so strings appear quoted, and cut short so one bad value cannot flood the line.
// dump() would print a non-finite double as `null`, which would hide the actual problem.
std::string describe(const json& value) {
    if (value.is_number_float() && !std::isfinite(value.get<double>())) {
        const double d = value.get<double>();
        return std::isnan(d) ? "nan" : (d > 0 ? "inf" : "-inf");
    }
    std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
    if (text.size() <= max_shown_length) return text;
    std::size_t cut = max_shown_length - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // Keep UTF-8 whole.
    return text.substr(0, cut) + "...";
}

std::string counted(std::size_t n, const std::string& noun) {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// "a string", "a string or null", "an object, an array or null".
std::string type_phrase(const json& types) {
    std::string phrase;
    for (std::size_t i = 0; i < types.size(); ++i) {
        const auto& type = types[i].get_ref<const std::string&>();
        if (i > 0) phrase += (i + 1 == types.size()) ? " or " : ", ";
        if (type != "null") phrase += is_in(type, {"object", "array", "integer"}) ? "an " : "a ";
        phrase += type;
    }
    return phrase;
}

// Suggest the closest declared field, comparing without case so that `Mass` finds `mass`: a typo is far
// more likely than a genuinely new field, and naming the fix saves a trip to the documentation.
std::string unknown_field_problem(const std::string& key, const json* properties) {
    if (!properties || properties->empty()) return "unknown field; no fields are allowed here";
    std::vector<std::string> names;
    std::string expected;
    for (auto it = properties->begin(); it != properties->end(); ++it) {
        names.push_back(it.key());
        expected += (expected.empty() ? "" : ", ") + json(it.key()).dump();
    }
    if (const std::optional<std::string> best = closest_name(key, names))
        return "unknown field (did you mean " + json(*best).dump() + "?)";
    return "unknown field; expected one of " + expected;
}

struct Node {
    const json& value;
    std::string path;
    int depth;  // The root is 0; each object member or array element is one deeper.
};

struct Failure {
    std::string where;
    std::string problem;
    int depth;  // How deep in the document the failure is; anyOf and oneOf report their deepest branch.
};

using Result = std::optional<Failure>;

Failure fail(const Node& node, std::string problem) {
    return {node.path, std::move(problem), node.depth};
}

bool has_type(const json& value, const std::string& type) {
    if (type == "object") return value.is_object();
    if (type == "array") return value.is_array();
    if (type == "string") return value.is_string();
    if (type == "boolean") return value.is_boolean();
    if (type == "null") return value.is_null();
    if (!value.is_number_float()) return value.is_number();
    const double d = value.get<double>();  // Like the spec, a double with no fractional part is an integer.
    return std::isfinite(d) && (type == "number" || std::trunc(d) == d);
}

std::size_t code_points(const std::string& text) {
    const auto starts_character = [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; };
    return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), starts_character));
}

Result check_type(const json& type, const Node& node) {
    const json types = type.is_array() ? type : json::array({type});
    const json& value = node.value;
    const bool wants_number = std::find(types.begin(), types.end(), "number") != types.end() ||
                              std::find(types.begin(), types.end(), "integer") != types.end();
    if (wants_number && value.is_number_float() && !std::isfinite(value.get<double>())) {
        return fail(node, "must be a finite number, got " + describe(value));
    }
    for (const json& name : types) {
        if (has_type(value, name.get_ref<const std::string&>())) return {};
    }
    return fail(node, "must be " + type_phrase(types) + ", got " + describe(value));
}

Result check_bounds(const json& schema, const Node& node) {
    const json& value = node.value;
    if (value.is_number()) {
        // nlohmann compares numbers across integer and floating-point kinds, as JSON Schema does. Each test
        // asks whether the bound holds, rather than whether it is broken, so that NaN fails every bound.
        using Holds = bool (*)(const json&, const json&);
        const std::tuple<const char*, const char*, Holds> bounds[] = {
            {"minimum", ">=", [](const json& v, const json& b) { return v >= b; }},
            {"exclusiveMinimum", ">", [](const json& v, const json& b) { return v > b; }},
            {"maximum", "<=", [](const json& v, const json& b) { return v <= b; }},
            {"exclusiveMaximum", "<", [](const json& v, const json& b) { return v < b; }}};
        for (const auto& [name, relation, holds] : bounds) {
            const json* bound = keyword(schema, name);
            if (!bound || holds(value, *bound)) continue;
            return fail(node, "must be " + std::string(relation) + " " + bound->dump() + ", got " + describe(value));
        }
    }
    if (value.is_string()) {
        const std::size_t length = code_points(value.get_ref<const std::string&>());
        if (const auto min = count_keyword(schema, "minLength"); min && length < *min) {
            if (*min == 1) return fail(node, "must not be empty");
            return fail(node, "must be at least " + counted(*min, "character") + " long");
        }
        if (const auto max = count_keyword(schema, "maxLength"); max && length > *max) {
            return fail(node, "must be at most " + counted(*max, "character") + " long, got " + std::to_string(length));
        }
    }
    return {};
}

Result check_values(const json& schema, const Node& node) {
    if (const json* allowed = keyword(schema, "enum")) {
        if (std::find(allowed->begin(), allowed->end(), node.value) == allowed->end()) {
            std::string list;
            std::vector<std::string> words;
            for (const json& v : *allowed) {
                list += (list.empty() ? "" : ", ") + describe(v);
                if (v.is_string()) words.push_back(v.get<std::string>());
            }
            // A guess only for a word long enough that its few wrong letters are a slip, not another word.
            std::string guess;
            if (node.value.is_string()) {
                const std::string& word = node.value.get_ref<const std::string&>();
                if (const auto closest = closest_name(word, words);
                    closest && 3 * edit_distance(word, *closest) <= word.size())
                    guess = " (did you mean \"" + *closest + "\"?)";
            }
            return fail(node, "must be one of " + list + "; got " + describe(node.value) + guess);
        }
    }
    if (const json* expected = keyword(schema, "const"); expected && *expected != node.value) {
        return fail(node, "must be " + describe(*expected) + ", got " + describe(node.value));
    }
    return {};
}

// The failure deepest in the document is usually in the branch the author meant: it got furthest.
// max_element returns the first of equal elements, so a tie goes to the earliest branch.
Failure deepest(const std::vector<Failure>& failures) {
    return *std::max_element(failures.begin(), failures.end(),
                             [](const Failure& a, const Failure& b) { return a.depth < b.depth; });
}

// Walks a document and the schema together. Failures are returned rather than thrown so that anyOf and
// oneOf can try every branch and then choose which failure to report.
class Walker {
public:
    explicit Walker(const Documents& siblings) : siblings_(siblings) {}

    // `root` is the document `schema` belongs to, against which its local $refs resolve.
    Result check(const json& schema, const json& root, const Node& node, int ref_hops) const {
        if (schema.is_boolean()) return schema.get<bool>() ? Result{} : fail(node, "not allowed here");
        if (node.depth > max_document_depth) return fail(node, "nested too deeply (more than 64 levels)");
        if (const json* ref = keyword(schema, "$ref")) {
            if (ref_hops >= max_ref_hops) throw std::logic_error("schema: a $ref cycle never enters the document");
            const Located target = resolve_ref(root, siblings_, *ref, "$ref");
            if (auto failure = check(target.schema, target.root, node, ref_hops + 1)) return failure;
        }
        if (const json* type = keyword(schema, "type")) {
            if (auto failure = check_type(*type, node)) return failure;
        }
        Result failure;
        if (node.value.is_object()) failure = check_object(schema, root, node);
        if (node.value.is_array()) failure = check_array(schema, root, node);
        if (!failure) failure = check_bounds(schema, node);
        if (!failure) failure = check_values(schema, node);
        if (!failure) failure = check_combinators(schema, root, node, ref_hops);
        return failure;
    }

private:
    Result check_object(const json& schema, const json& root, const Node& node) const {
        const json& object = node.value;
        const json* properties = keyword(schema, "properties");
        const json* additional = keyword(schema, "additionalProperties");
        const bool closed = additional && *additional == false;
        const auto declared = [&](const std::string& key) { return properties && properties->contains(key); };
        const auto member = [&](const std::string& key, const json& value) {
            return Node{value, json_path_child(node.path, key), node.depth + 1};
        };

        for (auto it = object.begin(); closed && it != object.end(); ++it) {
            if (declared(it.key())) continue;
            return fail(member(it.key(), *it), unknown_field_problem(it.key(), properties));
        }
        for (const json& name : schema.value("required", json::array())) {
            const auto& key = name.get_ref<const std::string&>();
            if (object.contains(key)) continue;
            return Failure{json_path_child(node.path, key), "missing (required)", node.depth + 1};
        }
        // Fields that come together: with the first present, each of the others must be too.
        if (const json* dependent = keyword(schema, "dependentRequired")) {
            for (auto it = dependent->begin(); it != dependent->end(); ++it) {
                if (!object.contains(it.key())) continue;
                for (const json& name : *it) {
                    const auto& key = name.get_ref<const std::string&>();
                    if (object.contains(key)) continue;
                    return Failure{json_path_child(node.path, key), "missing (given with " + it.key() + ")",
                                   node.depth + 1};
                }
            }
        }
        if (properties) {
            for (auto it = properties->begin(); it != properties->end(); ++it) {
                const auto present = object.find(it.key());
                if (present == object.end()) continue;
                if (auto failure = check(*it, root, member(it.key(), *present), 0)) return failure;
            }
        }
        for (auto it = object.begin(); additional && !closed && it != object.end(); ++it) {
            if (declared(it.key())) continue;
            if (auto failure = check(*additional, root, member(it.key(), *it), 0)) return failure;
        }
        if (const auto min = count_keyword(schema, "minProperties"); min && object.size() < *min) {
            return fail(node,
                        "must have at least " + counted(*min, "field") + ", got " + std::to_string(object.size()));
        }
        return {};
    }

    Result check_array(const json& schema, const json& root, const Node& node) const {
        const std::size_t size = node.value.size();
        const auto min = count_keyword(schema, "minItems");
        const auto max = count_keyword(schema, "maxItems");
        const std::string got = ", got " + std::to_string(size);
        if (min && min == max && size != *min) return fail(node, "must have exactly " + counted(*min, "item") + got);
        if (min && size < *min) return fail(node, "must have at least " + counted(*min, "item") + got);
        if (max && size > *max) return fail(node, "must have at most " + counted(*max, "item") + got);

        const json* prefix = keyword(schema, "prefixItems");
        const json* items = keyword(schema, "items");
        for (std::size_t i = 0; i < size; ++i) {
            const json* item_schema = prefix && i < prefix->size() ? &(*prefix)[i] : items;
            if (!item_schema) break;  // Past the prefix with no `items`: the rest is unconstrained.
            const Node element{node.value[i], json_path_index(node.path, i), node.depth + 1};
            if (auto failure = check(*item_schema, root, element, 0)) return failure;
        }
        return {};
    }

    Result check_combinators(const json& schema, const json& root, const Node& node, int ref_hops) const {
        if (const json* forbidden = keyword(schema, "not"); forbidden && !check(*forbidden, root, node, ref_hops)) {
            return fail(node, "must not match the forbidden form");
        }
        // anyOf wants at least one matching branch and oneOf exactly one, so trying further branches after one
        // (anyOf) or two (oneOf) matches cannot change the answer.
        for (const auto& [combinator, enough] : {std::pair<const char*, std::size_t>{"anyOf", 1}, {"oneOf", 2}}) {
            const json* branches = keyword(schema, combinator);
            if (!branches) continue;
            std::vector<Failure> failures;
            std::vector<std::size_t> matches;
            for (std::size_t i = 0; i < branches->size() && matches.size() < enough; ++i) {
                if (auto failure = check((*branches)[i], root, node, ref_hops)) {
                    failures.push_back(std::move(*failure));
                } else {
                    matches.push_back(i);
                }
            }
            if (matches.empty()) return deepest(failures);
            if (matches.size() > 1) {
                return fail(node, "matches more than one allowed form (branches " + std::to_string(matches[0]) +
                                      " and " + std::to_string(matches[1]) + ")");
            }
        }
        return {};
    }

    const Documents& siblings_;
};

}  // namespace

SchemaValidator::SchemaValidator(json schema, Documents siblings)
    : schema_(std::move(schema)), siblings_(std::move(siblings)) {
    for (const auto& [name, sibling] : siblings_) check_schema(sibling, siblings_, sibling, name + "#");
    check_schema(schema_, siblings_, schema_, "#");
}

void SchemaValidator::validate(const json& document) const {
    const Walker walker(siblings_);
    if (auto failure = walker.check(schema_, schema_, Node{document, "", 0}, 0)) {
        throw InputError(std::move(failure->where), std::move(failure->problem));
    }
}

}  // namespace impulse::formats
