// Every lesson taken to its end in the window, with the keys alone, at 1024x768, 1280x800 and 1920x1080 (a test
// each): the
// window runs offscreen (the app itself, `lesson N --headless --script`), and the script's `key` and `type` lines
// go through SDL's own event queue as a keyboard's would. Each question is answered as a student types it — the
// engine's value as the tables print it, every other one with a decimal comma and its unit, an option by its
// number — with Enter; → goes on; → on the last step opens the end of the lesson; Esc closes. The progress file
// must then say every question was right at the first try and the lesson was left at its last step.

#include "course/lesson.hpp"
#include "course/progress.hpp"
#include "explain/format.hpp"
#include "support/png_image.hpp"
#include "support/run_cli.hpp"
#include "support/temp_dir.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>

namespace impulse::test {

namespace {

// The keys a student presses to take `lesson` from its first step to its end.
std::string keys_for(const course::PreparedLesson& lesson) {
    std::string script;
    for (std::size_t k = 0; k < lesson.lesson.steps.size(); ++k) {
        if (const auto& q = lesson.lesson.steps[k].question) {
            const course::Answer& a = *lesson.answers[k];
            std::string typed;
            if (q->kind == course::Question::Kind::predict) {
                typed = explain::number(a.value.get<double>());
                if (k % 2 == 1) {
                    std::replace(typed.begin(), typed.end(), '.', ',');
                    if (!a.unit.empty()) typed += " " + a.unit;
                }
            } else {
                typed = std::to_string(a.correct_option + 1);
            }
            script += "type " + typed + "\nkey Return\n";
        }
        script += "key Right\n";
    }
    return script;
}

// Each size its own test, so they can run side by side.
void take_every_lesson(const char* size) {
    const std::vector<std::filesystem::path> files = course::lesson_files(IMPULSE_SOURCE_DIR "/lessons");
    REQUIRE(files.size() == 14);
    for (const std::filesystem::path& file : files) {
        const course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        const int questions = course::question_count(lesson.lesson);
        INFO(file.filename().string() << " at " << size);
        TempDir dir;
        ::setenv("XDG_CONFIG_HOME", dir.file("config").string().c_str(), 1);
        const std::filesystem::path script =
            dir.write("keys.txt", keys_for(lesson) + "screenshot " + dir.file("end.png").string() + "\nkey Escape\n");
        const CliResult r = run_cli({"lesson", std::to_string(lesson.lesson.number), "--headless", "--size", size,
                                     "--script", script.string()});
        ::unsetenv("XDG_CONFIG_HOME");
        CHECK(r.code == 0);
        CHECK(r.err == "");
        const course::LessonProgress p =
            course::load_progress(dir.file("config/impulse-lab/progress.json")).progress.lessons[lesson.lesson.name];
        CHECK(p.last_step == static_cast<int>(lesson.lesson.steps.size()) - 1);
        CHECK(course::tally(p).first_try == questions);
        // The end of the lesson is on the screen: not blank.
        CHECK(distinct_colours(load_png(dir.file("end.png"))) > 100);
    }
}

}  // namespace

TEST_CASE("every lesson is taken to its end in a 1024x768 window with the keys alone") {
    take_every_lesson("1024x768");
}

TEST_CASE("every lesson is taken to its end in a 1280x800 window with the keys alone") {
    take_every_lesson("1280x800");
}

TEST_CASE("every lesson is taken to its end in a 1920x1080 window with the keys alone") {
    take_every_lesson("1920x1080");
}

}  // namespace impulse::test

namespace impulse::test {

TEST_CASE("in the window, → on an open question asks first, Ctrl+S skips, the end lists what is open, Esc closes") {
    // The ball meeting the ground: a step without a question, the desired Δv (7.5 m/s), the impulse (15 N·s).
    TempDir dir;
    std::filesystem::create_directories(dir.file("course"));
    dir.write("course/01-ball.md",
              "```json\n{\"title\": \"A ball\", \"scene\": \"" IMPULSE_SOURCE_DIR
              "/scenes/cases/sphere_ground.json\",\n"
              R"("steps": [{"id": "closing", "at": "phase=preparation,contact=0,step=contact_velocity"},
                {"id": "desired", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
                 "question": {"kind": "predict", "prompt": "What desired change?", "value": "desired_delta_velocity",
                              "tolerance": {"relative": 0.02}}},
                {"id": "impulse", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
                 "question": {"kind": "predict", "prompt": "What impulse?", "value": "impulse[0]",
                              "tolerance": {"relative": 0.02}}}]})"
              "\n```\n\n## closing\nThe `contact_velocity`.\n\n## desired\nThe `desired_delta_velocity`.\n\n"
              "## impulse\nThe `impulse` next.\n");
    const std::filesystem::path script = dir.write("keys.txt",
                                                   "key Return\n"     // step 2
                                                   "key Return\n"     // Enter on the empty field: said beside it
                                                   "key Right\n"      // asked: skip this question?
                                                   "key Right\n"      // again: on, the question left open
                                                   "key ctrl+s\n"     // step 3 skipped
                                                   "key Right\n"      // the end of the lesson
                                                   "type 1\n"         // its first open question: step 2
                                                   "type 15,0 m/s\n"  // the impulse's number: wrong, a retry
                                                   "key Return\n"
                                                   "key ctrl+a\n"
                                                   "type 7,5\n"
                                                   "key Return\n"
                                                   "key Escape\n"  // one press closes
                                                   "screenshot " +
                                                       dir.file("never.png").string() + "\n");
    ::setenv("XDG_CONFIG_HOME", dir.file("config").string().c_str(), 1);
    const CliResult r =
        run_cli({"lesson", "1", "--lessons", dir.file("course").string(), "--headless", "--script", script.string()});
    ::unsetenv("XDG_CONFIG_HOME");
    CHECK(r.code == 0);
    CHECK(r.err == "");
    CHECK_FALSE(std::filesystem::exists(dir.file("never.png")));  // closed before the script's last line
    course::LessonProgress p =
        course::load_progress(dir.file("config/impulse-lab/progress.json")).progress.lessons["01-ball"];
    CHECK(p.answers["impulse"].skipped);
    CHECK(p.answers["desired"].correct);
    CHECK(p.answers["desired"].tries == 2);  // 15 (wrong), then 7,5; the empty Enter was no try
    CHECK(p.last_step == 1);
}

}  // namespace impulse::test
