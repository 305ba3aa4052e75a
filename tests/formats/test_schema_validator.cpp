#include <doctest/doctest.h>

#include "formats/input_error.hpp"
#include "formats/schema_validator.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

using impulse::formats::InputError;
using impulse::formats::SchemaValidator;
using json = nlohmann::ordered_json;

namespace {

// Our documents keep their key order, so the tests parse into ordered_json too.
json operator""_oj(const char* text, std::size_t length) {
    return json::parse(text, text + length);
}

struct Reported {
    std::string where;
    std::string problem;
};

// The first violation as (path, problem); a document that passes gives a marker no expected message matches.
Reported report(const json& schema, const json& document) {
    try {
        SchemaValidator(schema).validate(document);
    } catch (const InputError& e) {
        return {e.where(), e.problem()};
    }
    return {"<valid>", "<valid>"};
}

bool passes(const json& schema, const json& document) {
    return report(schema, document).where == "<valid>";
}

const json body_schema = R"({
    "$schema": "https://json-schema.org/draft/2020-12/schema",
    "title": "case",
    "type": "object",
    "additionalProperties": false,
    "required": ["name", "bodies"],
    "properties": {
        "name": {"type": "string", "minLength": 1, "description": "shown in the inspector"},
        "bodies": {"type": "array", "minItems": 1, "items": {"$ref": "#/$defs/body"}}
    },
    "$defs": {
        "vec3": {"type": "array", "minItems": 3, "maxItems": 3, "items": {"type": "number"}},
        "body": {
            "type": "object",
            "additionalProperties": false,
            "required": ["position", "mass"],
            "properties": {
                "position": {"$ref": "#/$defs/vec3"},
                "mass": {"type": "number", "exclusiveMinimum": 0, "default": 1},
                "kind": {"enum": ["box", "sphere"]}
            }
        }
    }
})"_oj;

}  // namespace

TEST_CASE("a valid document passes") {
    const json document = R"({"name": "stack", "bodies": [
        {"position": [0, 1.5, 0], "mass": 2, "kind": "box"},
        {"position": [0, 0, 0], "mass": 0.5}
    ]})"_oj;
    CHECK_NOTHROW(SchemaValidator(body_schema).validate(document));
}

TEST_CASE("paths name nested members and array elements") {
    const auto r = report(body_schema, R"({"name": "x", "bodies": [{"position": [0, 0, 0], "mass": 1},
                                                                  {"position": [0, "up", 0], "mass": 1}]})"_oj);
    CHECK(r.where == "bodies[1].position[1]");
    CHECK(r.problem == "must be a number, got \"up\"");
}

TEST_CASE("a type mismatch names the expected type with the right article") {
    CHECK(report(json{{"type", "number"}}, "abc").problem == "must be a number, got \"abc\"");
    CHECK(report(json{{"type", "object"}}, json{1, 2}).problem == "must be an object, got [1,2]");
    CHECK(report(json{{"type", "array"}}, true).problem == "must be an array, got true");
    CHECK(report(json{{"type", "integer"}}, 2.5).problem == "must be an integer, got 2.5");
    CHECK(report(json{{"type", "boolean"}}, nullptr).problem == "must be a boolean, got null");
    CHECK(report(json{{"type", "null"}}, 0).problem == "must be null, got 0");
    const auto r = report(json{{"type", "string"}}, 1);
    CHECK(r.where == "");
    CHECK(r.problem == "must be a string, got 1");
}

TEST_CASE("a list of types reads as a sentence") {
    CHECK(report(R"({"type": ["string", "null"]})"_oj, 3).problem == "must be a string or null, got 3");
    CHECK(report(R"({"type": ["object", "array", "null"]})"_oj, "s").problem ==
          "must be an object, an array or null, got \"s\"");
    CHECK(passes(R"({"type": ["string", "null"]})"_oj, nullptr));
}

TEST_CASE("number accepts integers and integer accepts whole doubles") {
    CHECK(passes(json{{"type", "number"}}, 3));
    CHECK(passes(json{{"type", "number"}}, -3));
    CHECK(passes(json{{"type", "integer"}}, json::parse("3.0")));
    CHECK(passes(json{{"type", "integer"}}, 7u));
    CHECK(report(json{{"type", "integer"}}, json::parse("3.5")).problem == "must be an integer, got 3.5");
    CHECK(report(json{{"type", "integer"}}, "3").problem == "must be an integer, got \"3\"");
}

TEST_CASE("a non-finite number fails number and integer with its own message") {
    // nlohmann refuses 1e999 while parsing, so such a value never reaches the validator from a file...
    const auto parse_overflow = [] { return json::parse("[1e999]"); };
    CHECK_THROWS_AS(parse_overflow(), json::out_of_range);
    // ...but a document built in code can still hold one, and dump() would print it as null.
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(report(json{{"type", "number"}}, inf).problem == "must be a finite number, got inf");
    CHECK(report(json{{"type", "integer"}}, -inf).problem == "must be a finite number, got -inf");
    CHECK(report(R"({"type": ["number", "null"]})"_oj, std::nan("")).problem == "must be a finite number, got nan");
    CHECK(report(json{{"type", "string"}}, inf).problem == "must be a string, got inf");
}

TEST_CASE("a long value is cut to 40 characters") {
    const std::string long_text(50, 'x');
    CHECK(report(json{{"type", "number"}}, long_text).problem ==
          "must be a number, got \"" + std::string(36, 'x') + "...");
    // Exactly 40 characters when dumped is shown whole.
    CHECK(report(json{{"type", "number"}}, std::string(38, 'y')).problem ==
          "must be a number, got \"" + std::string(38, 'y') + "\"");
}

TEST_CASE("checks at one value run in a fixed order") {
    // Value keywords come before combinators.
    CHECK(report(R"({"enum": [1, 2], "anyOf": [{"const": 3}]})"_oj, 5).problem == "must be one of 1, 2; got 5");
    // Bounds come before enum.
    CHECK(report(R"({"minimum": 10, "enum": [20]})"_oj, 5).problem == "must be >= 10, got 5");
    // Declared properties are visited in the order the schema writes them.
    const json schema = R"({"properties": {"b": {"type": "string"}, "a": {"type": "string"}}})"_oj;
    CHECK(report(schema, R"({"a": 2, "b": 1})"_oj).where == "b");
}

TEST_CASE("a failed type check is the only thing reported for that value") {
    const json schema = R"({"type": "string", "enum": ["a"], "not": {"type": "number"}})"_oj;
    CHECK(report(schema, 5).problem == "must be a string, got 5");
}

TEST_CASE("an unknown key names the closest known field") {
    auto r = report(body_schema, R"({"name": "x", "bodies": [{"position": [0, 0, 0], "mas": 1}]})"_oj);
    CHECK(r.where == "bodies[0].mas");
    CHECK(r.problem == "unknown field (did you mean \"mass\"?)");
    r = report(body_schema, R"({"name": "x", "bodies": [{"position": [0, 0, 0], "mass": 1, "KIND": "box"}]})"_oj);
    CHECK(r.where == "bodies[0].KIND");
    CHECK(r.problem == "unknown field (did you mean \"kind\"?)");
}

TEST_CASE("an unknown key with no close match lists the expected fields") {
    const json schema = R"({"additionalProperties": false, "properties": {"a": {}, "b": {}, "c": {}}})"_oj;
    const auto r = report(schema, R"({"a": 1, "velocity": 2})"_oj);
    CHECK(r.where == "velocity");
    CHECK(r.problem == "unknown field; expected one of \"a\", \"b\", \"c\"");
    CHECK(report(json{{"additionalProperties", false}}, json{{"x", 1}}).problem ==
          "unknown field; no fields are allowed here");
}

TEST_CASE("fields that come together are all required once one of them is given") {
    const json schema = R"({"dependentRequired": {"model": ["impulse", "change"], "impulse": ["model"]}})"_oj;
    CHECK(passes(schema, R"({})"_oj));
    CHECK(passes(schema, R"({"model": 1, "impulse": 2, "change": 3})"_oj));
    CHECK(passes(schema, R"({"change": 3})"_oj));  // change alone asks for nothing
    auto r = report(schema, R"({"model": 1, "impulse": 2})"_oj);
    CHECK(r.where == "change");
    CHECK(r.problem == "missing (given with model)");
    r = report(schema, R"({"impulse": 2})"_oj);
    CHECK(r.where == "model");
    CHECK(r.problem == "missing (given with impulse)");
    CHECK_THROWS_AS(SchemaValidator(R"({"dependentRequired": {"a": "b"}})"_oj), std::logic_error);
}

TEST_CASE("unknown keys are reported before missing required keys") {
    const auto r = report(body_schema, R"({"nmae": "x"})"_oj);
    CHECK(r.where == "nmae");
    CHECK(r.problem == "unknown field (did you mean \"name\"?)");
}

TEST_CASE("a missing required key is reported at its own path in the schema's order") {
    auto r = report(body_schema, json::object());
    CHECK(r.where == "name");
    CHECK(r.problem == "missing (required)");
    r = report(body_schema, R"({"name": "x", "bodies": [{"mass": 1}]})"_oj);
    CHECK(r.where == "bodies[0].position");
    CHECK(r.problem == "missing (required)");
    // Missing keys come before bad values of present ones.
    r = report(body_schema, R"({"bodies": [{"mass": "heavy"}]})"_oj);
    CHECK(r.where == "name");
}

TEST_CASE("additionalProperties as a schema checks the undeclared fields") {
    const json schema = R"({"properties": {"id": {"type": "string"}},
                            "additionalProperties": {"type": "number"}})"_oj;
    CHECK(passes(schema, R"({"id": "a", "x": 1, "y": 2})"_oj));
    const auto r = report(schema, R"({"id": "a", "x": 1, "y": "two"})"_oj);
    CHECK(r.where == "y");
    CHECK(r.problem == "must be a number, got \"two\"");
}

TEST_CASE("minProperties counts the fields") {
    const auto r = report(R"({"minProperties": 2})"_oj, json{{"a", 1}});
    CHECK(r.problem == "must have at least 2 fields, got 1");
    CHECK(report(R"({"minProperties": 1})"_oj, json::object()).problem == "must have at least 1 field, got 0");
}

TEST_CASE("item counts say exactly, at least or at most") {
    auto r = report(body_schema, R"({"name": "x", "bodies": [{"position": [0, 0], "mass": 1}]})"_oj);
    CHECK(r.where == "bodies[0].position");
    CHECK(r.problem == "must have exactly 3 items, got 2");
    r = report(body_schema, R"({"name": "x", "bodies": []})"_oj);
    CHECK(r.where == "bodies");
    CHECK(r.problem == "must have at least 1 item, got 0");
    CHECK(report(R"({"maxItems": 4})"_oj, json{1, 2, 3, 4, 5}).problem == "must have at most 4 items, got 5");
    CHECK(report(R"({"minItems": 2, "maxItems": 4})"_oj, json{1}).problem == "must have at least 2 items, got 1");
    CHECK(report(R"({"minItems": 1, "maxItems": 1})"_oj, json{1, 2}).problem == "must have exactly 1 item, got 2");
}

TEST_CASE("item counts are checked before the items themselves") {
    const json schema = R"({"minItems": 3, "items": {"type": "string"}})"_oj;
    const auto r = report(schema, json{1});
    CHECK(r.where == "");
    CHECK(r.problem == "must have at least 3 items, got 1");
}

TEST_CASE("prefixItems check the leading elements and items the rest") {
    const json schema = R"({"prefixItems": [{"type": "string"}, {"type": "boolean"}],
                            "items": {"type": "number"}})"_oj;
    CHECK(passes(schema, R"(["a", true, 1, 2])"_oj));
    CHECK(passes(schema, R"(["a"])"_oj));
    auto r = report(schema, R"(["a", 1])"_oj);
    CHECK(r.where == "[1]");
    CHECK(r.problem == "must be a boolean, got 1");
    r = report(schema, R"(["a", false, 1, null])"_oj);
    CHECK(r.where == "[3]");
    CHECK(r.problem == "must be a number, got null");
    CHECK(passes(R"({"prefixItems": [{"type": "string"}]})"_oj, R"(["a", 1, null])"_oj));
}

TEST_CASE("numeric bounds print the bound as the schema wrote it") {
    CHECK(report(R"({"minimum": 0})"_oj, -2).problem == "must be >= 0, got -2");
    CHECK(report(R"({"exclusiveMinimum": 0})"_oj, 0).problem == "must be > 0, got 0");
    CHECK(report(R"({"maximum": 1})"_oj, 1.5).problem == "must be <= 1, got 1.5");
    CHECK(report(R"({"exclusiveMaximum": 1})"_oj, 1).problem == "must be < 1, got 1");
    CHECK(report(R"({"minimum": 0.25})"_oj, 0.125).problem == "must be >= 0.25, got 0.125");
    CHECK(passes(R"({"minimum": 0, "maximum": 1})"_oj, 0));
    CHECK(passes(R"({"minimum": 0, "maximum": 1})"_oj, 1));
    CHECK(passes(R"({"exclusiveMinimum": 0})"_oj, 1e-9));
    CHECK(passes(R"({"minimum": 0})"_oj, "strings are not bounded by minimum"));
    // Without a `type`, a NaN still cannot satisfy a bound.
    CHECK(report(R"({"minimum": 0})"_oj, std::nan("")).problem == "must be >= 0, got nan");
}

TEST_CASE("enum and const show the allowed values and the actual one") {
    auto r = report(body_schema, R"({"name": "x", "bodies": [{"position": [0, 0, 0], "mass": 1, "kind": "cone"}]})"_oj);
    CHECK(r.where == "bodies[0].kind");
    CHECK(r.problem == "must be one of \"box\", \"sphere\"; got \"cone\"");
    CHECK(report(R"({"enum": ["a", "b", "c"]})"_oj, "d").problem == "must be one of \"a\", \"b\", \"c\"; got \"d\"");
    CHECK(report(R"({"const": "x"})"_oj, "y").problem == "must be \"x\", got \"y\"");
    CHECK(passes(R"({"const": 1})"_oj, 1.0));
}

TEST_CASE("string lengths count characters") {
    auto r = report(body_schema, R"({"name": "", "bodies": [{"position": [0, 0, 0], "mass": 1}]})"_oj);
    CHECK(r.where == "name");
    CHECK(r.problem == "must not be empty");
    CHECK(report(R"({"minLength": 3})"_oj, "ab").problem == "must be at least 3 characters long");
    CHECK(report(R"({"maxLength": 4})"_oj, "abcdef").problem == "must be at most 4 characters long, got 6");
    CHECK(passes(R"({"maxLength": 2})"_oj, "\xc3\xa9\xc3\xa9"));  // Two characters, four bytes.
}

TEST_CASE("not rejects the forbidden form") {
    const auto r = report(R"({"properties": {"n": {"not": {"const": 0}}}})"_oj, json{{"n", 0}});
    CHECK(r.where == "n");
    CHECK(r.problem == "must not match the forbidden form");
    CHECK(passes(R"({"not": {"const": 0}})"_oj, 1));
}

TEST_CASE("anyOf reports the branch that failed deepest") {
    const json schema = R"({"anyOf": [
        {"type": "number"},
        {"type": "object", "required": ["r"], "properties": {"r": {"minimum": 0}}}
    ]})"_oj;
    CHECK(passes(schema, 2));
    CHECK(passes(schema, json{{"r", 1}}));
    const auto r = report(schema, json{{"r", -1}});
    CHECK(r.where == "r");
    CHECK(r.problem == "must be >= 0, got -1");
}

TEST_CASE("oneOf reports the branch that failed deepest, or the first on a tie") {
    const json schema = R"({"oneOf": [
        {"type": "object", "required": ["half_extents"], "properties": {"half_extents": {"$ref": "#/$defs/v2"}}},
        {"type": "object", "required": ["radius"], "properties": {"radius": {"type": "number"}}}
    ], "$defs": {"v2": {"type": "array", "items": {"type": "number"}}}})"_oj;
    CHECK(passes(schema, json{{"radius", 1}}));
    // Branch 0 fails at half_extents[1], deeper than branch 1's missing `radius`.
    auto r = report(schema, R"({"half_extents": [1, "x"]})"_oj);
    CHECK(r.where == "half_extents[1]");
    CHECK(r.problem == "must be a number, got \"x\"");
    // Branch 0 fails at the missing `half_extents` and branch 1 at `radius`: equally deep, so the first wins.
    r = report(schema, json{{"radius", "big"}});
    CHECK(r.where == "half_extents");
    CHECK(r.problem == "missing (required)");
    // Neither branch gets past the type check: both fail at the root, so branch 0 is reported.
    r = report(schema, 5);
    CHECK(r.where == "");
    CHECK(r.problem == "must be an object, got 5");
}

TEST_CASE("oneOf rejects a value that matches more than one branch") {
    const json schema = R"({"properties": {"v": {"oneOf": [
        {"type": "number"}, {"type": "string"}, {"type": "integer", "minimum": 0}
    ]}}})"_oj;
    CHECK(passes(schema, json{{"v", "s"}}));
    CHECK(passes(schema, json{{"v", -1}}));
    const auto r = report(schema, json{{"v", 2}});
    CHECK(r.where == "v");
    CHECK(r.problem == "matches more than one allowed form (branches 0 and 2)");
}

TEST_CASE("$ref resolves $defs and the root, and may recurse") {
    const json tree = R"({
        "type": "object",
        "additionalProperties": false,
        "properties": {"value": {"$ref": "#/$defs/count"}, "children": {"type": "array", "items": {"$ref": "#"}}},
        "$defs": {"count": {"type": "integer", "minimum": 0}}
    })"_oj;
    CHECK(passes(tree, R"({"value": 1, "children": [{"value": 2, "children": [{"value": 3}]}]})"_oj));
    auto r = report(tree, R"({"value": 1, "children": [{"children": [{"value": -3}]}]})"_oj);
    CHECK(r.where == "children[0].children[0].value");
    CHECK(r.problem == "must be >= 0, got -3");
    r = report(tree, R"({"children": [{"children": [{"valeu": 3}]}]})"_oj);
    CHECK(r.where == "children[0].children[0].valeu");
    CHECK(r.problem == "unknown field (did you mean \"value\"?)");
}

TEST_CASE("boolean schemas accept everything or nothing") {
    CHECK(passes(json(true), R"({"anything": [1, "goes"]})"_oj));
    auto r = report(json(false), 1);
    CHECK(r.where == "");
    CHECK(r.problem == "not allowed here");
    r = report(R"({"properties": {"legacy": false}})"_oj, R"({"legacy": 1})"_oj);
    CHECK(r.where == "legacy");
    CHECK(r.problem == "not allowed here");
    CHECK(passes(R"({"items": false})"_oj, json::array()));
    CHECK(report(R"({"items": false})"_oj, json{7}).where == "[0]");
}

TEST_CASE("documents nested more than 64 levels deep are refused") {
    const json schema = R"({"type": ["array", "number"], "items": {"$ref": "#"}})"_oj;
    const auto nest = [](int levels) {
        json value = 0;
        for (int i = 0; i < levels; ++i) value = json::array({value});
        return value;
    };
    CHECK(passes(schema, nest(64)));
    const auto r = report(schema, nest(65));
    std::string deepest_path;
    for (int i = 0; i < 65; ++i) deepest_path += "[0]";
    CHECK(r.where == deepest_path);
    CHECK(r.problem == "nested too deeply (more than 64 levels)");
}

TEST_CASE("a schema with an unsupported keyword is refused when it is loaded") {
    CHECK_THROWS_AS(SchemaValidator(R"({"type": "string", "pattern": "^a"})"_oj), std::logic_error);
    CHECK_THROWS_WITH_AS(SchemaValidator(R"({"properties": {"x": {"format": "email"}}})"_oj),
                         "schema at #/properties/x/format: unsupported keyword \"format\"", std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"allOf": [{}]})"_oj), std::logic_error);
}

TEST_CASE("a schema with a malformed keyword or a dangling $ref is refused when it is loaded") {
    CHECK_THROWS_AS(SchemaValidator(R"({"type": "float"})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"items": [{}]})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"minItems": -1})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"required": "name"})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"oneOf": []})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"$ref": "#/$defs/missing"})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(R"({"$ref": "other.json#/$defs/a"})"_oj), std::logic_error);
    CHECK_THROWS_AS(SchemaValidator(json(3)), std::logic_error);
}

TEST_CASE("annotation keywords are accepted and ignored") {
    const json schema = R"({"$id": "case", "$comment": "c", "title": "t", "description": "d",
                            "default": {"pattern": 1}, "examples": [1], "deprecated": false, "readOnly": true,
                            "type": "number"})"_oj;
    CHECK(passes(schema, 1));
    CHECK(report(schema, "x").problem == "must be a number, got \"x\"");
}

TEST_CASE("a $ref cycle that never enters the document is a schema error, not a hang") {
    const SchemaValidator validator(R"({"$defs": {"a": {"anyOf": [{"$ref": "#/$defs/a"}]}}, "$ref": "#/$defs/a"})"_oj);
    CHECK_THROWS_AS(validator.validate(1), std::logic_error);
}
