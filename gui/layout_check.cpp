#include "gui/layout_check.hpp"

#include "gui/display.hpp"
#include "gui/panels.hpp"

#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <set>

namespace impulse::gui {

namespace {

// The actions only a window can carry out do nothing here: the check moves by the lesson's own functions.
class NoHost final : public model::ActionHost {
public:
    void screenshot(const std::string&) override {}
    void view(const std::string&) override {}
    void lesson_step(int) override {}
    void quit() override {}
    void key(const std::string&) override {}
    void type(const std::string&) override {}
};

std::string rect_text(float x0, float y0, float x1, float y1) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.0f, %.0f)-(%.0f, %.0f)", x0, y0, x1, y1);
    return text;
}

// Checks the last frame's items; `needed` must all be among them.
void check_items(const UiState& state, int width, int height, const std::string& where,
                 const std::vector<std::string>& needed, LayoutReport& report) {
    constexpr float slack = 1.0f;  // ImGui rounds positions to whole pixels
    const float* panel = state.lesson_panel;
    if (panel[0] < -slack || panel[1] < -slack || panel[2] > width + slack || panel[3] > height + slack)
        report.problems.push_back(where + ": the lesson panel " + rect_text(panel[0], panel[1], panel[2], panel[3]) +
                                  " is not inside the window");
    std::set<std::string> seen;
    for (const LaidOutItem& item : state.layout) {
        ++report.items;
        seen.insert(item.what);
        const bool across = item.min_x >= item.region_min_x - slack && item.max_x <= item.region_max_x + slack;
        const bool down =
            item.scrolls || (item.min_y >= item.region_min_y - slack && item.max_y <= item.region_max_y + slack);
        const bool in_panel = item.region_min_x >= panel[0] - slack && item.region_max_x <= panel[2] + slack &&
                              item.region_min_y >= panel[1] - slack && item.region_max_y <= panel[3] + slack;
        if (!across || !down || !in_panel)
            report.problems.push_back(
                where + ": " + item.what + " at " + rect_text(item.min_x, item.min_y, item.max_x, item.max_y) +
                " is outside " + rect_text(item.region_min_x, item.region_min_y, item.region_max_x, item.region_max_y) +
                (in_panel ? "" : ", a region outside the lesson panel"));
    }
    for (const std::string& what : needed)
        if (!seen.count(what)) report.problems.push_back(where + ": no " + what + " was laid out");
}

}  // namespace

OffscreenLayout::OffscreenLayout(int width, int height) : previous_(ImGui::GetCurrentContext()) {
    context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(context_);
    set_up_imgui();
    ImGuiIO& io = ImGui::GetIO();
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);  // builds the atlas, as a renderer would
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DeltaTime = 1.0f / 60.0f;
}

OffscreenLayout::~OffscreenLayout() {
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous_);
}

void OffscreenLayout::frame(model::Session& session, UiState& state, float mouse_x, float mouse_y, bool mouse_down) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(mouse_x, mouse_y);
    io.MouseDown[0] = mouse_down;
    NoHost host;
    ImGui::NewFrame();
    draw_inspector(session, state, host);
    ImGui::Render();
}

LayoutReport check_lesson_layout(course::PreparedLesson& lesson, int width, int height) {
    OffscreenLayout layout(width, height);
    model::Session& session = lesson.session;
    UiState state;
    state.lesson.emplace(course::LessonRun(lesson, nullptr, std::nullopt), true);
    state.record_layout = true;
    LayoutReport report;

    // The lesson panel's items take their places within the frame that draws them (its sizes are measured,
    // never carried over from the frame before), so one frame per state is enough once the windows exist.
    layout.frame(session, state);
    const auto lay_out = [&] {
        layout.frame(session, state);
        ++report.states;
    };
    const int steps = state.lesson->run.step_count();
    for (int k = 0; k < steps; ++k) {
        go_to_lesson_step(session, state, k);  // with every question before it answered
        LessonState& l = *state.lesson;
        const course::Step& step = l.run.current();
        std::vector<std::string> needed{"button Back", "button Next"};
        if (step.question) {
            needed.insert(needed.end(), {"button Check", "button Skip", "verdict"});
            if (step.question->kind == course::Question::Kind::predict) needed.push_back("input");
            for (std::size_t o = 0; o < step.question->options.size(); ++o)
                needed.push_back("option " + std::to_string(o + 1));
        }
        const std::string where = "step " + std::to_string(k + 1) + " (" + step.id + ")";
        lay_out();
        check_items(state, width, height, where, needed, report);
        if (!step.question) continue;

        // A wrong answer (its verdict is the longest a predict question gets), then, from open again, a skip
        // (which shows the answer: for a choose question, its option's label).
        const course::Question& q = *step.question;
        const course::Answer& a = *lesson.answers[static_cast<std::size_t>(k)];
        std::string wrong;
        if (q.kind == course::Question::Kind::predict) {
            char text[64];
            std::snprintf(text, sizeof text, "%.6g", a.value.get<double>() * 1.5 + 1.0);
            wrong = text;
        } else {
            wrong = std::to_string((a.correct_option + 1) % static_cast<int>(q.options.size()) + 1);
        }
        l.run.answer(wrong);
        refresh_mask(session, state);
        lay_out();
        check_items(state, width, height, where + " answered wrong", needed, report);
        l.run.answered_before(k);
        refresh_mask(session, state);
        // About to move on with it open: the panel asks first, with its buttons below the question.
        l.leaving = k + 1;
        lay_out();
        std::vector<std::string> asked = needed;
        asked.insert(asked.end(), {"prompt", "button Skip it", "button Leave open", "button Stay"});
        check_items(state, width, height, where + " asked before leaving", asked, report);
        l.leaving.reset();
        l.run.skip();
        refresh_mask(session, state);
        lay_out();
        check_items(state, width, height, where + " skipped", needed, report);
    }
    // The end of the lesson, with every question still open (the longest list) and the next lesson offered.
    LessonState& l = *state.lesson;
    l.run.answered_before(0);
    l.finished = true;
    l.next_lesson =
        course::LessonLink{lesson.lesson.number + 1, "The next lesson's title, as long as a title gets", {}};
    lay_out();
    std::vector<std::string> needed{"score", "button Next lesson", "button Back to steps"};
    if (course::question_count(lesson.lesson) > 0) needed.push_back("open question");
    check_items(state, width, height, "the end", needed, report);
    return report;
}

}  // namespace impulse::gui
