// The lesson beside the inspector: the step's text, its question (answered before the value is shown), and
// the way through the lesson's steps. Everything wraps to the panel's width; the question, its Check and Skip
// buttons and the verdict sit below the text, sized to what they need, so they are never cut off.
// Keys while a lesson is open: → / PgDn / Enter the next step, ← / PgUp the previous one, Enter checks an
// answer, Tab / Shift+Tab and ↑ / ↓ move between a question's options; the inspector's moves stay on its
// buttons.

#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"
#include "formats/input_error.hpp"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <cstring>

namespace impulse::gui {

namespace {

const ImVec4 title_colour(1.0f, 0.9f, 0.4f, 1.0f);
const ImVec4 heading_colour(0.75f, 0.95f, 0.55f, 1.0f);
const ImVec4 question_colour(0.6f, 0.85f, 1.0f, 1.0f);
const ImVec4 right_colour(0.5f, 0.9f, 0.5f, 1.0f);
const ImVec4 wrong_colour(1.0f, 0.65f, 0.4f, 1.0f);
const ImVec4 skipped_colour(0.75f, 0.75f, 1.0f, 1.0f);

std::string_view trim_left(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    return s;
}

std::string plain(std::string line) {
    std::erase(line, '`');
    for (std::size_t bold = line.find("**"); bold != std::string::npos; bold = line.find("**")) line.erase(bold, 2);
    return line;
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

void check(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const course::Question& q = *l.run.current().question;
    std::string typed = q.kind == course::Question::Kind::predict
                            ? std::string(l.typed.data())
                            : (l.chosen >= 0 ? std::to_string(l.chosen + 1) : std::string());
    if (typed.empty()) {
        state.message =
            q.kind == course::Question::Kind::predict ? "type your answer first" : "pick an option first (Tab or ↑ ↓)";
        state.message_is_error = true;
        return;
    }
    try {
        const course::AnswerVerdict verdict = l.run.answer(typed);
        state.message = l.run.save_problem(), state.message_is_error = !state.message.empty();
        // A wrong number stays in the field to be corrected; the field gets the keyboard again.
        if (!verdict.correct) l.focus_answer = true;
        refresh_mask(session, state);
    } catch (const formats::InputError& e) {
        state.message = e.problem(), state.message_is_error = true;
        l.focus_answer = true;
    }
}

void skip(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    l.run.skip();
    state.message = l.run.save_problem(), state.message_is_error = !state.message.empty();
    refresh_mask(session, state);
}

void next(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    if (l.run.step() + 1 < l.run.step_count()) go_to_lesson_step(session, state, l.run.step() + 1);
}

void back(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    if (l.run.step() > 0) go_to_lesson_step(session, state, l.run.step() - 1);
}

void handle_keys(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const ImGuiIO& io = ImGui::GetIO();
    // Typing in a field (the answer, a setting, an export path): the arrows move its caret and Enter is the
    // field's own.
    const bool typing = io.WantTextInput;
    const course::Step& step = l.run.current();
    const bool choose = step.question && step.question->kind == course::Question::Kind::choose;
    const int options = choose ? static_cast<int>(step.question->options.size()) : 0;
    for (int key : state.pressed_keys) {
        const bool open = l.run.waiting();
        switch (key) {
            case SDL_SCANCODE_RIGHT:
                if (!typing) next(session, state);
                break;
            case SDL_SCANCODE_PAGEDOWN:
                next(session, state);
                break;
            case SDL_SCANCODE_LEFT:
                if (!typing) back(session, state);
                break;
            case SDL_SCANCODE_PAGEUP:
                back(session, state);
                break;
            case SDL_SCANCODE_RETURN:
            case SDL_SCANCODE_KP_ENTER:
                if (typing) break;
                if (open && (l.chosen >= 0 || l.typed[0] != '\0'))
                    check(session, state);
                else if (!open)
                    next(session, state);
                break;
            case SDL_SCANCODE_TAB:
            case SDL_SCANCODE_DOWN:
            case SDL_SCANCODE_UP:
                if (!choose || !open) break;
                if (key == SDL_SCANCODE_UP || (key == SDL_SCANCODE_TAB && io.KeyShift))
                    l.chosen = l.chosen <= 0 ? options - 1 : l.chosen - 1;
                else
                    l.chosen = (l.chosen + 1) % options;
                break;
            case SDL_SCANCODE_ESCAPE:
                state.quit = true;
                break;
            default:
                break;
        }
    }
    state.pressed_keys.clear();
}

// What the verdict's line says before any answer.
std::string hint(const course::Question& q) {
    return q.kind == course::Question::Kind::predict
               ? "Type a number and press Enter. Its value stays hidden everywhere until you answer."
               : "Pick an option (Tab or ↑ ↓) and press Enter. The answer stays hidden until then.";
}

// The height the question takes below the text: prompt, input or options, the buttons and the verdict.
float question_height(const LessonState& l, float width) {
    const course::Question& q = *l.run.current().question;
    const ImGuiStyle& style = ImGui::GetStyle();
    const float gap = style.ItemSpacing.y, frame = ImGui::GetFrameHeight();
    float h = gap * 2 + 1.0f;                    // separator
    h += ImGui::GetFontSize() + gap;             // "Question"
    h += wrapped_height(q.prompt, width) + gap;  // the prompt
    if (q.kind == course::Question::Kind::predict)
        h += frame + gap;
    else
        for (const course::Option& o : q.options)
            h += std::max(frame, wrapped_height(o.label, width - frame - style.ItemInnerSpacing.x)) + gap;
    h += frame + gap;  // Check, Skip
    const std::string& said = l.run.feedback(l.run.step());
    h += wrapped_height(said.empty() ? hint(q) : said, width) + gap;
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
    wrapped_text(q.prompt);
    record_item(state, "text");
    if (!open) ImGui::BeginDisabled();
    if (q.kind == course::Question::Kind::predict) {
        if (l.focus_answer && open) ImGui::SetKeyboardFocusHere();
        l.focus_answer = false;
        ImGui::SetNextItemWidth(std::min(160.0f, ImGui::GetContentRegionAvail().x * 0.6f));
        if (ImGui::InputText("##answer", l.typed.data(), l.typed.size(),
                             ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific |
                                 ImGuiInputTextFlags_AutoSelectAll))  // a retry types over the last try
            check(session, state);
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
            wrapped_text(q.options[o].label);
            ImGui::EndGroup();
            if (ImGui::IsItemClicked()) l.chosen = static_cast<int>(o);
            record_item(state, what.c_str());
            if (ImGui::GetItemRectSize().y < frame) ImGui::Dummy(ImVec2(0, 0));
            ImGui::PopID();
        }
    }
    // Check and Skip on their own line, where no label pushes them out of the panel.
    if (ImGui::Button("Check")) check(session, state);
    record_item(state, "button Check");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Enter");
    ImGui::SameLine();
    if (ImGui::Button("Skip")) skip(session, state);
    record_item(state, "button Skip");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the engine's answer; counted as skipped");
    if (!open) ImGui::EndDisabled();

    const std::string& said = l.run.feedback(l.run.step());
    if (said.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        wrapped_text(hint(q));
    } else {
        ImGui::PushStyleColor(ImGuiCol_Text, now == course::QuestionState::answered  ? right_colour
                                             : now == course::QuestionState::skipped ? skipped_colour
                                                                                     : wrong_colour);
        wrapped_text(said);
    }
    ImGui::PopStyleColor();
    record_item(state, "verdict");
}

}  // namespace

void draw_lesson(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    handle_keys(session, state);
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
    ImGui::Text("Step %d of %d", l.run.step() + 1, l.run.step_count());
    record_item(state, "text");
    ImGui::SameLine();
    ImGui::BeginDisabled(l.run.step() == 0);
    if (ImGui::SmallButton("◀ Back")) back(session, state);
    ImGui::EndDisabled();
    record_item(state, "button Back");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The previous step (← or Page Up)");
    ImGui::SameLine();
    ImGui::BeginDisabled(l.run.step() + 1 == l.run.step_count());
    if (ImGui::SmallButton("Next ▶")) next(session, state);
    ImGui::EndDisabled();
    record_item(state, "button Next");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The next step (→, Page Down, or Enter once answered)");
    // The student stepped away with the inspector's buttons: one click brings the step's place back.
    std::optional<model::Cursor> place;
    try {
        place = model::resolve_goto(session.trace(), model::parse_goto(step.at, "at"), "at");
    } catch (const formats::InputError&) {
    }
    if (place && session.cursor() && !(*session.cursor() == *place)) {
        if (ImGui::SmallButton("Back to this step's place")) session.move_to(*place);
        record_item(state, "button Place");
    }
    ImGui::Separator();

    const float width = ImGui::GetContentRegionAvail().x;
    const float lines = ImGui::GetTextLineHeightWithSpacing();
    const float below = step.question ? question_height(l, width) : 0.0f;
    // The text keeps at least four lines; a question taller than the rest scrolls within its own region.
    const float available = ImGui::GetContentRegionAvail().y;
    const float question_space = std::min(below, std::max(available - 4.0f * lines, 0.0f));
    ImGui::BeginChild("text", ImVec2(0, -question_space), false);
    if (l.run.step() == 0 && !lesson.introduction.empty()) {
        draw_markdown(state, lesson.introduction);
        ImGui::Separator();
    }
    draw_markdown(state, step.text);
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
