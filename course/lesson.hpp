#pragma once
// Lessons (docs/lessons.md): a scene, its settings, and an ordered path through its trace, each step with
// text and perhaps a question. Reading checks the header against schemas/lesson.schema.json and pairs each
// step with its "## id" section; preparing runs the scene and checks that every place exists and every
// question's answer can be read from the trace. The answers are the engine's values, never the author's.

#include "model/session.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace impulse::course {

struct AnswerTolerance {
    std::optional<double> relative;  // |answer - value| <= relative |value|
    std::optional<double> absolute;  // |answer - value| <= absolute, in the value's unit
};

struct Option {
    std::string label;
    nlohmann::ordered_json value;
};

struct Question {
    enum class Kind { predict, choose } kind;
    std::string prompt;
    std::string value;  // a path inside the place's item: "desired_delta_velocity", "impulse_world[1]"
    AnswerTolerance tolerance;
    std::vector<Option> options;
    // Vocabulary names whose values would give this answer away (a step's table that shows it under another
    // name): hidden with the answer, and with what is computed from them, until the question is answered.
    std::vector<std::string> reveals;
};

struct Step {
    std::string id;
    std::string at;  // a place, as inspect --goto takes it
    std::optional<Question> question;
    std::string text;  // the step's Markdown section
};

struct Lesson {
    std::filesystem::path file;
    std::string name;  // the file's stem: "01-impulse-is-a-velocity-change"
    int number = 0;    // from the name's leading digits
    std::string title;
    std::filesystem::path scene;  // resolved against the lesson's folder
    std::vector<std::string> settings;
    std::optional<int> frames;
    std::vector<std::string> record;  // as --record takes them: frames=A..B, contacts=I,J
    std::string introduction;         // the text before the first section
    std::vector<Step> steps;
    std::vector<std::string> notes;  // old words read by their new names: "steps[2].at: step \"a\" is now \"b\""
};

// How many of the lesson's steps ask a question.
int question_count(const Lesson& lesson);

// Throws formats::InputError("line N" or a header JSON path, problem); `file` names the lesson.
Lesson read_lesson_text(std::string_view text, const std::filesystem::path& file);
// Throws formats::FileError naming the file.
Lesson read_lesson(const std::filesystem::path& file);

// The lesson files of a folder (NN-*.md), in number order.
std::vector<std::filesystem::path> lesson_files(const std::filesystem::path& folder);

// The engine's answer to a question.
struct Answer {
    nlohmann::ordered_json value;  // a number for predict; the trace's value for choose
    std::string quantity;          // the vocabulary name of the value asked for ("velocity_update")
    std::string unit;              // the quantity's unit ("m/s"); empty for a value without one
    int correct_option = -1;       // choose: the index of the option equal to the value
    std::string shown;             // "3.24 m/s", or the correct option's label
};

// A lesson with its run: the place of each step and the answer of each question.
struct PreparedLesson {
    Lesson lesson;
    model::Session session;
    std::vector<model::Cursor> places;           // one per step
    std::vector<std::optional<Answer>> answers;  // one per step: none without a question
};

// Runs the lesson's scene with its settings; throws formats::FileError naming the lesson file and the header
// path of the first step whose place or question does not work with this run.
PreparedLesson prepare_lesson(Lesson lesson);

// How close a typed number is to the value a table shows: six significant digits, so within half the sixth.
inline constexpr double shown_precision = 5e-6;

// What a student typed (a number, or for choose the option's number from 1), against the engine's answer. A
// wrong answer says how far off it is, never the answer: the student may try again, or skip to see it.
struct AnswerVerdict {
    bool correct = false;
    // One line: "right: the engine has 3.24 m/s (you were 1.2 % off)" (no share when the answer is the value
    // as a table shows it), "not quite: 33.3 % too low; try again, or skip to see the engine's value", or the
    // slip it looks like instead of the share ("not quite: the opposite sign: ...").
    std::string feedback;
};
// Reads the number with course/answer_number.hpp. Throws formats::InputError("answer", ...) when the text is not
// a number in the question's unit (or not an option's number).
AnswerVerdict check_answer(const Question& question, const Answer& answer, std::string_view typed);
// What a skipped question shows: "skipped: the engine's answer is 7.5 m/s".
std::string skipped_text(const Answer& answer);

// The vocabulary name of a question's value at a place of `stage`: "impulse" for "impulse[0]",
// "velocity_update" for "updates[0].after[0]" in a velocity iteration. Empty when the path names none.
std::string question_quantity(const Question& question, model::Stage stage);

}  // namespace impulse::course
