#pragma once
// A lesson in a terminal. Interactive: each step's text (its terminal reading) and table fitted to the terminal,
// with what its open questions hide shown as "? (hidden until you answer step N)", the question asked and the
// answer read by the one reader the window uses, how far off a wrong answer is (or the slip it looks like), a
// retry or a skip, keys for what the window's panels show (the bodies, the contacts, the phase's order), settings
// changed as the window's Settings tab changes them, and at the end the score, the open questions and the next
// lesson; progress saved after each as the window saves it. Not interactive (no terminal to read from): the
// annotated lesson with the engine's answers, written at once.

#include "course/lesson_end.hpp"
#include "course/lesson_run.hpp"

#include <istream>
#include <optional>
#include <ostream>

namespace impulse::course {

// What the student chose at the end: to open the next lesson, or to stop.
struct TerminalOutcome {
    bool next_lesson = false;
};

// Reads answers and commands line by line from `in` until the student quits or `in` ends; `width` is the
// terminal's, for wrapping the text and fitting the tables. `prepared` is the lesson `run` takes: a setting
// changed with `set` re-runs its session. `next` is offered at the end. The commands: Enter the next step, an
// answer, s skip, b back, g N step N, t the item's earlier tables, o the bodies, c the contacts, i the phase's
// order, set NAME VALUE, h help, q quit.
TerminalOutcome take_lesson(PreparedLesson& prepared, LessonRun& run, std::istream& in, std::ostream& out, int width,
                            const std::optional<LessonLink>& next = std::nullopt);

// The lesson as annotated text: each step's place, text, question, the step's table and the engine's answer.
void write_annotated_lesson(std::ostream& out, const PreparedLesson& prepared);

// The lines of `text` that fit `width` columns, broken at spaces (a word longer than a line stays whole).
std::string wrap_text(std::string_view text, int width, std::string_view indent = "");

}  // namespace impulse::course
