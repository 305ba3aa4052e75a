#pragma once
// The inspector's actions, one per line of a --script file and one per key or button in the window:
//   next step | prev step | next contact | prev contact | next iteration | prev iteration
//   next item | prev item (a contact in the preparation, an iteration in a phase)
//   next phase | prev phase | first | last          (an optional count repeats a move: next step 3)
//   goto frame=F,phase=velocity,iteration=I,contact=C,step=NAME
//   set <setting> <value>                           (as --set setting=value; re-runs the scene)
//   view front|top|side|3d                         (the scene view's plane, or the rotatable view)
//   lesson step N                                  (the open lesson's step N, from 1)
//   key NAME | key ctrl+NAME                       (a key pressed and released: Right, Return, Tab, Escape, ...)
//   type TEXT                                      (text typed, the rest of the line: type 7,5 m/s)
//   screenshot FILE.png | export trace FILE.json | export table FILE.csv | quit
// Blank lines and lines starting with # are ignored, and so is a # after a space and what follows it (a comment
// after an action). Paths are relative to the working directory.

#include "model/session.hpp"

#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::model {

enum class ActionKind {
    next_step,
    previous_step,
    next_contact,
    previous_contact,
    next_iteration,
    previous_iteration,
    next_item,
    previous_item,
    next_phase,
    previous_phase,
    first,
    last,
    go_to,
    set,
    view,
    lesson_step,  // "lesson step N": the open lesson's step N (from 1)
    key,          // "key ctrl+s": a key pressed and released, through the window's own event queue
    type,         // "type 7,5": text typed, through the window's own event queue
    screenshot,
    export_trace,
    export_table,
    quit,
};

struct Action {
    ActionKind kind;
    std::string argument = {};  // the goto spec, the setting's "name=value", or the file
    int count = 1;              // how many times a move repeats
    int line = 0;               // in the script, for errors (0 = not from a script)
};

// Throws formats::InputError("line N", ...) for the first line that is not an action.
std::vector<Action> parse_script(std::string_view text);
// One action from its text, as typed in a script line.
Action parse_action(std::string_view text, int line);

// What only the window can do. Null in tests: a screenshot then fails with a clear error.
class ActionHost {
public:
    virtual ~ActionHost() = default;
    virtual void screenshot(const std::string& path) = 0;
    virtual void view(const std::string& plane) = 0;  // front, top, side or 3d
    virtual void lesson_step(int step) = 0;           // from 0; throws formats::InputError when there is none
    virtual void quit() = 0;
    // A key chord ("Right", "ctrl+s") or typed text put on the window's event queue, as the keyboard would: a
    // script drives the window as a student's keys do. Throws formats::InputError for a key it does not know.
    virtual void key(const std::string& chord) = 0;
    virtual void type(const std::string& text) = 0;
    // Where an export or screenshot named "-" goes (the command's standard output), or null when nowhere.
    virtual std::ostream* standard_output() { return nullptr; }
    // A file an export wrote (a browser offers it as a download).
    virtual void written(const std::string& /*path*/) {}
};

// Carries out one action. A move that would leave the trace, a bad goto or setting, or an unwritable file
// throws formats::InputError(where, ...) and changes nothing.
void perform(Session& session, const Action& action, std::string_view where, ActionHost* host);

// What a re-run with `assignment` ("restitution_cutoff=0") gave, for the window's status line and a script's
// terminal: "re-ran with …", then where the run stopped if a body became non-finite, or which frames it recorded
// if the trace budget cut the recording short. Whether it is an error (the run broke) goes in `is_error`.
std::string rerun_text(const Session& session, std::string_view assignment, bool* is_error = nullptr);

// The file an export writes: the trace as JSON, or the derivation table at the cursor as CSV.
std::string exported_trace(const Session& session);
std::string exported_table(const Session& session);

}  // namespace impulse::model
