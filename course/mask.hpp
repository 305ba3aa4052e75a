#pragma once
// Predict, then see: what a lesson's open questions hide, wherever the student looks (every table of the
// recording, the contacts list, the bodies, the scene, the plots and the navigator), until each is answered
// or skipped. A question hides:
//   - its quantity, the quantities its lesson says reveal it (`reveals`), and everything the vocabulary
//     computes from those (explain::consumers): the impulse and the velocity change give a desired Δv away;
//   - when it looks ahead (asked before the step that computes its quantity), that step's own inputs of the
//     quantity: the parts that add up to it;
//   - in every item about its contact, and about any contact whose same quantity has the answer's value
//     (the lesson's three objects all bounce back at the same speed);
//   - and when what it hides changes the bodies (an impulse, a move, an update), the state of the bodies
//     that change moved, from that item on, and every later item and contact value on those bodies;
//   - and anywhere, any value equal to its answer in the answer's unit (the resting ball's velocity is the
//     landing ball's velocity from acceleration), unless the answer is computed from it or is 0 (zeros are
//     everywhere and give nothing away).
// Pure functions of the lesson and a trace: the window, the terminal and the tests all ask the same mask.

#include "course/lesson.hpp"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

// What one question hides while it is open, over one trace.
struct QuestionReach {
    int step = -1;                            // the lesson step that asks the question (from 0)
    int frame = -1;                           // the frame index its place is in
    std::set<int> contacts;                   // its contact and those whose same quantity has the answer's value
    std::set<std::string, std::less<>> keys;  // vocabulary names hidden in those contacts' items
    // The bodies a hidden change moves, each with the first item (time order) that moves it: from there on
    // its state, and everything computed from it, is hidden.
    std::map<int, model::Cursor> bodies;
    // A predict question's answer, to hide any value equal to it.
    std::optional<double> answer;
    double allowed = 0.0;                       // its tolerance
    std::string unit;                           // its unit
    std::set<std::string, std::less<>> inputs;  // what it is computed from (directly or not): shown all the same
};

// One per step of the lesson (none for a step without a question), worked out on `trace`: the lesson's own
// run or a re-run with other settings (a question whose place is not in it hides its keys everywhere).
std::vector<std::optional<QuestionReach>> question_reaches(const PreparedLesson& lesson, const Trace& trace);

// The lesson step (from 0) whose open question hides a value, so a panel can say "hidden until you answer step
// 3" and link to it; none when the value is shown.
using HiddenBy = std::optional<int>;

class Mask {
public:
    Mask() = default;  // hides nothing
    // `open[i]`: step i's question is neither answered nor skipped. The trace is the one the reaches were
    // worked out on; the mask reads it in every query.
    Mask(const std::vector<std::optional<QuestionReach>>& reaches, const std::vector<bool>& open, const Trace& trace);

    bool empty() const { return reaches_.empty(); }

    // A row of a derivation table of the item `item` stands on (its step is ignored).
    HiddenBy row_hidden_by(const model::Cursor& item, const explain::Row& row) const;
    // The row's other-frame reading ("contact (…)" beside a world vector): hidden with the row, and also when it
    // reads as an open answer although the row itself is shown (a world velocity the student works from, whose
    // contact coordinates are the slip asked for).
    HiddenBy other_frame_hidden_by(const model::Cursor& item, const explain::Row& row) const;
    // A contact's bookkeeping value as the contacts list, the navigator and the plots show it just before
    // the item `at` stands on: "penetration", "desired_delta_velocity" or "impulse_world" (the impulse so far).
    HiddenBy value_hidden_by(const model::Cursor& at, int contact, std::string_view key, double value) const;
    // Which bodies a contact joins ("ball / world").
    HiddenBy bodies_hidden_by(int frame, int contact) const;
    // A body's state just before (after = false) or just after the item `at` stands on; `state` is that state.
    HiddenBy body_hidden_by(const model::Cursor& at, int body, bool after, const BodyState& state) const;
    // Whether a body's state at `at` is hidden for a hidden change (whatever its values).
    HiddenBy body_hidden_by(const model::Cursor& at, int body, bool after) const;
    // A value of `key` (in that quantity's unit, or `unit` when given) equal to an open answer it does not
    // feed into (`inputs_too`: or that it does).
    HiddenBy answer_equal_to(std::string_view key, double value, std::string_view unit = {},
                             bool inputs_too = false) const;

    bool hides_row(const model::Cursor& item, const explain::Row& row) const {
        return row_hidden_by(item, row).has_value();
    }
    bool hides_value(const model::Cursor& at, int contact, std::string_view key, double value) const {
        return value_hidden_by(at, contact, key, value).has_value();
    }
    bool hides_bodies_of(int frame, int contact) const { return bodies_hidden_by(frame, contact).has_value(); }
    bool hides_body(const model::Cursor& at, int body, bool after, const BodyState& state) const {
        return body_hidden_by(at, body, after, state).has_value();
    }
    bool hides_body(const model::Cursor& at, int body, bool after) const {
        return body_hidden_by(at, body, after).has_value();
    }
    bool equals_an_answer(std::string_view key, double value, std::string_view unit = {}) const {
        return answer_equal_to(key, value, unit).has_value();
    }
    // The item before which a hidden body was last shown, to draw it where it was; none when it is not hidden
    // at `at`.
    std::optional<model::Cursor> body_shown_until(const model::Cursor& at, int body) const;

private:
    // Items run in this order within a frame: the preparation (0), then the phases' iterations (1, 2, ...).
    int rank(const model::Cursor& c) const;
    // Whether a body hidden from `from` is hidden at `at`: strictly later (before = its state going in), or
    // also at `from` itself (after).
    bool later(const model::Cursor& at, const model::Cursor& from, bool including) const;
    HiddenBy touches_hidden_body(const model::Cursor& at, int contact, bool including) const;

    std::vector<QuestionReach> reaches_;
    const Trace* trace_ = nullptr;
};

}  // namespace impulse::course
