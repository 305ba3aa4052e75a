// The lesson beside the inspector: the step's text, its question (answered before the value is shown), and
// the way through the lesson's steps.

#include "gui/panels.hpp"
#include "formats/input_error.hpp"

#include <imgui.h>

namespace impulse::gui {

namespace {

std::string_view trim_left(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    return s;
}

// Markdown shown as plain wrapped text: code spans and bold lose their marks, list items become bullets.
void draw_text(const std::string& markdown) {
    std::string paragraph;
    const auto flush = [&paragraph] {
        if (!paragraph.empty()) ImGui::TextWrapped("%s", paragraph.c_str());
        paragraph.clear();
    };
    std::size_t start = 0;
    while (start <= markdown.size()) {
        const std::size_t end = std::min(markdown.find('\n', start), markdown.size());
        std::string line = markdown.substr(start, end - start);
        start = end + 1;
        std::erase(line, '`');
        for (std::size_t bold = line.find("**"); bold != std::string::npos; bold = line.find("**")) line.erase(bold, 2);
        if (line.empty()) {
            flush();
            ImGui::Spacing();
        } else if (line.starts_with("- ") || line.starts_with("* ")) {
            // A list item, with the indented lines after it that continue it.
            flush();
            std::string item = line.substr(2);
            while (start < markdown.size() && markdown.compare(start, 2, "  ") == 0) {
                const std::size_t next = std::min(markdown.find('\n', start), markdown.size());
                item += " " + std::string(trim_left(markdown.substr(start, next - start)));
                start = next + 1;
            }
            std::erase(item, '`');
            ImGui::Bullet();
            ImGui::TextWrapped("%s", item.c_str());
        } else if (line.starts_with("#")) {
            flush();
            ImGui::TextColored(ImVec4(0.75f, 0.95f, 0.55f, 1.0f), "%s",
                               line.substr(line.find_first_not_of("# ")).c_str());
        } else {
            paragraph += (paragraph.empty() ? "" : " ") + line;
        }
        if (end == markdown.size()) break;
    }
    flush();
}

void record_answer(UiState& state, const std::string& typed, const lessons::Verdict& verdict) {
    LessonState& l = *state.lesson;
    if (!l.progress || !l.progress_file) return;
    lessons::AnswerRecord& record =
        l.progress->lessons[l.lesson->lesson.name].answers[l.lesson->lesson.steps[static_cast<std::size_t>(l.step)].id];
    record.answer = typed;
    record.correct = verdict.correct;
    ++record.tries;
    try {
        lessons::save_progress(*l.progress_file, *l.progress);
    } catch (const io::InputError& e) {
        state.message = e.problem(), state.message_is_error = true;
    }
}

}  // namespace

void draw_lesson(inspect::Session& session, UiState& state) {
    LessonState& l = *state.lesson;
    const lessons::Lesson& lesson = l.lesson->lesson;
    const auto index = static_cast<std::size_t>(l.step);
    const lessons::Step& step = lesson.steps[index];

    ImGui::TextColored(ImVec4(1.0f, 0.9f, 0.4f, 1.0f), "Lesson %d · %s", lesson.number, lesson.title.c_str());
    ImGui::Text("Step %d of %zu", l.step + 1, lesson.steps.size());
    ImGui::SameLine();
    if (ImGui::SmallButton("◀ Back") && l.step > 0) go_to_lesson_step(session, state, l.step - 1);
    ImGui::SameLine();
    if (ImGui::SmallButton("Next ▶") && l.step + 1 < static_cast<int>(lesson.steps.size()))
        go_to_lesson_step(session, state, l.step + 1);
    if (session.cursor() && !(*session.cursor() == l.lesson->places[index])) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Back to this step's place")) session.move_to(l.lesson->places[index]);
    }
    ImGui::Separator();

    const float question_height = step.question ? ImGui::GetTextLineHeightWithSpacing() * 8.0f : 0.0f;
    ImGui::BeginChild("text", ImVec2(0, -question_height), false);
    if (l.step == 0 && !lesson.introduction.empty()) {
        draw_text(lesson.introduction);
        ImGui::Separator();
    }
    draw_text(step.text);
    ImGui::EndChild();
    if (!step.question) return;

    const lessons::Question& q = *step.question;
    const lessons::Answer& answer = *l.lesson->answers[index];
    std::optional<lessons::Verdict>& verdict = l.verdicts[index];
    ImGui::Separator();
    ImGui::TextColored(ImVec4(0.6f, 0.85f, 1.0f, 1.0f), "Question");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", q.prompt.c_str());
    bool check = false;
    if (q.kind == lessons::Question::Kind::predict) {
        ImGui::SetNextItemWidth(140);
        check = ImGui::InputText("##answer", l.typed.data(), l.typed.size(), ImGuiInputTextFlags_EnterReturnsTrue);
        ImGui::SameLine();
        ImGui::TextDisabled("%s", answer.unit.c_str());
    } else {
        const int chosen = std::atoi(l.typed.data()) - 1;
        for (std::size_t o = 0; o < q.options.size(); ++o)
            if (ImGui::RadioButton(q.options[o].label.c_str(), chosen == static_cast<int>(o)))
                std::snprintf(l.typed.data(), l.typed.size(), "%zu", o + 1);
    }
    ImGui::SameLine();
    check = ImGui::Button("Check") || check;
    if (check) {
        try {
            verdict = lessons::check_answer(q, answer, l.typed.data());
            record_answer(state, l.typed.data(), *verdict);
        } catch (const io::InputError& e) {
            state.message = e.problem(), state.message_is_error = true;
        }
    }
    if (verdict)
        ImGui::TextColored(verdict->correct ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.4f, 1.0f), "%s",
                           verdict->feedback.c_str());
    else
        ImGui::TextDisabled("The value stays hidden in the tables until you answer.");
}

}  // namespace impulse::gui
