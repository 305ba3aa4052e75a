#pragma once
// Where the inspector stands in a trace, and how it moves. A trace reads as a tree: frame -> stage
// (the contacts as prepared, then the two phases in the order they ran) -> item (a prepared contact, or
// one iteration and the contact it chose) -> derivation step (one annotated table). Every move is a
// plain function of (trace, cursor): stepping back lands exactly where stepping forward came from,
// because both read the recording and nothing is simulated again.

#include "explain/derivation_table.hpp"
#include "record/trace.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::model {

enum class Stage {
    preparation,  // steps 1-5 of each contact, computed once when the frame's contacts were prepared
    position,     // the position phase's iterations (step 8)
    velocity,     // the velocity phase's iterations (steps 4-7)
};

std::string_view stage_name(Stage stage);  // "preparation", "position", "velocity"

struct Cursor {
    int frame = 0;  // index into trace.frames (not the frame number)
    Stage stage = Stage::preparation;
    int item = 0;  // preparation: index into the frame's recorded contacts; a phase: the iteration
    int step = 0;  // index into step_tables(trace, cursor)

    bool operator==(const Cursor&) const = default;
};

// The stages of a frame in the order they ran, leaving out those with nothing to step through.
std::vector<Stage> stages(const FrameRecord& frame);
int item_count(const FrameRecord& frame, Stage stage);

// The annotated tables of the cursor's item: for a prepared contact steps 1-5; for an iteration first the
// choice (which contact, its value against the epsilon), then the step tables of its move or impulse.
std::vector<explain::StepTable> step_tables(const Trace& trace, const Cursor& cursor);

// The names of those tables' steps, read from the record's shape without formatting: what moves count and name.
std::vector<std::string_view> step_names(const Trace& trace, const Cursor& cursor);

// The recorded preparation of contact `contact` (its index in the frame's contact list), or null when the
// recording's contact filter left it out.
const ContactPreparation* preparation_of(const FrameRecord& frame, int contact);

// The contact the cursor's item is about (its index in the frame's contact list).
int contact_at(const Trace& trace, const Cursor& cursor);

// The first and last places in the trace; none when nothing at all was recorded.
std::optional<Cursor> first_cursor(const Trace& trace);
std::optional<Cursor> last_cursor(const Trace& trace);

// Moves. Each returns none at the end of the trace (the caller stays where it is).
// step: the next or previous table, crossing into the neighbouring item, stage and frame.
std::optional<Cursor> next_step(const Trace& trace, const Cursor& cursor);
std::optional<Cursor> previous_step(const Trace& trace, const Cursor& cursor);
// item: the next or previous contact (preparation) or iteration (a phase), on the step of the same name
// when the new item has it, else its first step; crosses stages and frames.
std::optional<Cursor> next_item(const Trace& trace, const Cursor& cursor);
std::optional<Cursor> previous_item(const Trace& trace, const Cursor& cursor);
// contact: in preparation the next prepared contact; in a phase the next iteration that chose a different
// contact from the current one.
std::optional<Cursor> next_contact(const Trace& trace, const Cursor& cursor);
std::optional<Cursor> previous_contact(const Trace& trace, const Cursor& cursor);
// iteration: the next iteration of a phase (from preparation, the first phase's first iteration).
std::optional<Cursor> next_iteration(const Trace& trace, const Cursor& cursor);
std::optional<Cursor> previous_iteration(const Trace& trace, const Cursor& cursor);
// stage: the first step of the next stage (or the next frame's first stage).
std::optional<Cursor> next_stage(const Trace& trace, const Cursor& cursor);
std::optional<Cursor> previous_stage(const Trace& trace, const Cursor& cursor);

// A place named by a person: --goto frame=F,phase=preparation|position|velocity,iteration=I,contact=C,
// step=NAME. Every part is optional; `step` takes a step name ("impulse") or any quantity of the word list, by its
// full name ("position_change.angular_change") or its last part ("angular_change"; a last part two words share
// means the later, the step's result): the step that computes it, or for a given value the first that shows it.
struct GotoSpec {
    std::optional<int> frame;  // the frame number, as recorded
    std::optional<Stage> stage;
    std::optional<int> iteration;
    std::optional<int> contact;
    std::optional<std::string> step;
};

// Throws formats::InputError(where, ...) for a malformed spec.
GotoSpec parse_goto(std::string_view text, std::string_view where);
// Throws formats::InputError(where, ...) naming what the trace does not have.
Cursor resolve_goto(const Trace& trace, const GotoSpec& spec, std::string_view where);

// Where the cursor stands, as it would be written back: stays valid after re-running the same scene with
// other settings, so the inspector can return to the same contact and step.
struct Location {
    int frame_number = 0;
    Stage stage = Stage::preparation;
    int iteration = 0;
    int contact = 0;
    std::string step;
};
Location location_of(const Trace& trace, const Cursor& cursor);
// The nearest cursor to a location in a (re-run) trace: same frame and stage; the same contact (in a phase,
// the iteration nearest the old one that resolves it, else the same iteration number);
// same step by name; whatever no longer exists falls back to the closest that does.
std::optional<Cursor> nearest_cursor(const Trace& trace, const Location& location);

// A body's name in the trace's scene, or "world" for the static world (world_body).
std::string body_label(const Trace& trace, int body);

// "frame 0 · velocity phase · iteration 3 · contact 1 · impulse"
std::string describe(const Trace& trace, const Cursor& cursor);

}  // namespace impulse::model
