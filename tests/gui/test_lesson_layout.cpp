// The lesson window fits: every step of every lesson, laid out at 921x691 (the window a 1024x768 display gets),
// 1024x768, 1280x800 and 1920x1080 as the
// student meets it, after a wrong answer and after a skip, has every text and control of the lesson
// panel inside the window, read from ImGui's own item rectangles.

#include "gui/layout_check.hpp"
#include "course/lesson.hpp"
#include "course/lesson_run.hpp"

#include <doctest/doctest.h>

namespace impulse::test {

TEST_CASE("every step of every lesson fits the lesson panel at 921x691, 1024x768, 1280x800 and 1920x1080") {
    const std::vector<std::filesystem::path> files = course::lesson_files(IMPULSE_SOURCE_DIR "/lessons");
    REQUIRE(files.size() == 14);
    int states = 0, items = 0;
    for (const std::filesystem::path& file : files) {
        course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        // 921x691: the window a 1024x768 display gets (90 % of it).
        for (const std::pair<int, int>& size :
             {std::pair{921, 691}, std::pair{1024, 768}, std::pair{1280, 800}, std::pair{1920, 1080}}) {
            const int width = size.first, height = size.second;  // named, not bound: INFO captures them
            const gui::LayoutReport report = gui::check_lesson_layout(lesson, width, height);
            INFO(file.filename().string() << " at " << width << "x" << height);
            for (const std::string& problem : report.problems) FAIL_CHECK(problem);
            CHECK(report.states >= static_cast<int>(lesson.lesson.steps.size()));
            states += report.states;
            items += report.items;
        }
    }
    MESSAGE(states << " step states and " << items << " items checked");
}

}  // namespace impulse::test

namespace impulse::test {

TEST_CASE("dragging the border beside the lesson widens its panel, and the layout keeps the new width") {
    course::PreparedLesson lesson =
        course::prepare_lesson(course::read_lesson(course::lesson_files(IMPULSE_SOURCE_DIR "/lessons").front()));
    gui::OffscreenLayout layout(1280, 800);
    gui::UiState state;
    state.lesson.emplace(course::LessonRun(lesson, nullptr, std::nullopt), true);
    state.record_layout = true;
    layout.frame(lesson.session, state);
    // The default: 36 % of 1280 px.
    const float before = state.lesson_panel[2];
    CHECK(before == doctest::Approx(1280 * 0.36f).epsilon(0.01));
    // Press on the border, move 100 px right over a few frames, release.
    layout.frame(lesson.session, state, before, 300, false);
    layout.frame(lesson.session, state, before, 300, true);
    for (float x = before; x <= before + 100; x += 25) layout.frame(lesson.session, state, x, 300, true);
    layout.frame(lesson.session, state, before + 100, 300, false);
    layout.frame(lesson.session, state);
    CHECK(state.lesson_panel[2] == doctest::Approx(before + 100).epsilon(0.02));
    CHECK(state.sizes.lesson_width == doctest::Approx(before + 100).epsilon(0.02));
}

}  // namespace impulse::test

#include "gui/layout_memory.hpp"
#include "support/temp_dir.hpp"

#include <cstdlib>

namespace impulse::test {

TEST_CASE("a window's panel layout is remembered as shares of the window, and a bad file gives the defaults") {
    gui::PanelSizes s;
    s.lesson_width = 512;
    s.derivation_share = 0.4f;
    s.scene_share = 0.6f;
    const std::string text = gui::layout_text(s, 1280, 800);
    // The same proportions in a window of another size.
    const gui::PanelSizes wide = gui::layout_from_text(text, 1920, 1080);
    CHECK(wide.lesson_width == doctest::Approx(512.0 / 1280 * 1920));
    CHECK(wide.derivation_share == doctest::Approx(0.4));
    CHECK(wide.scene_share == doctest::Approx(0.6));
    CHECK(wide.left_width == 0);  // never dragged: the default
    // Kept beside the progress file; none there yet gives the defaults, and a kept one comes back.
    TempDir dir;
    ::setenv("XDG_CONFIG_HOME", dir.file("config").string().c_str(), 1);
    CHECK(gui::load_layout(1280, 800).lesson_width == 0);
    CHECK(gui::save_layout(s, 1280, 800));
    CHECK(gui::load_layout(1280, 800).lesson_width == doctest::Approx(512));
    ::unsetenv("XDG_CONFIG_HOME");
    for (const char* bad : {"", "not json", "{\"format\": \"something else\", \"lesson_width\": 0.4}",
                            "{\"format\": \"impulse-lab-layout\", \"lesson_width\": 3}"}) {
        const gui::PanelSizes d = gui::layout_from_text(bad, 1280, 800);
        CHECK(d.lesson_width == 0);
        CHECK(d.derivation_share == 0);
    }
}

}  // namespace impulse::test

namespace impulse::test {

TEST_CASE("the lesson window's borders stay where they are until dragged, at every window size") {
    // The scene's border once took its position for its width: at 1920 px its share flipped every frame.
    course::PreparedLesson lesson =
        course::prepare_lesson(course::read_lesson(course::lesson_files(IMPULSE_SOURCE_DIR "/lessons").front()));
    for (const auto& [width, height] : {std::pair{1024, 768}, std::pair{1280, 800}, std::pair{1920, 1080}}) {
        gui::OffscreenLayout layout(width, height);
        gui::UiState state;
        state.lesson.emplace(course::LessonRun(lesson, nullptr, std::nullopt), true);
        for (int frame = 0; frame < 4; ++frame) layout.frame(lesson.session, state);
        CHECK(state.sizes.lesson_width == 0);
        CHECK(state.sizes.derivation_share == 0);
        CHECK(state.sizes.scene_share == 0);
    }
}

}  // namespace impulse::test
