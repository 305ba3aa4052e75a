#include "course/lesson_run.hpp"

#include "formats/input_error.hpp"

#include <algorithm>
#include <climits>

namespace impulse::course {

LessonRun::LessonRun(const PreparedLesson& lesson, Progress* progress, std::optional<std::filesystem::path> file)
    : lesson_(&lesson), progress_(progress), file_(std::move(file)) {
    const std::vector<Step>& steps = lesson.lesson.steps;
    states_.assign(steps.size(), QuestionState::none);
    feedback_.assign(steps.size(), {});
    given_.assign(steps.size(), {});
    tries_.assign(steps.size(), 0);
    for (std::size_t i = 0; i < steps.size(); ++i)
        if (steps[i].question) states_[i] = QuestionState::open;
    if (!progress_) return;
    const auto found = progress_->lessons.find(lesson.lesson.name);
    if (found == progress_->lessons.end()) return;
    // Back where the student left off, each question as it stood.
    step_ = std::clamp(found->second.last_step, 0, step_count() - 1);
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const auto saved = found->second.answers.find(steps[i].id);
        if (!steps[i].question || saved == found->second.answers.end()) continue;
        const AnswerRecord& a = saved->second;
        tries_[i] = a.tries;
        given_[i] = a.answer;
        if (a.skipped) {
            states_[i] = QuestionState::skipped;
            feedback_[i] = skipped_text(*lesson.answers[i]);
            continue;
        }
        if (a.tries == 0) continue;
        try {
            const AnswerVerdict v = check_answer(*steps[i].question, *lesson.answers[i], a.answer);
            states_[i] = v.correct ? QuestionState::answered : QuestionState::open;
            feedback_[i] = v.feedback;
        } catch (const formats::InputError&) {
            // An answer the lesson no longer accepts (its options changed): asked again.
        }
    }
}

void LessonRun::go_to(int step) {
    step_ = std::clamp(step, 0, step_count() - 1);
    if (progress_) {
        progress_->lessons[lesson_->lesson.name].last_step = step_;
        save();
    }
}

AnswerRecord* LessonRun::record(int step) {
    if (!progress_) return nullptr;
    return &progress_->lessons[lesson_->lesson.name].answers[lesson_->lesson.steps[static_cast<std::size_t>(step)].id];
}

AnswerVerdict LessonRun::answer(std::string_view typed) {
    const auto i = static_cast<std::size_t>(step_);
    const AnswerVerdict verdict = check_answer(*current().question, *lesson_->answers[i], typed);
    if (states_[i] != QuestionState::open) return verdict;  // already settled: a check, not a new answer
    states_[i] = verdict.correct ? QuestionState::answered : QuestionState::open;
    feedback_[i] = verdict.feedback;
    given_[i] = std::string(typed);
    // Counts stop at the largest int rather than wrap negative (a negative count made the next start throw the
    // progress file aside).
    if (tries_[i] < INT_MAX) ++tries_[i];
    if (AnswerRecord* r = record(step_)) {
        r->answer = std::string(typed);
        r->correct = verdict.correct;
        if (r->tries < INT_MAX) ++r->tries;
        save();
    }
    return verdict;
}

void LessonRun::skip() {
    const auto i = static_cast<std::size_t>(step_);
    if (states_[i] != QuestionState::open) return;
    states_[i] = QuestionState::skipped;
    feedback_[i] = skipped_text(*lesson_->answers[i]);
    if (AnswerRecord* r = record(step_)) {
        r->skipped = true;
        r->correct = false;
        save();
    }
}

void LessonRun::answered_before(int step) {
    for (int i = 0; i < step_count(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (states_[k] == QuestionState::none) continue;
        states_[k] = i < step ? QuestionState::answered : QuestionState::open;
        feedback_[k] = i < step ? "right: the engine has " + lesson_->answers[k]->shown : std::string();
    }
}

Tally LessonRun::tally() const {
    Tally t;
    for (std::size_t i = 0; i < states_.size(); ++i) {
        if (states_[i] == QuestionState::skipped)
            ++t.skipped;
        else if (states_[i] == QuestionState::answered)
            ++(tries_[i] <= 1 ? t.first_try : t.after_retries);
        else if (states_[i] == QuestionState::open && tries_[i] > 0)
            ++t.open;
    }
    return t;
}

std::vector<bool> LessonRun::open() const {
    std::vector<bool> open(states_.size());
    for (std::size_t i = 0; i < states_.size(); ++i) open[i] = states_[i] == QuestionState::open;
    return open;
}

void LessonRun::save() {
    if (!progress_ || !file_) return;
    try {
        save_progress(*file_, *progress_);
        save_problem_.clear();
    } catch (const formats::InputError& e) {
        save_problem_ = e.problem();
    }
}

}  // namespace impulse::course
