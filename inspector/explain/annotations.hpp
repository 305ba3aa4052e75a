#pragma once
// What each value of the derivation vocabulary is: the formula that makes it, the chapter's equation
// number, its unit, and one line on what it means. One table, used by `resolve --explain` now and by the
// inspector's tables and the lessons later.

#include <string_view>

namespace impulse::explain {

struct Annotation {
    std::string_view quantity;  // the vocabulary name (a trace key)
    std::string_view formula;
    std::string_view equation;  // "(14.2)" from the chapter, "ch. 15" for the reference engine's additions
    std::string_view unit;
    std::string_view meaning;
};

// The annotation of a vocabulary name; a name not in the table is a programming error (asserted).
const Annotation& annotation(std::string_view quantity);

// The same for a name that may not be in the vocabulary (a key read from a file): null when it is not.
const Annotation* find_annotation(std::string_view quantity);
// The annotation of a name that may not be in the vocabulary (a key read from a file), or null.
const Annotation* find_annotation(std::string_view quantity);

}  // namespace impulse::explain
