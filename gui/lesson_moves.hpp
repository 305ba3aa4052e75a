#pragma once
// Moving through a lesson in the window, shared by the lesson panel's parts: every move away from a step whose
// question is still open first asks ("skip this question?"), an answer is checked or refused beside its field,
// and the last step leads to the end-of-lesson screen. Keys and buttons both come here.

#include "gui/ui_state.hpp"

namespace impulse::gui {

// A move to `step` (the step count: the end of the lesson). Moving on from an open question asks first; moving
// back to read an earlier step never does.
void request_step(model::Session& session, UiState& state, int step);
// The student's word on the pending move: go on with the question left open, or stay on it.
void leave_open(model::Session& session, UiState& state);
void stay(UiState& state);
// Checks what is typed or picked; an empty field or a refused number is said beside the field.
void check_typed(model::Session& session, UiState& state);
// Gives the current question up (its answer shown); a pending move then goes on.
void skip_question(model::Session& session, UiState& state);

// The keys of a lesson (panels.hpp lists them), from `state.pressed_keys` and the characters typed this frame.
void handle_lesson_keys(model::Session& session, UiState& state);

// The steps as a row of numbered buttons, each marked with its question's state (open, answered, skipped).
void draw_step_list(model::Session& session, UiState& state);
// The question asked before a move leaves it open: its buttons and keys.
void draw_leaving_prompt(model::Session& session, UiState& state);
// The end of the lesson: the score, the open questions with a jump to each, the next lesson.
void draw_lesson_end(model::Session& session, UiState& state);

}  // namespace impulse::gui
