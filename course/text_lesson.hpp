#pragma once
// A lesson in a terminal. Interactive: each step's text and tables with what its open questions hide shown
// as "?", the question asked and the answer waited for, how far off a wrong answer is, a retry or a skip,
// and progress saved after each as the window saves it. Not interactive (no terminal to read from): the
// annotated lesson with the engine's answers, written at once.

#include "course/lesson_run.hpp"

#include <istream>
#include <ostream>

namespace impulse::course {

// Reads answers and commands line by line from `in` until the lesson ends, the student types q, or `in`
// ends; `width` is the terminal's, for wrapping the text. The commands: Enter the next step, a number (or
// an option's number) to answer, s to skip the question, b the previous step, q to quit.
void take_lesson(LessonRun& run, std::istream& in, std::ostream& out, int width);

// The lesson as annotated text: each step's place, text, question, the step's table and the engine's answer.
void write_annotated_lesson(std::ostream& out, const PreparedLesson& prepared);

// The lines of `text` that fit `width` columns, broken at spaces (a word longer than a line stays whole).
std::string wrap_text(std::string_view text, int width, std::string_view indent = "");

}  // namespace impulse::course
