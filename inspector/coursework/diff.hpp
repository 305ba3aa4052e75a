#pragma once
// Comparing a trace, or a filled worksheet, with a reference trace, value by value in trace order. A number
// matches when |found − expected| ≤ atol + rtol·|expected|; text and booleans must be equal. The first
// mismatch in trace order is the first divergence: later ones often follow from it.

#include "coursework/filled_worksheet.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::coursework {

struct Tolerance {
    double rtol = 1e-9;   // the reference engine's arithmetic agrees with ours to about 1e-12 relative
    double atol = 1e-12;  // so that an expected 0 is matched by rounding noise, not by any small number
};

enum class FindingKind {
    value,             // a different value (or a different type of value)
    setting,           // a different resolver setting: everything downstream diverges
    scene,             // a different scene (bodies, materials, contacts as given)
    missing,           // in the reference, not in the other file (a key, an iteration, a contact)
    extra,             // in the other file, not in the reference
    blank,             // a worksheet cell left blank: not a mismatch, not a match
    not_in_reference,  // a worksheet cell whose path the reference does not have
};

std::string_view finding_kind_name(FindingKind kind);  // "value", "setting", ..., "not_in_reference"

struct Finding {
    FindingKind kind = FindingKind::value;
    std::string path;
    io::json expected;                     // the reference's value; null when extra
    io::json found;                        // the other's; null when missing or blank
    std::optional<double> relative_error;  // |a − b| / |a|, or |a − b| when a = 0; numbers only
    std::string quantity;                  // the vocabulary name the path ends in, when it has one
    std::string formula;
    std::string equation;
    bool first_divergence = false;
};

struct DiffReport {
    std::string other_kind;         // "trace" or "worksheet"
    std::size_t matched = 0;        // scalars that match
    std::size_t mismatched = 0;     // findings other than blank
    std::size_t blank = 0;          // blank worksheet cells (numbers)
    std::vector<Finding> findings;  // every mismatch and blank, in trace order

    const Finding* first_divergence() const;
    bool all_match() const { return mismatched == 0 && blank == 0; }
};

// Walks both trace documents (already checked against the trace schema) in the reference's order: the header
// (settings first among what can differ), then frame by frame the contacts, the phases and their iterations.
// Frames, contacts, phases and iterations are paired by their number ("frame", "contact", "phase",
// "iteration"), so one missing iteration is reported once rather than shifting every later one; other arrays
// by index.
DiffReport diff_traces(const io::json& reference, const io::json& other, const Tolerance& tolerance);

// Each cell of the sheet against the reference's value at its path, then the sheet's settings and scene
// against the reference's, sorted into trace order.
DiffReport diff_worksheet(const io::json& reference, const FilledWorksheet& sheet, const Tolerance& tolerance);

}  // namespace impulse::coursework
