#include "gui/lesson_moves.hpp"
#include "gui/lesson_colours.hpp"

#include "gui/keys.hpp"
#include "gui/text_wrap.hpp"
#include "formats/input_error.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

namespace impulse::gui {

namespace {

// Whether a text field has the keyboard at this moment. ImGui's io.WantTextInput lags a frame: it is still set in
// the frame after Enter closed the answer field, which would take the → pressed right after the answer.
bool text_field_active() {
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    return g.ActiveId != 0 && g.ActiveId == g.InputTextState.ID;
}

bool is_predict(const course::Step& step) {
    return step.question && step.question->kind == course::Question::Kind::predict;
}

void go(model::Session& session, UiState& state, int step) {
    LessonState& l = *state.lesson;
    l.leaving.reset();
    l.field_error.clear();
    l.finished = step >= l.run.step_count();
    if (!l.finished) go_to_lesson_step(session, state, step);
}

// The characters typed this frame, as UTF-8, taken from ImGui's queue so no field sees them.
std::string take_typed_characters() {
    ImGuiIO& io = ImGui::GetIO();
    std::string text;
    for (const ImWchar c : io.InputQueueCharacters) {
        const auto code = static_cast<unsigned>(c);
        if (code < 0x80) {
            text += static_cast<char>(code);
        } else if (code < 0x800) {
            text += static_cast<char>(0xC0 | (code >> 6));
            text += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            text += static_cast<char>(0xE0 | (code >> 12));
            text += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            text += static_cast<char>(0x80 | (code & 0x3F));
        }
    }
    io.InputQueueCharacters.resize(0);
    return text;
}

// Characters typed while no field had the keyboard. A predict question's field takes them (they are never
// dropped), a digit picks a choose question's option, and on the end screen a digit goes to an open question.
void take_characters(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const std::string typed = take_typed_characters();
    if (typed.empty()) return;
    const course::Step& step = l.run.current();
    if (l.finished) {
        const std::vector<int> open = course::lesson_end(l.run).open_steps;
        for (const char c : typed)
            if (c >= '1' && c <= '9' && c - '1' < static_cast<int>(open.size())) {
                go(session, state, open[static_cast<std::size_t>(c - '1')]);
                return;
            }
        return;
    }
    if (!l.run.waiting() || l.leaving) return;
    if (is_predict(step)) {
        // A retry types over the last try, as the field does when it has the keyboard (it selects it all).
        const bool last_try = l.typed.data() == l.run.given(l.run.step());
        std::string text = (last_try ? std::string() : std::string(l.typed.data())) + typed;
        text.resize(std::min(text.size(), l.typed.size() - 1));
        l.typed.fill('\0');
        text.copy(l.typed.data(), text.size());
        l.focus_answer = true;
        l.caret_to_end = true;
        l.field_error.clear();
        return;
    }
    for (const char c : typed)
        if (c >= '1' && c <= '9' && c - '1' < static_cast<int>(step.question->options.size())) l.chosen = c - '1';
}

// A small button coloured for a question's state.
bool coloured_button(const std::string& label, const ImVec4& colour, bool current) {
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    const bool pressed = ImGui::SmallButton(label.c_str());
    ImGui::PopStyleColor(current ? 2 : 1);
    return pressed;
}

}  // namespace

void request_step(model::Session& session, UiState& state, int step) {
    LessonState& l = *state.lesson;
    step = std::clamp(step, 0, l.run.step_count());
    if (!l.finished && step == l.run.step()) {
        stay(state);
        return;
    }
    // Moving on from an open question: ask first. Reading an earlier step again leaves it as it is.
    if (!l.finished && step > l.run.step() && l.run.waiting() && !l.preview) {
        l.leaving = step;
        return;
    }
    go(session, state, step);
}

void leave_open(model::Session& session, UiState& state) {
    if (const std::optional<int> to = state.lesson->leaving) go(session, state, *to);
}

void stay(UiState& state) {
    state.lesson->leaving.reset();
    state.lesson->focus_answer = true;
}

void check_typed(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    if (!l.run.current().question || !l.run.waiting()) return;
    const bool predict = is_predict(l.run.current());
    const std::string typed =
        predict ? std::string(l.typed.data()) : (l.chosen >= 0 ? std::to_string(l.chosen + 1) : std::string());
    l.leaving.reset();
    l.focus_answer = true;
    if (typed.empty()) {
        l.field_error = predict ? "Type your answer first: a number, e.g. 3.2, 3,2 or 1/60 (Ctrl+S skips)."
                                : "Pick an option first: its number, Tab or ↑ ↓ (Ctrl+S skips).";
        return;
    }
    try {
        l.run.answer(typed);
        l.field_error.clear();
        state.message = l.run.save_problem(), state.message_is_error = !state.message.empty();
        refresh_mask(session, state);
    } catch (const formats::InputError& e) {
        l.field_error = e.problem();
    }
}

void skip_question(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    if (!l.run.waiting()) return;
    l.run.skip();
    l.leaving.reset();
    l.field_error.clear();
    state.message = l.run.save_problem(), state.message_is_error = !state.message.empty();
    refresh_mask(session, state);
}

void handle_lesson_keys(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const ImGuiIO& io = ImGui::GetIO();
    // A field has the keyboard (the answer, a setting, an export path): its caret keys and Enter are its own.
    const bool typing = text_field_active();
    // ← and → move a field's caret, but an empty answer field has none to move: there they are the lesson's.
    const bool arrows_are_mine = !typing || (l.field_active && l.typed[0] == '\0');
    if (!typing) take_characters(session, state);
    if (l.go_to_request) {
        const int step = *l.go_to_request;
        l.go_to_request.reset();
        request_step(session, state, step);
    }
    const course::Step& step = l.run.current();
    const bool choose = step.question && step.question->kind == course::Question::Kind::choose;
    const int options = choose ? static_cast<int>(step.question->options.size()) : 0;
    const int here = l.run.step();
    for (const int pressed : state.pressed_keys) {
        const bool open = l.run.waiting() && !l.finished;
        switch (pressed) {
            case key::right:
            case key::page_down:
                if (!arrows_are_mine && pressed == key::right) break;
                if (l.finished) break;
                // A second → while asked: go on, the question left open.
                if (l.leaving)
                    leave_open(session, state);
                else
                    request_step(session, state, here + 1);
                break;
            case key::left:
            case key::page_up:
                if (!arrows_are_mine && pressed == key::left) break;
                if (l.leaving)
                    stay(state);
                else
                    request_step(session, state, l.finished ? l.run.step() : here - 1);
                break;
            case key::enter:
            case key::keypad_enter:
                if (typing) break;  // the answer field checks its own Enter
                if (l.finished) {
                    if (l.next_lesson) l.open_next = true, state.quit = true;
                } else if (l.leaving) {
                    if ((choose ? l.chosen >= 0 : l.typed[0] != '\0'))
                        check_typed(session, state);
                    else
                        stay(state);
                } else if (open) {
                    check_typed(session, state);
                } else {
                    request_step(session, state, here + 1);
                }
                break;
            case key::s:
                if (io.KeyCtrl && open) skip_question(session, state);
                break;
            case key::tab:
            case key::down:
            case key::up:
                if (!choose || !open || l.leaving) break;
                if (pressed == key::up || (pressed == key::tab && io.KeyShift))
                    l.chosen = l.chosen <= 0 ? options - 1 : l.chosen - 1;
                else
                    l.chosen = (l.chosen + 1) % options;
                break;
            case key::escape:
                // One press: it answers the question asked, else closes the window.
                if (l.leaving)
                    stay(state);
                else
                    state.quit = true;
                break;
            default:
                break;
        }
    }
    state.pressed_keys.clear();
}

void draw_step_list(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const float right_edge = ImGui::GetWindowContentRegionMax().x;
    for (int i = 0; i < l.run.step_count(); ++i) {
        const course::QuestionState q = l.run.state(i);
        const char* mark = q == course::QuestionState::open       ? " ●"
                           : q == course::QuestionState::answered ? " ✓"
                           : q == course::QuestionState::skipped  ? " ↷"
                                                                  : "";
        const ImVec4 colour = q == course::QuestionState::open       ? open_colour
                              : q == course::QuestionState::answered ? right_colour
                              : q == course::QuestionState::skipped  ? skipped_colour
                                                                     : ImGui::GetStyleColorVec4(ImGuiCol_Text);
        const std::string label = std::to_string(i + 1) + mark;
        const float width = ImGui::CalcTextSize(label.c_str()).x + ImGui::GetStyle().FramePadding.x * 2;
        if (i > 0) {
            ImGui::SameLine(0.0f, 4.0f);
            if (ImGui::GetCursorPosX() + width > right_edge) ImGui::NewLine();
        }
        ImGui::PushID(i);
        if (coloured_button(label, colour, i == l.run.step() && !l.finished)) request_step(session, state, i);
        ImGui::PopID();
        record_item(state, "step list");
        if (ImGui::IsItemHovered()) {
            const course::Step& s = l.run.lesson().lesson.steps[static_cast<std::size_t>(i)];
            const std::string tip = "step " + std::to_string(i + 1) + " · " + s.id +
                                    (q == course::QuestionState::open       ? ": its question is open"
                                     : q == course::QuestionState::answered ? ": answered"
                                     : q == course::QuestionState::skipped  ? ": skipped"
                                                                            : "");
            ImGui::SetTooltip("%s", tip.c_str());
        }
    }
}

void draw_leaving_prompt(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const bool choose = !is_predict(l.run.current());
    const bool typed = choose ? l.chosen >= 0 : l.typed[0] != '\0';
    ImGui::PushStyleColor(ImGuiCol_Text, open_colour);
    wrapped_text(std::string("Skip this question? It is still open. ") + (typed ? "Check your answer first, s" : "S") +
                 "kip it to see the engine's value, or go on and come back to it: the end of the lesson lists "
                 "open questions.");
    ImGui::PopStyleColor();
    record_item(state, "prompt");
    if (typed) {
        if (ImGui::Button("Check (Enter)")) check_typed(session, state);
        record_item(state, "button Check first");
        ImGui::SameLine();
    }
    if (ImGui::Button("Skip (Ctrl+S)")) skip_question(session, state);
    record_item(state, "button Skip it");
    // The buttons wrap rather than run out of a narrow panel.
    const auto next_button = [](const char* label) {
        ImGui::SameLine();
        if (ImGui::GetCursorPosX() + ImGui::CalcTextSize(label).x + ImGui::GetStyle().FramePadding.x * 2 >
            ImGui::GetWindowContentRegionMax().x)
            ImGui::NewLine();
    };
    next_button("Go on, leave it open (→)");
    if (ImGui::Button("Go on, leave it open (→)")) leave_open(session, state);
    record_item(state, "button Leave open");
    next_button("Stay (Esc)");
    if (ImGui::Button("Stay (Esc)")) stay(state);
    record_item(state, "button Stay");
}

// Drawn in a region that scrolls: what does not fit below is reached by scrolling.
void draw_lesson_end(model::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const course::LessonEnd end = course::lesson_end(l.run);
    ImGui::Separator();
    ImGui::PushStyleColor(ImGuiCol_Text, title_colour);
    wrapped_text("The end of lesson " + std::to_string(l.run.lesson().lesson.number));
    ImGui::PopStyleColor();
    record_item(state, "text", true);
    wrapped_text("Score: " + course::score_text(end) + ".");
    record_item(state, "score", true);
    if (!end.open_steps.empty()) {
        ImGui::Spacing();
        ImGui::PushStyleColor(ImGuiCol_Text, open_colour);
        wrapped_text("Still open (press its number to go to it):");
        ImGui::PopStyleColor();
        record_item(state, "text", true);
        for (std::size_t k = 0; k < end.open_steps.size(); ++k) {
            const int step = end.open_steps[k];
            ImGui::PushID(step);
            const std::string key = k < 9 ? std::to_string(k + 1) : std::string("·");
            if (ImGui::SmallButton(key.c_str())) go(session, state, step);
            record_item(state, "open question", true);
            ImGui::SameLine();
            wrapped_text(course::open_question_text(l.run, step));
            record_item(state, "text", true);
            ImGui::PopID();
        }
    }
    ImGui::Spacing();
    if (l.next_lesson) {
        wrapped_text("Next: lesson " + std::to_string(l.next_lesson->number) + " · " + l.next_lesson->title);
        record_item(state, "text", true);
        if (ImGui::Button("Open the next lesson (Enter)")) l.open_next = true, state.quit = true;
        record_item(state, "button Next lesson", true);
    } else {
        wrapped_text("That was the last lesson of the course.");
        record_item(state, "text", true);
    }
    if (ImGui::Button("◀ Back to the last step (←)")) go(session, state, l.run.step());
    record_item(state, "button Back to steps", true);
    ImGui::TextDisabled("Esc closes the window; your progress is kept.");
    record_item(state, "text", true);
}

}  // namespace impulse::gui
