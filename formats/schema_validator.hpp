#pragma once
// A validator for the small subset of JSON Schema (draft 2020-12) that our own case, trace and settings
// schemas use. Debian packages no C++ JSON-Schema validator, so this is written here, and kept strict:
// a schema that uses anything outside the subset is rejected up front instead of being half-checked.
//
// Supported: $defs, $ref (`#`, `#/$defs/name`, or either after the name of a sibling schema given to the
// constructor, e.g. `scene.schema.json#/$defs/settings`), type, properties, required, additionalProperties,
// items, prefixItems, minItems, maxItems, enum, const, minimum, maximum, exclusiveMinimum,
// exclusiveMaximum, minLength, maxLength, minProperties, oneOf, anyOf, not, and the boolean schemas
// `true` and `false`. Annotations ($schema, $id, $comment, title, description, default, examples,
// deprecated, readOnly) are accepted and ignored.
//
// validate() reports only the FIRST violation, as an InputError whose `where` is the JSON path of the
// offending value and whose `problem` is one line for a person ("must be >= 0, got -2"). Checks run in a
// fixed order, so the same document always gives the same message:
//   $ref; type (if it fails, nothing else is reported); for objects: unknown keys (additionalProperties
//   false), required, properties (in the schema's key order), additionalProperties as a schema,
//   minProperties; for arrays: minItems/maxItems, then the items in index order; number and string
//   bounds; enum and const; not, anyOf, oneOf.
// Documents are nlohmann::ordered_json, so "document order" and "the schema's key order" are the order
// the files were written in.

#include <nlohmann/json.hpp>

#include <map>
#include <string>

namespace impulse::formats {

class SchemaValidator {
public:
    // Throws std::logic_error if the schema uses a keyword outside the supported subset, gives a keyword
    // a malformed value, or has a $ref that does not resolve, so our own schemas can never silently rely
    // on something that is not checked.
    using Documents = std::map<std::string, nlohmann::ordered_json>;

    explicit SchemaValidator(nlohmann::ordered_json schema, Documents siblings = {});

    // Throws InputError(path, problem) for the first violation found. Also throws std::logic_error if
    // the schema has a $ref cycle that never moves into the document (which would otherwise loop forever).
    void validate(const nlohmann::ordered_json& document) const;

private:
    nlohmann::ordered_json schema_;
    Documents siblings_;
};

}  // namespace impulse::formats
