// The lesson beside the inspector: the step's text, its question (answered before the value is shown), and
// the way through the lesson's steps. Everything wraps to the panel's width; the question, its Check and Skip
// buttons and the verdict sit below the text, sized to what they need, so they are never cut off.
// Keys while a lesson is open (gui/lesson_moves.cpp): → / PgDn / Enter the next step, ← / PgUp the previous
// one, Enter checks an answer, Ctrl+S skips it, Tab / Shift+Tab, ↑ / ↓ or an option's number pick an option,
// Esc closes the window; the inspector's moves stay on its buttons. Whatever is typed goes into the answer
// field, whether it has the keyboard yet or not.

#include "gui/lesson_moves.hpp"
#include "gui/lesson_colours.hpp"
#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"
#include "course/readings.hpp"
#include "formats/input_error.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace impulse::gui {

namespace {

std::string_view trim_left(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    return s;
}

std::string plain(std::string line) {
    std::erase(line, '`');
    for (std::size_t bold = line.find("**"); bold != std::string::npos; bold = line.find("**")) line.erase(bold, 2);
    return line;
}

// A lesson's text as the window reads it (course/readings.hpp).
std::string window_text(const std::string& text) {
    return course::reading(text, course::Reading::window);
}

// Markdown shown as plain wrapped text: code spans and bold lose their marks, list items become bullets.
void draw_markdown(UiState& state, const std::string& markdown) {
    std::string paragraph;
    const auto flush = [&] {
        if (!paragraph.empty()) {
            wrapped_text(paragraph);
            record_item(state, "text", true);
        }
        paragraph.clear();
    };
    std::size_t start = 0;
    while (start <= markdown.size()) {
        const std::size_t end = std::min(markdown.find('\n', start), markdown.size());
        std::string line = plain(markdown.substr(start, end - start));
        start = end + 1;
        if (line.empty()) {
            flush();
            ImGui::Spacing();
        } else if (line.starts_with("- ") || line.starts_with("* ")) {
            // A list item, with the indented lines after it that continue it.
            flush();
            std::string item = line.substr(2);
            while (start < markdown.size() && markdown.compare(start, 2, "  ") == 0) {
                const std::size_t next = std::min(markdown.find('\n', start), markdown.size());
                item += " " + plain(std::string(trim_left(markdown.substr(start, next - start))));
                start = next + 1;
            }
            ImGui::Bullet();
            wrapped_text(item);
            record_item(state, "text", true);
        } else if (line.starts_with("#")) {
            flush();
            ImGui::PushStyleColor(ImGuiCol_Text, heading_colour);
            wrapped_text(line.substr(line.find_first_not_of("# ")));
            ImGui::PopStyleColor();
            record_item(state, "text", true);
        } else {
            paragraph += (paragraph.empty() ? "" : " ") + line;
        }
        if (end == markdown.size()) break;
    }
    flush();
}

// Puts the caret after text typed before the field had the keyboard, instead of selecting it all.
int place_caret(ImGuiInputTextCallbackData* data) {
    auto* l = static_cast<LessonState*>(data->UserData);
    if (l->caret_to_end) {
        data->CursorPos = data->SelectionStart = data->SelectionEnd = data->BufTextLen;
        l->caret_to_end = false;
    }
    return 0;
}

// What the verdict's line says before any answer.
std::string hint(const course::Question& q) {
    return q.kind == course::Question::Kind::predict
               ? "Type a number (3.2, 3,2 or 1/60; its unit may follow) and press Enter. Its value stays hidden "
                 "everywhere until you answer."
               : "Pick an option (its number, Tab or ↑ ↓) and press Enter. The answer stays hidden until then.";
}

// The line under the question: the refusal of the last Enter, the verdict, or the hint.
std::string verdict_line(const LessonState& l) {
    if (!l.field_error.empty()) return l.field_error;
    const std::string& said = l.run.feedback(l.run.step());
    return said.empty() ? hint(*l.run.current().question) : said;
}

// The height the question takes below the text: prompt, input or options, the buttons and the verdict.
float question_height(const LessonState& l, float width) {
    const course::Question& q = *l.run.current().question;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float gap = style.ItemSpacing.y, frame = ImGui::GetFrameHeight();
    float h = gap * 2 + 1.0f;                                 // separator
    h += ImGui::GetFontSize() + gap;                          // "Question"
    h += wrapped_height(window_text(q.prompt), width) + gap;  // the prompt
    if (q.kind == course::Question::Kind::predict)
        h += frame + gap;
    else
        for (const course::Option& o : q.options)
            h += std::max(frame, wrapped_height(window_text(o.label), width - frame - style.ItemInnerSpacing.x)) + gap;
    h += frame + gap;  // Check, Skip
    h += wrapped_height(verdict_line(l), width) + gap;
    if (l.leaving) h += 2 * frame + 3 * gap + wrapped_height(std::string(220, 'x'), width);  // the prompt
    return h + style.WindowPadding.y;
}

void draw_question(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const auto index = static_cast<std::size_t>(l.run.step());
    const course::Question& q = *l.run.current().question;
    const course::Answer& answer = *l.run.lesson().answers[index];
    const course::QuestionState now = l.run.state(l.run.step());
    const bool open = now == course::QuestionState::open;

    ImGui::Separator();
    ImGui::TextColored(question_colour, "Question");
    record_item(state, "text");
    wrapped_text(window_text(q.prompt));
    record_item(state, "text");
    if (!open) ImGui::BeginDisabled();
    if (q.kind == course::Question::Kind::predict) {
        // A focus asked for takes the field at the next frame; asked again while that is pending, or while the
        // field has the keyboard, it would make ImGui start the field over and drop the Enter of that frame.
        const bool request = l.focus_answer && open && !l.leaving && !l.field_active && !l.focus_pending;
        if (request) ImGui::SetKeyboardFocusHere();
        if (request || l.field_active || !open) l.focus_answer = false;
        l.focus_pending = request;
        const float field_width = std::min(160.0f, ImGui::GetContentRegionAvail().x * 0.6f);
        if (open) {
            ImGui::SetNextItemWidth(field_width);
            // Any text: the answer's reader (course/answer_number.hpp) takes a decimal comma, a fraction and a
            // unit, and says what is wrong with anything else. A retry types over the last try.
            if (ImGui::InputText("##answer", l.typed.data(), l.typed.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll |
                                     ImGuiInputTextFlags_CallbackAlways,
                                 place_caret, &l))
                check_typed(session, state);
            l.field_active = ImGui::IsItemActive();
        } else {
            // Settled: the answer given, as text. No field, so a focus asked for before the answer (a frame's
            // delay) cannot take the keyboard from the lesson's keys.
            ImGui::Button(l.typed[0] ? l.typed.data() : "—", ImVec2(field_width, 0));
            l.field_active = l.focus_pending = false;
        }
        record_item(state, "input");
        ImGui::SameLine();
        ImGui::TextUnformatted(answer.unit.empty() ? "(no unit)" : answer.unit.c_str());
        record_item(state, "text");
    } else {
        const float frame = ImGui::GetFrameHeight();
        for (std::size_t o = 0; o < q.options.size(); ++o) {
            ImGui::PushID(static_cast<int>(o));
            const bool picked =
                l.chosen == static_cast<int>(o) || (!open && now == course::QuestionState::answered &&
                                                    static_cast<int>(o) == answer.correct_option && l.chosen < 0);
            if (ImGui::RadioButton("##option", picked)) l.chosen = static_cast<int>(o);
            const std::string what = "option " + std::to_string(o + 1);
            record_item(state, what.c_str());
            ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
            ImGui::BeginGroup();
            wrapped_text(window_text(q.options[o].label));
            ImGui::EndGroup();
            if (ImGui::IsItemClicked()) l.chosen = static_cast<int>(o);
            record_item(state, what.c_str());
            if (ImGui::GetItemRectSize().y < frame) ImGui::Dummy(ImVec2(0, 0));
            ImGui::PopID();
        }
    }
    // Check and Skip on their own line, where no label pushes them out of the panel.
    if (ImGui::Button("Check")) check_typed(session, state);
    record_item(state, "button Check");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enter");
    ImGui::SameLine();
    if (ImGui::Button("Skip")) skip_question(session, state);
    record_item(state, "button Skip");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the engine's answer; counted as skipped (Ctrl+S)");
    if (!open) ImGui::EndDisabled();

    // Beside the field: why Enter did nothing, the verdict, or how to answer.
    const std::string& said = l.run.feedback(l.run.step());
    ImGui::PushStyleColor(ImGuiCol_Text, !l.field_error.empty() ? error_colour
                                         : said.empty()         ? ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled)
                                         : now == course::QuestionState::answered ? right_colour
                                         : now == course::QuestionState::skipped  ? skipped_colour
                                                                                  : wrong_colour);
    wrapped_text(verdict_line(l));
    ImGui::PopStyleColor();
    record_item(state, "verdict");
    if (l.leaving) draw_leaving_prompt(session, state);
}

}  // namespace

void draw_lesson(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    handle_lesson_keys(session, state);
    const course::Lesson& lesson = l.run.lesson().lesson;
    const course::Step& step = l.run.current();
    if (state.record_layout) {
        const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
        state.lesson_panel[0] = pos.x, state.lesson_panel[1] = pos.y;
        state.lesson_panel[2] = pos.x + size.x, state.lesson_panel[3] = pos.y + size.y;
    }

    ImGui::PushStyleColor(ImGuiCol_Text, title_colour);
    wrapped_text("Lesson " + std::to_string(lesson.number) + " · " + lesson.title);
    ImGui::PopStyleColor();
    record_item(state, "text");
    if (l.finished)
        ImGui::TextUnformatted("Done");
    else
        ImGui::Text("Step %d of %d", l.run.step() + 1, l.run.step_count());
    record_item(state, "text");
    ImGui::SameLine();
    ImGui::BeginDisabled(!l.finished && l.run.step() == 0);
    if (ImGui::SmallButton("◀ Back")) request_step(session, state, l.finished ? l.run.step() : l.run.step() - 1);
    ImGui::EndDisabled();
    record_item(state, "button Back");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The previous step (← or Page Up)");
    ImGui::SameLine();
    ImGui::BeginDisabled(l.finished);
    const bool last = l.run.step() + 1 == l.run.step_count();
    if (ImGui::SmallButton(last ? "Finish ▶" : "Next ▶")) request_step(session, state, l.run.step() + 1);
    ImGui::EndDisabled();
    record_item(state, "button Next");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(last
                              ? "The end of the lesson: your score and what is still open (→, Page Down, or Enter once "
                                "answered)"
                              : "The next step (→, Page Down, or Enter once answered)");
    // The student stepped away with the inspector's buttons: one click brings the step's place back.
    std::optional<model::Cursor> place;
    try {
        place = model::resolve_goto(session.trace(), model::parse_goto(step.at, "at"), "at");
    } catch (const formats::InputError&) {
    }
    if (!l.finished && place && session.cursor() && !(*session.cursor() == *place)) {
        if (ImGui::SmallButton("Back to this step's place")) session.move_to(*place);
        record_item(state, "button Place");
    }
    draw_step_list(session, state);
    ImGui::Separator();
    if (l.finished) {
        ImGui::BeginChild("end", ImVec2(0, 0), false);
        draw_lesson_end(session, state);
        ImGui::EndChild();
        return;
    }

    const float width = ImGui::GetContentRegionAvail().x;
    const float lines = ImGui::GetTextLineHeightWithSpacing();
    const float below = step.question ? question_height(l, width) : 0.0f;
    // The text keeps at least four lines; a question taller than the rest scrolls within its own region.
    const float available = ImGui::GetContentRegionAvail().y;
    const float question_space = std::min(below, std::max(available - 4.0f * lines, 0.0f));
    ImGui::BeginChild("text", ImVec2(0, -question_space), false);
    if (l.run.step() == 0 && !lesson.introduction.empty()) {
        draw_markdown(state, window_text(lesson.introduction));
        ImGui::Separator();
    }
    draw_markdown(state, window_text(step.text));
    ImGui::EndChild();
    if (!step.question) return;
    if (question_space < below) {
        ImGui::BeginChild("question", ImVec2(0, 0), false);
        draw_question(session, state);
        ImGui::EndChild();
    } else {
        draw_question(session, state);
    }
}

}  // namespace impulse::gui
