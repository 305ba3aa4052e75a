#pragma once
// A student taking a lesson: the step they are on, where each question stands (open, answered, skipped),
// what they were told, and their progress saved after every answer, skip and move. The window and the
// terminal both drive one of these, so both save progress the same way.

#include "course/lesson.hpp"
#include "course/progress.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

enum class QuestionState {
    none,      // the step asks nothing
    open,      // not answered yet (perhaps tried): its value and what gives it away stay hidden
    answered,  // answered right
    skipped,   // the student asked for the answer
};

class LessonRun {
public:
    // Resumes where `progress` left the lesson (its step, and each question as it stood); `progress` and
    // `file` may be null and empty: nothing is then saved.
    LessonRun(const PreparedLesson& lesson, Progress* progress, std::optional<std::filesystem::path> file);

    const PreparedLesson& lesson() const { return *lesson_; }
    int step() const { return step_; }
    int step_count() const { return static_cast<int>(lesson_->lesson.steps.size()); }
    const Step& current() const { return lesson_->lesson.steps[static_cast<std::size_t>(step_)]; }

    // Moves to a step (clamped to the lesson) and saves it as the place to come back to.
    void go_to(int step);

    QuestionState state(int step) const { return states_[static_cast<std::size_t>(step)]; }
    // Whether the current step's question waits for an answer.
    bool waiting() const { return state(step_) == QuestionState::open; }
    // The last thing the student was told about a step's question (a verdict, or the skipped answer).
    const std::string& feedback(int step) const { return feedback_[static_cast<std::size_t>(step)]; }
    // The last answer the student gave to a step's question, as typed ("7.4", or an option's number from 1).
    const std::string& given(int step) const { return given_[static_cast<std::size_t>(step)]; }
    // How many answers the student gave to a step's question (a skip is not one).
    int tries(int step) const { return tries_[static_cast<std::size_t>(step)]; }
    // Whether that last answer was right.
    bool right(int step) const { return state(step) == QuestionState::answered; }

    // Checks an answer to the current step's open question, records and saves it. Throws formats::InputError
    // ("answer", ...) when the text is not a number (or not an option's number): nothing is recorded then.
    AnswerVerdict answer(std::string_view typed);
    // Gives the current step's open question up: its answer is shown and recorded as skipped.
    void skip();

    // Takes every question before `step` as answered and every later one as open, recording nothing: the
    // headless pictures show each step as a student who answered each question in turn sees it.
    void answered_before(int step);

    // How the questions went so far (tries counted since the lesson was opened, and before when resumed).
    Tally tally() const;

    // Per step: whether its question is open, for the mask.
    std::vector<bool> open() const;

    // The last failure to save progress, one line; empty when the last save worked.
    const std::string& save_problem() const { return save_problem_; }

private:
    AnswerRecord* record(int step);
    void save();

    const PreparedLesson* lesson_;
    Progress* progress_;
    std::optional<std::filesystem::path> file_;
    int step_ = 0;
    std::vector<QuestionState> states_;
    std::vector<std::string> feedback_;
    std::vector<std::string> given_;
    std::vector<int> tries_;
    std::string save_problem_;
};

}  // namespace impulse::course
