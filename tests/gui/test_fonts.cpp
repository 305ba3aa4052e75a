// The window's fonts carry every glyph its text uses: each code point of the vocabulary (names, formulas,
// equations, units, meanings), of every table of every shipped lesson's and case's recording (titles, values,
// other-frame readings), of the lessons' texts, prompts and options, and of the window's own labels, is in both
// fonts (text and values), and a combining mark (the dot of θ̇) is drawn above the letter it sits on, not inside it.

#include "course/lesson.hpp"
#include "course/readings.hpp"
#include "explain/annotations.hpp"
#include "gui/layout_check.hpp"
#include "model/session.hpp"

#include <doctest/doctest.h>
#include <imgui.h>

#include <set>

namespace impulse::test {

namespace {

void add_code_points(std::set<unsigned>& points, std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t length = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        unsigned c = length == 1 ? lead : lead & (0xFF >> (length + 1));
        for (std::size_t k = 1; k < length && i + k < text.size(); ++k)
            c = (c << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        if (c >= 0x20) points.insert(c);
        i += length;
    }
}

void add_tables(std::set<unsigned>& points, const Trace& trace) {
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f)
        for (const model::Stage stage : model::stages(trace.frames[static_cast<std::size_t>(f)]))
            for (int i = 0; i < model::item_count(trace.frames[static_cast<std::size_t>(f)], stage); ++i)
                for (const explain::StepTable& t : model::step_tables(trace, model::Cursor{f, stage, i, 0})) {
                    add_code_points(points, t.title);
                    for (const explain::Row& r : t.rows)
                        for (const std::string* s :
                             {&r.quantity, &r.value, &r.formula, &r.equation, &r.meaning, &r.other_frame})
                            add_code_points(points, *s);
                }
}

}  // namespace

TEST_CASE("the window's fonts have a glyph for every code point of the vocabulary, the tables and the lessons") {
    std::set<unsigned> points;
    for (const explain::Annotation& a : explain::vocabulary())
        for (const std::string_view s : {a.quantity, a.formula, a.equation, a.unit, a.meaning})
            add_code_points(points, s);
    for (const std::filesystem::path& file : course::lesson_files(IMPULSE_SOURCE_DIR "/lessons")) {
        const course::PreparedLesson lesson = course::prepare_lesson(course::read_lesson(file));
        add_code_points(points,
                        lesson.lesson.title + course::reading(lesson.lesson.introduction, course::Reading::window));
        for (const course::Step& s : lesson.lesson.steps) {
            add_code_points(points, course::reading(s.text, course::Reading::window));
            if (!s.question) continue;
            add_code_points(points, s.question->prompt);
            for (const course::Option& o : s.question->options) add_code_points(points, o.label);
        }
        for (const auto& answer : lesson.answers)
            if (answer) add_code_points(points, answer->shown);
        add_tables(points, lesson.session.trace());
    }
    for (const char* name : {"ruler", "sliding_box", "oblique_friction", "three_objects", "deep_corner", "tilted_box"})
        add_tables(points, model::Session::open(IMPULSE_SOURCE_DIR "/scenes/cases/" + std::string(name) + ".json",
                                                model::OpenOptions{})
                               .trace());
    // The window's own labels: buttons, the step list's marks, the plots and the scene.
    add_code_points(points,
                    "|◀ First ◀◀ Phase Step ▶ Phase ▶▶ Last ▶| ◀ Back Next ▶ Finish ▶ ● ✓ ↷ ▶ → ε · Δv |g| N·s "
                    "ω θ̇ — “ ” ‘ ’ … × ⁻¹ ² ₀ ₁ ᵀ");
    CHECK(points.size() > 100);

    gui::OffscreenLayout layout(1280, 800);  // the window's fonts, in their own ImGui context
    const ImFontAtlas& atlas = *ImGui::GetIO().Fonts;
    REQUIRE(atlas.Fonts.Size == 2);  // text and values: the DejaVu fonts are installed
    std::string missing;
    for (const ImFont* font : atlas.Fonts)
        for (const unsigned c : points)
            if (!font->FindGlyphNoFallback(static_cast<ImWchar>(c))) {
                char text[16];
                std::snprintf(text, sizeof text, " U+%04X", c);
                missing += text;
            }
    CHECK_MESSAGE(missing.empty(), "no glyph for" << missing << " (" << points.size() << " code points)");

    // θ̇: the dot is drawn above the θ's ink, centred on it, not inside its top stroke.
    for (const ImFont* font : atlas.Fonts) {
        const ImFontGlyph* theta = font->FindGlyphNoFallback(0x3B8);
        const ImFontGlyph* dot = font->FindGlyphNoFallback(0x307);
        REQUIRE(theta);
        REQUIRE(dot);
        CHECK(dot->AdvanceX == 0.0f);
        CHECK(dot->Y1 < theta->Y0);
        const float centre = -theta->AdvanceX + (theta->X0 + theta->X1) / 2;
        CHECK(std::abs((dot->X0 + dot->X1) / 2 - centre) < 1.0f);
    }
}

}  // namespace impulse::test
