#pragma once
// A worksheet: for chosen derivation steps of a trace, the values each step starts from (inputs, given) and
// the values it computes (cells, left blank), each addressed by its JSON path into the trace document, with
// its unit, formula, the chapter's equation and meaning. Students fill the cells by hand or with their own
// engine; `impulse-lab diff` grades the filled sheet against the reference trace. docs/coursework.md.
//
// Places come from anywhere that can name inspector cursors: `impulse-lab worksheet --steps SPEC` (the
// inspector's --goto syntax), the first frame by default, or a lesson's places.

#include "course/json_path.hpp"
#include "course/tolerance.hpp"
#include "course/worksheet_entry.hpp"
#include "formats/json_values.hpp"
#include "model/session.hpp"

#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace impulse::course {

inline constexpr std::string_view worksheet_format_name = "impulse-lab-worksheet";
inline constexpr int worksheet_format_version = 1;

struct WorksheetStep {
    std::string place;  // "frame 0 · velocity phase · iteration 0 · contact 0 · impulse"
    std::string at;  // the same place as --steps and --goto take it: "frame=0,phase=velocity,iteration=0,step=impulse"
    std::vector<WorksheetEntry> inputs;
    std::vector<WorksheetEntry> cells;
};

struct Worksheet {
    std::string source;         // the file the session opened
    formats::json conventions;  // the trace header's
    formats::json settings;     // the trace header's: every setting that ran
    formats::json reference;    // enough to re-run it: {run: {mode, frames}, recording, scene} as in the trace header
    std::vector<WorksheetStep> steps;
};

// The worksheet of `places` (inspector cursors into session.trace()), in the order given, repeats left out.
// A step's inputs are the item's givens, the settings its steps use up to this one, the values its earlier
// steps computed, the bodies' mass properties (and, for a contact, their state before the frame), for an
// iteration the chosen contact as prepared, and what the step's formula needs from outside the item (the
// frame's duration and last-frame accelerations, the chosen contact's value as earlier iterations left it, an
// updated contact's geometry: course/worksheet_inputs.cpp), so every cell can be worked out from the sheet;
// an input that is also a cell somewhere on the sheet is not given away, and inputs are rounded for work by hand.
// Throws formats::InputError("--steps", ...) for a place whose step computes nothing to fill in.
// `document`, when given, is formats::trace_json(session.trace()) made already (a big frame's takes a while).
Worksheet make_worksheet(const model::Session& session, const std::vector<model::Cursor>& places,
                         const formats::json* document = nullptr);

// The places among `candidates` whose step computes something to fill in (a lesson's places, for its worksheet).
std::vector<model::Cursor> places_with_cells(const model::Session& session,
                                             const std::vector<model::Cursor>& candidates,
                                             const formats::json* document = nullptr);

// Every step with something to fill in, of every item of the first recorded frame; empty when nothing is
// recorded. `document` is the trace as JSON when the caller has it already (else it is made).
std::vector<model::Cursor> default_places(const Trace& trace, const formats::json* document = nullptr);

// The places `specs` name (--steps, the inspector's --goto syntax). A spec with `step=` names one step, one
// without it every step of the item it names. Throws formats::InputError(where, ...). `document` as above.
std::vector<model::Cursor> places_from_specs(const Trace& trace, const std::vector<std::string>& specs,
                                             std::string_view where, const formats::json* document = nullptr);

// The reference trace re-run from a worksheet document's "settings" and "reference" (so a worksheet can stand
// in for the file it was made from). Throws formats::InputError with the JSON path of a problem.
Trace rerun_reference(const formats::json& worksheet_document);

// As a file: JSON (cells' values null, vectors and matrices [null, null, null]) or CSV (one row per number:
// kind,path,step,quantity,value,unit,formula,equation,meaning; an input shown once, before the first step
// that uses it).
formats::json worksheet_json(const Worksheet& sheet);
std::string worksheet_csv(const Worksheet& sheet);

inline constexpr std::string_view worksheet_csv_header = "kind,path,step,quantity,value,unit,formula,equation,meaning";

// What a written sheet shows: its cells (entries), the numbers in them, and its inputs. A CSV sheet has a row
// per number, cell or input, each input once; a JSON sheet lists each step's inputs with the step.
struct WorksheetCounts {
    std::size_t cells = 0;
    std::size_t numbers = 0;
    std::size_t inputs = 0;
};
WorksheetCounts csv_counts(const Worksheet& sheet);   // inputs: the input rows
WorksheetCounts json_counts(const Worksheet& sheet);  // inputs: the entries of every step's inputs

// Inputs are written for work by hand: each number as the shortest decimal within `hand_rounding_share` of
// what diff tolerates by default (|r − x| ≤ (atol + rtol·|x|) / 1000: 1e-15 + 1e-12·|x|), so 24.000000000000004
// is given as 24 and 1.1e-16 as 0, while a cell worked out from the rounded inputs still matches the reference
// (tests/course/test_blank_cells.cpp works every cell of every shipped lesson and case out that way).
inline constexpr double hand_rounding_share = 1e-3;
double rounded_for_hand_work(double value);
// The same within a share of another tolerance (a class graded with --rtol 1e-4 shows its expected values so).
double rounded_for_hand_work(double value, const Tolerance& grading);
formats::json rounded_for_hand_work(const formats::json& value);  // numbers inside arrays too; other values as they are

// How the worksheet names the value at a path of a trace document: the place of the step that computes it
// (as WorksheetStep::place writes it: "frame 0 · velocity phase · iteration 0 · contact 0 · impulse"; for a
// given of an item the item alone; "frame 3" elsewhere in a frame; "settings", "scene"), the value's name there
// (WorksheetEntry::quantity with its components: "impulse_world[1]", "updates[0].after") and its unit.
struct Wording {
    std::string place;
    std::string quantity;
    std::string unit;
};
// Wording a path formats its item's tables to learn the order of its steps: `cache`, when given, keeps what it
// learnt per item and step, so wording every number of a large sheet takes time linear in their count.
struct WordingCache {
    std::map<std::tuple<int, int, int>, std::vector<std::string>> step_orders;  // (frame, stage, item)
    std::map<std::tuple<int, int, int, int>, std::string> places;               // (frame, stage, item, step)
};
Wording word_path(const Trace& trace, const formats::json& document, const std::vector<PathToken>& path,
                  WordingCache* cache = nullptr);

// How a scalar is written in a worksheet's or report's CSV: numbers as the shortest text that reads back to
// the same double, booleans true/false, strings as they are, null empty.
std::string scalar_text(const formats::json& value);

// Calls `visit(path, value)` for every scalar of `value` (numbers, strings, booleans and nulls inside arrays),
// its path extended by [i] for each array it is in.
template <typename Visit>
void for_each_scalar(const formats::json& value, const std::string& path, Visit&& visit) {
    if (value.is_array()) {
        for (std::size_t i = 0; i < value.size(); ++i)
            for_each_scalar(value[i], path + "[" + std::to_string(i) + "]", visit);
    } else {
        visit(path, value);
    }
}

}  // namespace impulse::course
