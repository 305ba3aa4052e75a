#include "course/lesson_end.hpp"

#include "formats/input_error.hpp"

namespace impulse::course {

std::optional<LessonLink> lesson_after(const std::filesystem::path& folder, int number) {
    try {
        for (const std::filesystem::path& file : lesson_files(folder)) {
            const Lesson lesson = read_lesson(file);
            if (lesson.number > number) return LessonLink{lesson.number, lesson.title, file};
        }
    } catch (const formats::FileError&) {
        // A lesson that cannot be read is not offered; `impulse-lab lesson` names its problem.
    }
    return std::nullopt;
}

LessonEnd lesson_end(const LessonRun& run) {
    LessonEnd end;
    for (int i = 0; i < run.step_count(); ++i) {
        switch (run.state(i)) {
            case QuestionState::none:
                continue;
            case QuestionState::answered:
                ++(run.tries(i) <= 1 ? end.first_try : end.after_retries);
                break;
            case QuestionState::skipped:
                ++end.skipped;
                break;
            case QuestionState::open:
                end.open_steps.push_back(i);
                break;
        }
        ++end.questions;
    }
    return end;
}

std::string score_text(const LessonEnd& end) {
    const std::string text = std::to_string(end.questions) + (end.questions == 1 ? " question" : " questions");
    std::string parts;
    if (end.first_try + end.after_retries + end.skipped > 0)
        parts = tally_text(Tally{end.first_try, end.after_retries, end.skipped, 0});
    if (const auto open = end.open_steps.size(); open > 0)
        parts += (parts.empty() ? "" : ", ") + std::to_string(open) + " still open";
    return parts.empty() ? text : text + ": " + parts;
}

std::string open_question_text(const LessonRun& run, int step) {
    const Step& s = run.lesson().lesson.steps[static_cast<std::size_t>(step)];
    return "step " + std::to_string(step + 1) + " · " + s.id + (s.question ? ": " + s.question->prompt : "");
}

}  // namespace impulse::course
