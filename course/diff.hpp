#pragma once
// Comparing a trace, or a filled worksheet, with a reference trace, value by value in trace order. A number
// matches when |found − expected| ≤ atol + rtol·|expected|; text and booleans must be equal. The first
// mismatch in trace order is the first divergence: later ones often follow from it.

#include "course/filled_worksheet.hpp"
#include "course/tolerance.hpp"
#include "record/trace.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

enum class FindingKind {
    value,             // a different value (or a different type of value)
    setting,           // a different resolver setting: everything downstream diverges
    scene,             // a different scene (bodies, materials, contacts as given)
    missing,           // in the reference, not in the other file (a key, an iteration, a contact)
    extra,             // in the other file, not in the reference
    blank,             // a worksheet cell left blank: not a mismatch, not a match
    not_in_reference,  // a worksheet cell whose path the reference does not have
    duplicate,         // a worksheet cell given again (its first answer is the one graded)
    not_asked,         // a worksheet cell the reference has but did not ask for
    empty,             // a worksheet that gives no cell at all
};

std::string_view finding_kind_name(FindingKind kind);  // "value", "setting", ..., "not_in_reference"

struct Finding {
    FindingKind kind = FindingKind::value;
    std::string path;
    formats::json expected;                // the reference's value; null when extra
    formats::json found;                   // the other's; null when missing or blank
    std::optional<double> relative_error;  // |a − b| / |a|, or |a − b| when a = 0; numbers only
    // In the worksheet's own words (word_path; filled by word_findings): the step's place and the value's name
    // there ("impulse_world[1]"); until then the vocabulary name the path ends in, when it has one.
    std::string place;
    std::string quantity;
    std::string unit;
    std::string formula;
    std::string equation;
    bool first_divergence = false;
};

// One number of a worksheet's cells as graded: right, wrong, or left blank.
enum class Verdict { right, wrong, blank };
std::string_view verdict_name(Verdict verdict);  // "right", "wrong", "blank"

struct GradedNumber {
    std::string path;
    formats::json expected;  // null for a cell the reference does not have
    formats::json found;     // null when blank
    std::optional<double> relative_error;
    Verdict verdict = Verdict::right;
    std::string place;  // as Finding's
    std::string quantity;
    std::string unit;
};

struct DiffReport {
    std::string other_kind;            // "trace" or "worksheet"
    std::size_t matched = 0;           // scalars that match
    std::size_t mismatched = 0;        // findings other than blank
    std::size_t blank = 0;             // blank worksheet cells (numbers)
    std::vector<Finding> findings;     // every mismatch and blank, in trace order
    std::vector<GradedNumber> graded;  // a worksheet: every number of every cell, in trace order

    const Finding* first_divergence() const;
    bool all_match() const { return mismatched == 0 && blank == 0; }
};

// The grade of one file (docs/coursework.md, "Score"). A worksheet: every number of the cells it was asked for
// counts once, right, wrong or blank, and every number given again, not asked for or not in the reference counts
// as wrong; a sheet with no cells scores 0. A trace: every number compared counts once and a missing or extra
// element (an iteration, a key) once; there is nothing to leave blank. score = right / cells × 100.
struct Score {
    std::size_t cells = 0;
    std::size_t right = 0;
    std::size_t wrong = 0;
    std::size_t blank = 0;
    std::optional<double> percent;
};
Score score_of(const DiffReport& report);

// Walks both trace documents (already checked against the trace schema) in the reference's order: the header
// (settings first among what can differ), then frame by frame the contacts, the phases and their iterations.
// Frames, contacts, phases and iterations are paired by their number ("frame", "contact", "phase",
// "iteration"), so one missing iteration is reported once rather than shifting every later one; other arrays
// by index.
DiffReport diff_traces(const formats::json& reference, const formats::json& other, const Tolerance& tolerance);

// The sheet's cells matched, number by number, to the reference's places, then the sheet's settings and scene
// against the reference's, sorted into trace order. The places are `asked` when it is known (the reference is a
// worksheet or a lesson: the paths of the cells the sheet was handed out with), else every cell of each step the
// sheet answers something of (the step's cells as `worksheet` makes them). Each number of those places is graded
// once: right, wrong, or blank when the sheet leaves it empty or out. A number given again (a duplicate), one
// the places do not hold (not asked, or not in the reference) is a finding and counts as wrong; a sheet with no
// cells is a finding (empty) and scores 0.
DiffReport diff_worksheet(const formats::json& reference, const FilledWorksheet& sheet, const Tolerance& tolerance,
                          const std::vector<std::string>* asked = nullptr);

// Words every finding's and graded number's path as the worksheet does (word_path): its place and quantity.
void word_findings(DiffReport& report, const Trace& trace, const formats::json& reference);
// Words them as an answer key's own cells do (its step, quantity and unit columns): a key carries no trace.
void word_findings_by_key(DiffReport& report, const FilledWorksheet& key);

}  // namespace impulse::course
