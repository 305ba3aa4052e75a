// A lesson's text in its two readings (course/readings.hpp): the window's panels and the terminal's keys, one
// text per lesson; the terminal reading of the shipped course never sends a student to a panel it lacks.

#include "course/lesson.hpp"
#include "course/readings.hpp"
#include "formats/input_error.hpp"

#include <doctest/doctest.h>

namespace impulse::test {

using course::Reading;

TEST_CASE("a text with two readings reads as the window's or the terminal's, whole") {
    const std::string text = "Look at {{the bodies panel|the bodies (key o)}}, then {{the Settings\ntab|set x 1}}.";
    CHECK(course::reading(text, Reading::window) == "Look at the bodies panel, then the Settings\ntab.");
    CHECK(course::reading(text, Reading::terminal) == "Look at the bodies (key o), then set x 1.");
    CHECK(course::reading("{{|only in the terminal }}text", Reading::window) == "text");
    CHECK(course::reading("no readings, |v_s| stays", Reading::terminal) == "no readings, |v_s| stays");
    CHECK_NOTHROW(course::check_readings(text, "t"));
    const auto problem = [](std::string_view bad) {
        try {
            course::check_readings(bad, "section \"a\"");
        } catch (const formats::InputError& e) {
            CHECK(e.where() == "section \"a\"");
            return e.problem();
        }
        return std::string("accepted");
    };
    CHECK(problem("see {{the panel|key o").starts_with("\"{{the panel|key o\" has no closing }}"));
    CHECK(problem("see {{the panel}}").starts_with("\"{{the panel}}\" has no | between"));
    CHECK(problem("see the panel}}").starts_with("a }} without its {{"));
    CHECK(problem("{{a {{b|c}}|d}}").find("cannot nest") != std::string::npos);
}

TEST_CASE("the shipped lessons' terminal readings name the terminal's keys, never a window's panel or tab") {
    for (const std::filesystem::path& file : course::lesson_files(IMPULSE_SOURCE_DIR "/lessons")) {
        const course::Lesson lesson = course::read_lesson(file);
        std::string all = lesson.introduction;
        for (const course::Step& s : lesson.steps) {
            all += "\n" + s.text;
            if (s.question) all += "\n" + s.question->prompt;
        }
        const std::string terminal = course::reading(all, Reading::terminal);
        const std::string window = course::reading(all, Reading::window);
        INFO(file.filename().string());
        for (const std::string panel : {"Settings tab", "the navigator", "The navigator", "bodies panel",
                                        "contacts panel", "contacts list", "in the window", "untick"})
            CHECK_MESSAGE(terminal.find(panel) == std::string::npos, "the terminal reading names \"" << panel << "\"");
        for (const std::string key : {"(key o)", "(key c)", "(key i)", "(set "})
            CHECK_MESSAGE(window.find(key) == std::string::npos, "the window reading names \"" << key << "\"");
    }
}

}  // namespace impulse::test
