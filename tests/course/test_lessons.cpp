// Lessons: the shipped course loads, every place and question works with the engine's run, every step's
// text names what it shows; malformed lesson files are rejected with one line naming the place; progress
// survives a corrupt file.

#include "formats/input_files.hpp"
#include "formats/input_error.hpp"
#include "course/lesson.hpp"
#include "course/lesson_run.hpp"
#include "course/progress.hpp"
#include "support/run_cli.hpp"
#include "support/shipped.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>

namespace impulse::test {

namespace {

using impulse::test::shipped_lessons;
const std::string sphere_ground = IMPULSE_SOURCE_DIR "/scenes/cases/sphere_ground.json";

// A small lesson over the sphere meeting the ground; `steps` and `sections` replace its parts.
std::string lesson_text(const std::string& steps, const std::string& sections) {
    return "```json\n{\n  \"title\": \"A test\",\n  \"scene\": \"" + sphere_ground + "\",\n  \"steps\": [" + steps +
           "]\n}\n```\n\nIntro.\n\n" + sections;
}

const std::string good_steps =
    R"({"id": "closing", "at": "phase=preparation,contact=0,step=contact_velocity"},
       {"id": "desired", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
        "question": {"kind": "predict", "prompt": "How much?", "value": "desired_delta_velocity",
                     "tolerance": {"relative": 0.02}}})";
const std::string good_sections = "## closing\nThe `contact_velocity`.\n\n## desired\nThe `desired_delta_velocity`.\n";

// The problem reading (or, if reading passes, preparing) a lesson, as "where: problem".
std::string lesson_error(const std::string& text, const std::string& name = "01-test.md") {
    TempDir dir;
    const auto file = dir.write(name, text);
    try {
        course::prepare_lesson(course::read_lesson(file));
    } catch (const formats::FileError& e) {
        return e.where + ": " + e.problem;
    }
    return "no error";
}

// Every vocabulary word a step's text may name for its place: the step's table and its quantities.
bool mentions(const std::string& text, const std::string& word) {
    return text.find("`" + word) != std::string::npos;
}

}  // namespace

// One test for the whole course, so each lesson's scene runs once (the brick wall's is not small).
TEST_CASE(
    "the course has fourteen lessons that run with the engine, name what each step shows, and take the engine's "
    "answers") {
    const std::vector<std::filesystem::path> files = course::lesson_files(shipped_lessons);
    REQUIRE(files.size() == 14);
    for (std::size_t n = 0; n < files.size(); ++n) {
        const std::string name = files[n].filename().string();
        INFO(name);
        const course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(files[n]));
        CHECK(prepared.lesson.number == static_cast<int>(n) + 1);
        CHECK(prepared.places.size() == prepared.lesson.steps.size());
        CHECK(prepared.lesson.steps.size() >= 3);
        int questions = 0;
        for (std::size_t i = 0; i < prepared.places.size(); ++i) {
            const course::Step& step = prepared.lesson.steps[i];
            INFO("step " << step.id);

            // Its text names, in backticks, the step or a quantity its place shows.
            const model::Cursor& place = prepared.places[i];
            const explain::StepTable table =
                model::step_tables(prepared.session.trace(), place)[static_cast<std::size_t>(place.step)];
            bool named = mentions(step.text, table.step);
            for (const explain::Row& r : table.rows)
                named = named || mentions(step.text, r.quantity.substr(0, r.quantity.find('[')));
            if (step.question)
                named = named || mentions(step.text, course::question_quantity(*step.question, place.stage));
            CHECK(named);

            // Its question is right at the engine's value and wrong well away from it.
            if (!step.question) continue;
            ++questions;
            const course::Question& q = *step.question;
            const course::Answer& a = *prepared.answers[i];
            if (q.kind == course::Question::Kind::predict) {
                const double value = a.value.get<double>();
                char exact[64];
                std::snprintf(exact, sizeof exact, "%.17g", value);
                CHECK(course::check_answer(q, a, exact).correct);
                // Off by ten tolerances (or by 1 when the value is 0 and only a relative tolerance is given).
                const double allowed =
                    std::max(q.tolerance.relative.value_or(0) * std::abs(value), q.tolerance.absolute.value_or(0));
                char wrong[64];
                std::snprintf(wrong, sizeof wrong, "%.17g", value + (allowed > 0 ? 10 * allowed : 1.0));
                CHECK_FALSE(course::check_answer(q, a, wrong).correct);
            } else {
                for (std::size_t o = 0; o < q.options.size(); ++o)
                    CHECK(course::check_answer(q, a, std::to_string(o + 1)).correct ==
                          (static_cast<int>(o) == a.correct_option));
            }
        }
        CHECK(questions >= 1);
    }
}

TEST_CASE("a lesson written with a step's name from before trace format 2 opens at the renamed step, with a note") {
    // velocity_per_unit_impulse was the step that computes d; it is delta_velocity_per_unit_impulse now.
    TempDir dir;
    const std::string steps =
        R"({"id": "closing", "at": "phase=preparation,contact=0,step=velocity_per_unit_impulse"},
           {"id": "desired", "at": "phase=velocity,iteration=0,step=desired_delta_velocity"})";
    const auto file = dir.write("01-test.md", lesson_text(steps,
                                                          "## closing\nThe `delta_velocity_per_unit_impulse`.\n\n"
                                                          "## desired\nThe `desired_delta_velocity`.\n"));
    const course::PreparedLesson p = course::prepare_lesson(course::read_lesson(file));
    CHECK(p.lesson.steps[0].at == "phase=preparation,contact=0,step=delta_velocity_per_unit_impulse");
    REQUIRE(p.lesson.notes.size() == 1);
    CHECK(p.lesson.notes[0] ==
          "steps[0].at: step \"velocity_per_unit_impulse\" is now \"delta_velocity_per_unit_impulse\"");
}

TEST_CASE("a predict answer is right within its tolerance and says how far off it was") {
    TempDir dir;
    const auto file = dir.write("01-test.md", lesson_text(good_steps, good_sections));
    const course::PreparedLesson p = course::prepare_lesson(course::read_lesson(file));
    // The ball falls at 5 m/s with c = 0.5: Δv = (1 + 0.5) 5 = 7.5 m/s.
    REQUIRE(p.answers[1]->value.get<double>() == doctest::Approx(7.5));
    CHECK(p.answers[1]->shown == "7.5 m/s");
    const course::Question& q = *p.lesson.steps[1].question;
    CHECK(course::check_answer(q, *p.answers[1], "7.6").correct);  // 1.3 % off, 2 % allowed
    const course::AnswerVerdict wrong = course::check_answer(q, *p.answers[1], "5");
    CHECK_FALSE(wrong.correct);
    CHECK(wrong.feedback == "not quite: 33.3 % too low; try again, or skip to see the engine's value");
    CHECK(course::check_answer(q, *p.answers[1], "7.6").feedback ==
          "right: the engine has 7.5 m/s (you were 1.33 % off)");
    CHECK_THROWS_AS(course::check_answer(q, *p.answers[1], "seven"), formats::InputError);
}

TEST_CASE("malformed lessons are rejected with the place of the problem") {
    const std::string no_tolerance =
        R"({"id": "a", "at": "phase=velocity", "question": {"kind": "predict", "prompt": "?", "value": "contact"}})";
    const std::string no_match =
        R"({"id": "a", "at": "phase=velocity,step=impulse", "question": {"kind": "choose", "prompt": "?",
           "value": "impulse_model", "options": [{"label": "x", "value": "sliding"}, {"label": "y", "value": "static_friction"}]}})";
    std::string with_unknown_key = lesson_text(good_steps, good_sections);
    with_unknown_key.replace(with_unknown_key.find("{\n") + 2, 0, "  \"titel\": \"x\",\n");
    struct Case {
        std::string text;
        std::string error;
    };
    const Case cases[] = {
        {"# no header\n", "line 1: a lesson starts with its header in a ```json block"},
        {"```json\n{\"title\": \"x\"}\n", "line 1: the ```json header block is not closed by ```"},
        {"```json\n{\"title\": \n```\n", "header: "},
        {with_unknown_key, "titel: "},
        {lesson_text(good_steps, good_sections + "## extra\nText.\n"), "line 19: section \"extra\" has no step"},
        {lesson_text(good_steps, "## closing\nText `contact_velocity`.\n"), "steps[1].id: no \"## desired\" section"},
        {lesson_text(R"({"id": "a", "at": "phase=velocity"}, {"id": "a", "at": "phase=velocity"})", "## a\nx\n"),
         "steps[1].id: \"a\" is used twice"},
        {lesson_text(no_tolerance, "## a\nx\n"), "steps[0].question.tolerance: a predict question needs a tolerance"},
        {lesson_text(R"({"id": "a", "at": "phase=position"})", "## a\nx\n"),
         "steps[0].at: frame 0 has no position iterations"},
        {lesson_text(R"({"id": "a", "at": "phase=sideways"})", "## a\nx\n"), "steps[0].at: phase must be"},
        {lesson_text(R"({"id": "a", "at": "phase=velocity", "question": {"kind": "predict", "prompt": "?",
                       "value": "impulse_wrld", "tolerance": {"relative": 0.1}}})",
                     "## a\nx\n"),
         "steps[0].question.value: no \"impulse_wrld\" here"},
        {lesson_text(no_match, "## a\nx\n"),
         "steps[0].question.options: no option equals the engine's value frictionless"},
        {lesson_text(R"({"id": "a", "at": "phase=velocity", "question": {"kind": "predict", "prompt": "?",
                       "value": "desired_delta_velocity", "tolerance": {"relative": 0.1},
                       "reveals": ["impulse", "angular_componet"]}})",
                     "## a\nx\n"),
         "steps[0].question.reveals[1]: \"angular_componet\" is not a quantity of the vocabulary "
         "(docs/trace-format.md); did you mean \"angular_component\"?"},
        {lesson_text(R"({"id": "a", "at": "phase=preparation", "question": {"kind": "predict", "prompt": "?",
                       "value": "origin.features[0].index", "tolerance": {"relative": 0.1}}})",
                     "## a\nx\n"),
         "steps[0].question.value: \"origin.features[0].index\" names no quantity of the vocabulary"},
    };
    for (const Case& c : cases) {
        const std::string error = lesson_error(c.text);
        INFO(error);
        CHECK(error.starts_with(c.error));
        CHECK(error.find('\n') == std::string::npos);
    }
    CHECK(lesson_error(lesson_text(good_steps, good_sections), "test.md").starts_with(": a lesson file is named NN-"));
}

TEST_CASE("progress survives a round trip and a corrupt file is kept aside and reported") {
    TempDir dir;
    const auto file = dir.file("cfg/impulse-lab/progress.json");
    CHECK(course::load_progress(file).progress.lessons.empty());  // none yet

    course::Progress progress;
    progress.lessons["01-test"].last_step = 2;
    progress.lessons["01-test"].answers["desired"] = {"7.6", true, 2};
    course::save_progress(file, progress);
    const course::LoadedProgress back = course::load_progress(file);
    CHECK(back.note.empty());
    CHECK(back.progress.lessons.at("01-test").last_step == 2);
    CHECK(back.progress.lessons.at("01-test").answers.at("desired").answer == "7.6");
    CHECK(back.progress.lessons.at("01-test").answers.at("desired").tries == 2);

    dir.write("cfg/impulse-lab/progress.json",
              "{\"format\": \"impulse-lab-progress\", \"version\": 1, \"lessons\": {\"x\": 3}");
    const course::LoadedProgress corrupt = course::load_progress(file);
    CHECK(corrupt.progress.lessons.empty());
    CHECK(corrupt.note.find("is unreadable") != std::string::npos);
    CHECK(corrupt.note.find("kept as progress.json.corrupt-") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(file));
    std::size_t kept = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.file("cfg/impulse-lab")))
        kept += entry.path().filename().string().starts_with("progress.json.corrupt-") ? 1 : 0;
    CHECK(kept == 1);
}

TEST_CASE(
    "a progress file written before skipping existed still loads, and progress counts right, retried and skipped") {
    TempDir dir;
    // As the previous version wrote it: no "skipped".
    const auto file = dir.write("progress.json", R"({"format": "impulse-lab-progress", "version": 1, "lessons": {
        "01-test": {"last_step": 1, "answers": {"desired": {"answer": "7.5", "correct": true, "tries": 1}}}}})");
    const course::LoadedProgress old = course::load_progress(file);
    REQUIRE(old.note.empty());
    const course::AnswerRecord& desired = old.progress.lessons.at("01-test").answers.at("desired");
    CHECK(desired.correct);
    CHECK_FALSE(desired.skipped);

    course::Progress progress = old.progress;
    course::LessonProgress& p = progress.lessons.at("01-test");
    p.answers["retried"] = {"3", true, 3, false};
    p.answers["given-up"] = {"", false, 2, true};
    p.answers["still-open"] = {"9", false, 1, false};
    course::save_progress(file, progress);
    const course::Progress back = course::load_progress(file).progress;
    CHECK(back.lessons.at("01-test").answers.at("given-up").skipped);
    const course::Tally t = course::tally(back.lessons.at("01-test"));
    CHECK(t.first_try == 1);
    CHECK(t.after_retries == 1);
    CHECK(t.skipped == 1);
    CHECK(t.open == 1);
    CHECK(course::tally_text(t) ==
          "1 right at the first try, 1 right after retries, 1 skipped, 1 tried, not yet right");
    // A "skipped" that is not true or false is an error naming it.
    dir.write("bad.json", R"({"format": "impulse-lab-progress", "version": 1, "lessons": {"x": {"last_step": 0,
        "answers": {"a": {"answer": "", "correct": false, "tries": 0, "skipped": "yes"}}}}})");
    CHECK_THROWS_WITH_AS(course::read_progress_text(formats::read_input_file(dir.file("bad.json").string())),
                         doctest::Contains("skipped"), formats::InputError);
}

TEST_CASE("a lesson run resumes each question as it stood, and a skip is saved as skipped") {
    TempDir dir;
    const auto file = dir.write("01-test.md", lesson_text(good_steps, good_sections));
    const course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(file));
    const auto saved = dir.file("cfg/progress.json");
    course::Progress progress;
    {
        course::LessonRun run(prepared, &progress, saved);
        run.go_to(1);
        CHECK(run.waiting());
        CHECK_FALSE(run.answer("6").correct);
        run.skip();
        CHECK(run.state(1) == course::QuestionState::skipped);
        CHECK(run.feedback(1) == "skipped: the engine's answer is 7.5 m/s");
    }
    course::Progress reloaded = course::load_progress(saved).progress;
    course::LessonRun again(prepared, &reloaded, saved);
    CHECK(again.step() == 1);
    CHECK(again.state(1) == course::QuestionState::skipped);
    CHECK(again.open() == std::vector<bool>{false, false});
    const course::AnswerRecord& r = reloaded.lessons.at("01-test").answers.at("desired");
    CHECK(r.skipped);
    CHECK(r.tries == 1);
}

TEST_CASE("a progress file larger than any we write is kept aside unread, and progress starts afresh") {
    TempDir dir;
    const auto file = dir.write("progress.json", std::string((4u << 20) + 1, ' '));
    const course::LoadedProgress loaded = course::load_progress(file);
    CHECK(loaded.progress.lessons.empty());
    CHECK(loaded.note.find("is unreadable (is 4194305 bytes, over the limit of 4 MiB") != std::string::npos);
    CHECK(loaded.note.find("kept as progress.json.corrupt-") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(file));
}

TEST_CASE("impulse-lab lesson lists the lessons with the progress kept in the config folder") {
    TempDir dir;
    const auto lessons_dir = dir.file("course");
    std::filesystem::create_directories(lessons_dir);
    std::ofstream(lessons_dir / "01-test.md") << lesson_text(good_steps, good_sections);
    ::setenv("XDG_CONFIG_HOME", dir.file("cfg").c_str(), 1);
    course::Progress progress;
    progress.lessons["01-test"].answers["desired"] = {"7.6", true, 1};
    course::save_progress(*course::progress_file(), progress);

    const CliResult r = run_cli({"lesson", "--lessons", lessons_dir.string()});
    CHECK(r.code == 0);
    CHECK(r.out.find(" 1  A test ") != std::string::npos);
    CHECK(r.out.find("2 steps, 1 questions   1 right at the first try") != std::string::npos);

    const CliResult missing = run_cli({"lesson", "7", "--lessons", lessons_dir.string()});
    CHECK(missing.code == 2);
    CHECK(missing.err.starts_with("impulse-lab: lesson: there is no lesson 7 in "));
    ::unsetenv("XDG_CONFIG_HOME");
}

TEST_CASE("validate checks a lesson file with its run") {
    TempDir dir;
    const auto good = dir.write("01-good.md", lesson_text(good_steps, good_sections));
    const CliResult ok = run_cli({"validate", good.string()});
    CHECK(ok.code == 0);
    CHECK(ok.out == good.string() + ": valid lesson 1 (2 steps, 1 question)\n");
    const auto bad = dir.write("02-bad.md", lesson_text(R"({"id": "a", "at": "phase=position"})", "## a\nx\n"));
    const CliResult r = run_cli({"validate", bad.string()});
    CHECK(r.code == 1);  // the verdict asked for: invalid
    CHECK(r.err == "impulse-lab: " + bad.string() + ": steps[0].at: frame 0 has no position iterations\n");
}

}  // namespace impulse::test

#include "course/mask.hpp"

namespace impulse::test {

TEST_CASE("an open question hides its quantity until the student answers it") {
    TempDir dir;
    const auto file = dir.write("01-test.md", lesson_text(good_steps, good_sections));
    const course::PreparedLesson prepared = course::prepare_lesson(course::read_lesson(file));
    const Trace& trace = prepared.session.trace();
    const auto reaches = course::question_reaches(prepared, trace);
    course::LessonRun run(prepared, nullptr, std::nullopt);
    // The desired Δv row of the velocity iteration (step 1's place), and of the contact as prepared.
    explain::Row desired;
    desired.key = "desired_delta_velocity";
    const model::Cursor iteration = prepared.places[1], preparation{0, model::Stage::preparation, 0, 4};
    const course::Mask open(reaches, run.open(), trace);
    CHECK(open.hides_row(iteration, desired));
    CHECK(open.hides_row(preparation, desired));
    CHECK(open.hides_value(preparation, 0, "desired_delta_velocity", 7.5));
    run.go_to(1);
    CHECK_FALSE(run.answer("5").correct);  // a wrong answer leaves it hidden
    CHECK(course::Mask(reaches, run.open(), trace).hides_row(iteration, desired));
    CHECK(run.answer("7.5").correct);
    CHECK_FALSE(course::Mask(reaches, run.open(), trace).hides_row(iteration, desired));
}

}  // namespace impulse::test

namespace impulse::test {

TEST_CASE("a lesson's worksheet holds the cells of the lesson's steps that compute something") {
    TempDir dir;
    const auto file = dir.write("01-test.md", lesson_text(good_steps, good_sections));
    const auto sheet = dir.file("sheet.json");
    const CliResult r = run_cli({"worksheet", file.string(), "--out", sheet.string()});
    INFO(r.err);
    REQUIRE(r.code == 0);
    // Both steps compute something: contact_velocity in the preparation, desired_delta_velocity in iteration 0.
    CHECK(r.out.starts_with("worksheet written to " + sheet.string() + ": 2 steps, "));
    const CliResult flags = run_cli({"worksheet", file.string(), "--set", "preset=chapter", "--out", sheet.string()});
    CHECK(flags.code == 2);
    CHECK(flags.err.starts_with("impulse-lab: worksheet: a lesson runs with its own settings"));
}

}  // namespace impulse::test

#include "course/item_labels.hpp"

namespace impulse::test {

TEST_CASE("lesson 14's velocity phase reads as sweeps over the bodies, each followed by the contacts' dual updates") {
    const course::PreparedLesson lesson =
        course::prepare_lesson(course::read_lesson(shipped_lessons / "14-avbd-beside-the-book.md"));
    const Trace& trace = lesson.session.trace();
    const course::Mask none;
    // Frame 1 (the trace's first): body 0 gathers 8 contacts, body 1 (the heavy box) 4; then contacts 0..7.
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, 0) == "solve sweep 0 → body 0 (8 contacts)");
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, 1) == "solve sweep 0 → body 1 (4 contacts)");
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, 2) == "dual sweep 0 → contact 0");
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, 9) == "dual sweep 0 → contact 7");
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, 10) == "solve sweep 1 → body 0 (8 contacts)");
    // After the tenth dual sweep, the post-stabilisation sweep over the bodies ends the phase.
    const int last = model::item_count(trace.frames[0], model::Stage::velocity) - 1;
    CHECK(course::item_label(trace, none, 0, model::Stage::velocity, last) ==
          "stabilize sweep 10 → body 1 (4 contacts)");
    // 2 bodies x 11 sweeps + 8 contacts x 10 dual sweeps; the limit leaves room for a bounce per contact (none here).
    CHECK(course::stage_label(trace.frames[0], model::Stage::velocity) == "Velocity phase: 102 of 110 iterations");
}

}  // namespace impulse::test
