#pragma once
// The end of a lesson, as the window and the terminal both show it: the score (right at the first try, right
// after retries, skipped), the questions still open with the step each is on, and the lesson that comes next.

#include "course/lesson_run.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impulse::course {

// A lesson named by its number and title, to offer it ("Lesson 4 · Contact coordinates").
struct LessonLink {
    int number = 0;
    std::string title;
    std::filesystem::path file;
};

// The first lesson of `folder` numbered above `number`; none after the last one, or when its file cannot be read
// (it is then listed with its error by `impulse-lab lesson`).
std::optional<LessonLink> lesson_after(const std::filesystem::path& folder, int number);

struct LessonEnd {
    int questions = 0;
    int first_try = 0;
    int after_retries = 0;
    int skipped = 0;
    std::vector<int> open_steps;  // steps (from 0) whose question is neither answered nor skipped
};

LessonEnd lesson_end(const LessonRun& run);

// "6 questions: 3 right at the first try, 1 right after retries, 1 skipped, 1 still open".
std::string score_text(const LessonEnd& end);

// "step 5 · slip: How fast does corner 0 slip along tangent 2 (m/s)?"
std::string open_question_text(const LessonRun& run, int step);

}  // namespace impulse::course
