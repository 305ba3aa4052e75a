// A lesson in a terminal, driven through a pseudo-terminal as a student would take it: the answer hidden
// until given, a wrong answer told how far off, a retry, a skip, quitting midway and coming back; progress
// saved as the window saves it. Without a terminal the lesson is printed with its answers and never waits.

#include "course/lesson.hpp"
#include "course/progress.hpp"
#include "explain/text_table.hpp"
#include "support/program.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"
#include "support/terminal.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace impulse::test {

namespace {

using impulse::test::program;

// Three steps over the ball meeting the ground (2 kg at 5 m/s, c = 0.5): a step without a question, then
// the desired Δv (1.5 × 5 = 7.5 m/s) and the impulse (g = Δv / d = 7.5 / 0.5 = 15 N·s).
std::string three_steps() {
    return "```json\n{\n  \"title\": \"A ball\",\n  \"scene\": \"" IMPULSE_SOURCE_DIR
           "/scenes/cases/sphere_ground.json\",\n  \"steps\": ["
           R"({"id": "closing", "at": "phase=preparation,contact=0,step=contact_velocity"},
              {"id": "desired", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
               "question": {"kind": "predict", "prompt": "What desired change?", "value": "desired_delta_velocity",
                            "tolerance": {"relative": 0.02}}},
              {"id": "impulse", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
               "question": {"kind": "predict", "prompt": "What impulse?", "value": "impulse[0]",
                            "tolerance": {"relative": 0.02}}}])"
           "\n}\n```\n\nIntro.\n\n## closing\nThe `contact_velocity`.\n\n## desired\nThe "
           "`desired_delta_velocity`.\n\n## impulse\nThe `impulse` next.\n";
}

struct Course {
    TempDir dir;
    std::filesystem::path lessons = dir.file("course");
    std::filesystem::path config = dir.file("cfg");
    Course() {
        std::filesystem::create_directories(lessons);
        dir.write("course/01-ball.md", three_steps());
    }
    std::map<std::string, std::optional<std::string>> env() const {
        return {{"XDG_CONFIG_HOME", config.string()}, {"DISPLAY", std::nullopt}, {"WAYLAND_DISPLAY", std::nullopt}};
    }
    course::LessonProgress progress() const {
        return course::load_progress(config / "impulse-lab" / "progress.json").progress.lessons.at("01-ball");
    }
};

}  // namespace

TEST_CASE("a lesson in a terminal hides the answer, says how far off a wrong one is, and takes a retry and a skip") {
    Course course;
    Terminal t({program, "lesson", "1", "--text", "--lessons", course.lessons.string()}, course.env());
    t.expect("Step 1 of 3");
    t.expect("Enter: next step");
    t.send("");
    // The desired Δv's own row is hidden, and so is the impulse it gives in one division.
    const std::string step2 = t.expect("Your answer in m/s");
    CHECK(step2.find("? (hidden until you answer this step's question)") != std::string::npos);
    CHECK(step2.find("7.5") == std::string::npos);
    t.send("5");
    t.expect("not quite: 33.3 % too low; try again, or skip to see the engine's value");
    t.send("seven");
    t.expect("type a number");
    t.send("-7,5 m/s");
    t.expect("not quite: the opposite sign");
    t.send("7,5 m/s");
    const std::string seen = t.expect("right: the engine has 7.5 m/s\r\n");
    // Answered: the table again, with the value shown.
    const std::string shown = t.expect("Enter: next step");
    CHECK(shown.find("7.5 m/s") != std::string::npos);
    t.send("");
    t.expect("Your answer in N·s");
    t.send("s");
    t.expect("skipped: the engine's answer is 15 N·s");
    t.expect("That was the last step");
    t.send("");
    t.expect("The end of lesson 1");
    t.expect("Score: 2 questions: 1 right after retries, 1 skipped.");
    t.send("q");
    t.expect("Lesson 1: 1 right after retries, 1 skipped.");
    CHECK(t.wait() == 0);

    const course::LessonProgress p = course.progress();
    CHECK(p.answers.at("desired").correct);
    CHECK(p.answers.at("desired").tries == 3);  // "seven" was not an answer
    CHECK(p.answers.at("impulse").skipped);
    CHECK_FALSE(p.answers.at("impulse").correct);
    const course::Tally tally = course::tally(p);
    CHECK(tally.first_try == 0);
    CHECK(tally.after_retries == 1);
    CHECK(tally.skipped == 1);
}

TEST_CASE("a student who quits a lesson in a terminal midway comes back to the same step") {
    Course course;
    {
        Terminal t({program, "lesson", "1", "--text", "--lessons", course.lessons.string()}, course.env());
        t.expect("Enter: next step");
        t.send("");
        t.expect("Your answer in m/s");
        t.send("7.5");
        t.expect("right: the engine has 7.5 m/s");
        t.send("");
        t.expect("Your answer in N·s");
        t.send("q");
        CHECK(t.wait() == 0);
    }
    CHECK(course.progress().last_step == 2);
    Terminal t({program, "lesson", "1", "--text", "--lessons", course.lessons.string()}, course.env());
    t.expect("Back at step 3, where you left off.");
    t.expect("Your answer in N·s");
    t.send("15.1");
    t.expect("right: the engine has 15 N·s (you were 0.667 % off)");
    t.expect("That was the last step");
    t.send("");
    t.expect("Score: 2 questions: 2 right at the first try.");
    t.send("");
    t.expect("Lesson 1: 2 right at the first try.");
    CHECK(t.wait() == 0);
    CHECK(course::tally(course.progress()).first_try == 2);
}

TEST_CASE("a terminal lesson shows the bodies, the contacts and the phase's order on a key, through the mask") {
    Course course;
    Terminal t({program, "lesson", "1", "--text", "--lessons", course.lessons.string()}, course.env());
    t.expect("Enter: next step");
    t.send("");
    t.expect("Your answer in m/s");
    // At the desired Δv's step, the ball after the impulse would give the answer away: hidden, with the step.
    t.send("o");
    const std::string bodies = t.expect("Your answer in m/s");
    CHECK(bodies.find("Bodies before → after this item") != std::string::npos);
    CHECK(bodies.find("ball") != std::string::npos);
    CHECK(bodies.find("? (hidden until you answer step 2)") != std::string::npos);
    t.send("c");
    const std::string contacts = t.expect("Your answer in m/s");
    CHECK(contacts.find("▶ 0  ball / world") != std::string::npos);
    CHECK(contacts.find("7.5") == std::string::npos);
    t.send("i");
    const std::string order = t.expect("Your answer in m/s");
    CHECK(order.find("▶ iteration 0 → contact 0") != std::string::npos);
    CHECK(order.find("7.5") == std::string::npos);
    t.send("7.5");
    t.expect("right: ");
    t.expect("Enter: next step");
    t.send("");
    t.send("s");  // the impulse: with it settled, the ball's velocity after it is shown
    t.expect("skipped: ");
    t.expect("That was the last step");
    t.send("o");
    const std::string after = t.expect("ω rad/s");
    CHECK(after.find("(0, -5, 0) → (0, 2.5, 0)") != std::string::npos);
    t.send("q");
    CHECK(t.wait() == 0);
}

TEST_CASE("a terminal lesson asks before leaving an open question, and its end lists it and offers the next lesson") {
    Course course;
    course.dir.write("course/02-again.md", three_steps());
    Terminal t({program, "lesson", "1", "--text", "--lessons", course.lessons.string()}, course.env());
    t.expect("Enter: next step");
    t.send("");
    t.expect("Your answer in m/s");
    t.send("");
    t.expect("This question is still open: type your answer, s to skip it");
    t.send("");  // again: on, the question left open
    t.expect("Step 3 of 3");
    t.send("set restitution_cutoff 0");  // the Settings tab, typed: the scene runs again
    t.expect("re-ran with restitution_cutoff=0");
    t.send("s");
    t.expect("skipped: the engine's answer is 15 N·s");
    t.send("");
    t.expect("Score: 2 questions: 1 skipped, 1 still open.");
    t.expect("step 2 · desired: What desired change?");
    t.expect("Type a step's number to go back to it, n for lesson 2 · A ball, q to quit.");
    t.send("2");
    t.expect("Step 2 of 3");
    t.send("7.5");
    t.expect("right: ");
    t.send("g 3");
    t.expect("Step 3 of 3");
    t.send("");
    t.expect("Score: 2 questions: 1 right at the first try, 1 skipped.");
    t.send("n");
    t.expect("Lesson 2 · A ball");
    t.send("q");
    CHECK(t.wait() == 0);
}

// Every shipped lesson taken to its end in an 80-column terminal, each question answered from the keyboard with
// the engine's value as a student types it (a decimal comma, a unit after it): before the answer is given the
// terminal never shows it (a predict answer's text, "0.132 N·s"), no line is wider than the terminal, and at the
// end every question counts as right at the first try. The lessons whose runs are long (the brick wall) take a
// few seconds; the whole course well under a minute.
TEST_CASE("every shipped lesson can be taken to its end in an 80-column terminal without seeing an answer first") {
    const std::filesystem::path course = IMPULSE_SOURCE_DIR "/lessons";
    const std::vector<std::filesystem::path> files = course::lesson_files(course);
    REQUIRE(files.size() == 14);
    for (const std::filesystem::path& file : files) {
        INFO(file.filename().string());
        const course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(file));
        const std::vector<course::Step>& steps = prepared.lesson.steps;
        TempDir config;
        Terminal t({program, "lesson", std::to_string(prepared.lesson.number), "--text", "--lessons", course.string()},
                   {{"XDG_CONFIG_HOME", config.file("cfg").string()},
                    {"DISPLAY", std::nullopt},
                    {"WAYLAND_DISPLAY", std::nullopt}},
                   80);
        for (std::size_t k = 0; k < steps.size(); ++k) {
            t.expect("Step " + std::to_string(k + 1) + " of " + std::to_string(steps.size()));
            if (const auto& q = steps[k].question) {
                const course::Answer& answer = *prepared.answers[k];
                const std::string shown = t.expect("Your answer");
                std::string typed;
                if (q->kind == course::Question::Kind::predict) {
                    const double value = answer.value.get<double>();
                    const double allowed = std::max(q->tolerance.relative.value_or(0) * std::abs(value),
                                                    q->tolerance.absolute.value_or(0));
                    // A 0 is everywhere; any other answer's text is the giveaway.
                    if (std::abs(value) > allowed)
                        CHECK_MESSAGE(
                            shown.find(answer.shown) == std::string::npos,
                            "step " << k + 1 << " shows its answer " << answer.shown << " before it is given");
                    // As a student types it: every other answer with a decimal comma and its unit.
                    char text[32];
                    std::snprintf(text, sizeof text, "%.17g", value);
                    typed = text;
                    if (k % 2 == 1) {
                        std::replace(typed.begin(), typed.end(), '.', ',');
                        if (!answer.unit.empty()) typed += " " + answer.unit;
                    }
                } else {
                    typed = std::to_string(answer.correct_option + 1);
                }
                t.send(typed);
                t.expect("right: ");
            }
            // The views too fit the terminal.
            if (k == 0)
                for (const char* view : {"o", "c", "i"}) {
                    t.expect(steps.size() == 1 ? "That was the last step" : "Enter: next step");
                    t.send(view);
                }
            t.expect(k + 1 == steps.size() ? "That was the last step" : "Enter: next step");
            t.send("");
        }
        const int questions = course::question_count(prepared.lesson);
        t.expect("Score: " + std::to_string(questions) + (questions == 1 ? " question: " : " questions: ") +
                 std::to_string(questions) + " right at the first try.");
        t.send("q");
        t.expect("Lesson " + std::to_string(prepared.lesson.number) + ": " + std::to_string(questions) +
                 " right at the first try.");
        CHECK(t.wait() == 0);
        // Fitted to the terminal: tables wrapped at words, text at spaces.
        std::size_t start = 0;
        const std::string& all = t.all();
        while (start < all.size()) {
            const std::size_t end = std::min(all.find('\n', start), all.size());
            std::string line = all.substr(start, end - start);
            std::erase(line, '\r');
            CHECK_MESSAGE(explain::display_width(line) <= 80, "a line wider than 80 columns: " << line);
            start = end + 1;
        }
    }
}

TEST_CASE("without a display, a lesson in a terminal asks its questions there and says why") {
    Course course;
    Terminal t({program, "lesson", "1"}, course.env());
    t.expect("note: no display (DISPLAY is not set): the lesson runs in this terminal");
    t.expect("Lesson 1 · An impulse is an instant change of velocity");
    t.expect("Step 1 of 9");
    t.expect("Enter: next step");
    t.send("");
    t.expect("Your answer in m/s per N·s");
    t.send("q");
    CHECK(t.wait() == 0);
}

TEST_CASE("without a terminal to read from, lesson --text prints the lesson with its answers and never waits") {
    const CliResult r = run_cli({"lesson", "1", "--text"});
    CHECK(r.code == 0);
    CHECK(r.out.starts_with("Lesson 1 · An impulse is an instant change of velocity"));
    CHECK(r.out.find("Answer (the engine's): 7.5 m/s") != std::string::npos);
    const CliResult bad = run_cli({"lesson", "1", "--text", "--headless"});
    CHECK(bad.code == 2);
    CHECK(bad.err ==
          "impulse-lab: --text: takes the lesson in the terminal; --headless is for the window and its "
          "pictures\n");
}

}  // namespace impulse::test
