#include "gui/start_page.hpp"

#include "course/lesson.hpp"
#include "formats/input_files.hpp"

#include <imgui.h>

#include <algorithm>

namespace impulse::gui {

namespace {

std::vector<std::filesystem::path> json_files(const std::filesystem::path& folder) {
    std::vector<std::filesystem::path> files;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(folder, error))
        if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A row of buttons, one per file, wrapping at the window's edge.
void file_buttons(const std::vector<std::filesystem::path>& files, const StartPageActions& actions) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    for (std::size_t i = 0; i < files.size(); ++i) {
        const std::string name = files[i].stem().string();
        const float width = ImGui::CalcTextSize(name.c_str()).x + style.FramePadding.x * 2;
        if (i > 0) {
            ImGui::SameLine();
            if (ImGui::GetItemRectMax().x + style.ItemSpacing.x + width > right) ImGui::NewLine();
        }
        if (ImGui::Button(name.c_str())) actions.open_file(files[i]);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Open %s in the inspector", files[i].filename().string().c_str());
    }
}

}  // namespace

CourseListing list_course(const std::filesystem::path& data, const course::Progress& progress) {
    CourseListing listing;
    for (const std::filesystem::path& file : course::lesson_files(data / "lessons")) {
        try {
            const course::Lesson lesson = course::read_lesson(file);
            CourseListing::LessonLine line{lesson.number, lesson.title, static_cast<int>(lesson.steps.size()),
                                           course::question_count(lesson), "not started"};
            if (const auto p = progress.lessons.find(lesson.name); p != progress.lessons.end())
                line.progress = course::tally_text(course::tally(p->second));
            listing.lessons.push_back(line);
        } catch (const formats::FileError& e) {
            listing.problems.push_back(e.file + ": " + (e.where.empty() ? "" : e.where + ": ") + e.problem);
        }
    }
    listing.scenes = json_files(data / "scenes");
    listing.cases = json_files(data / "scenes" / "cases");
    return listing;
}

void draw_start_page(const CourseListing& listing, const std::string& message, bool message_is_error,
                     const StartPageActions& actions, std::vector<LaidOutItem>* controls) {
    const auto record = [controls](const std::string& what) {
        if (controls) record_control(*controls, what);
    };
    if (controls) controls->clear();
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(0, 0));
    ImGui::SetNextWindowSize(io.DisplaySize);
    ImGui::Begin("##start", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    // A column of readable width in the middle of a wide window.
    const float width = std::min(io.DisplaySize.x - 32.0f, 980.0f);
    ImGui::SetCursorPosX(std::max(16.0f, (io.DisplaySize.x - width) / 2));
    ImGui::BeginGroup();
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextColored(ImVec4(1.0f, 0.9f, 0.4f, 1.0f), "Impulse Lab");
    ImGui::TextWrapped(
        "Collision resolution, step by step: chapter 14 of Millington's Game Physics Engine Development. Each lesson "
        "asks you to predict a value before the engine shows it, and keeps your answers in this browser.");
    if (!message.empty())
        ImGui::TextColored(message_is_error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.5f, 0.9f, 0.5f, 1.0f), "%s",
                           message.c_str());
    ImGui::Spacing();

    ImGui::TextColored(ImVec4(0.75f, 0.95f, 0.55f, 1.0f), "Lessons");
    if (ImGui::BeginTable("lessons", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH, ImVec2(width, 0))) {
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("Lesson", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("Steps", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("Your progress", ImGuiTableColumnFlags_WidthStretch, 0.7f);
        ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableHeadersRow();
        for (const CourseListing::LessonLine& l : listing.lessons) {
            ImGui::PushID(l.number);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("%d", l.number);
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.0f);  // a title wraps in its column, not at the page's column
            ImGui::TextWrapped("%s", l.title.c_str());
            ImGui::PopTextWrapPos();
            ImGui::TableNextColumn();
            ImGui::Text("%d, %d questions", l.steps, l.questions);
            ImGui::TableNextColumn();
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextWrapped("%s", l.progress.c_str());
            ImGui::PopTextWrapPos();
            ImGui::TableNextColumn();
            if (ImGui::Button("Open")) actions.open_lesson(l.number);
            record("button Open " + std::to_string(l.number));
            ImGui::SameLine();
            if (ImGui::Button("Worksheet")) actions.worksheet(l.number);
            record("button Worksheet " + std::to_string(l.number));
            if (ImGui::IsItemHovered())
                ImGui::SetTooltip("The cells of lesson %d's steps to fill in, as a CSV file to hand out", l.number);
            ImGui::PopID();
        }
        ImGui::EndTable();
    }
    for (const std::string& problem : listing.problems)
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", problem.c_str());
    ImGui::Spacing();

    ImGui::TextColored(ImVec4(0.75f, 0.95f, 0.55f, 1.0f), "Scenes (simulated, then stepped through)");
    file_buttons(listing.scenes, actions);
    ImGui::Spacing();
    ImGui::TextColored(ImVec4(0.75f, 0.95f, 0.55f, 1.0f), "Cases (contacts resolved once)");
    file_buttons(listing.cases, actions);
    ImGui::Spacing();

    ImGui::TextColored(ImVec4(0.75f, 0.95f, 0.55f, 1.0f), "Your own files");
    if (ImGui::Button("Open a scene, case or trace...")) actions.pick_file();
    record("button Open a file");
    ImGui::SameLine();
    ImGui::TextDisabled("(or drop one on the page)");
    if (ImGui::Button("Export progress.json")) actions.export_progress();
    record("button Export progress.json");
    ImGui::SameLine();
    if (ImGui::Button("Import progress.json...")) actions.import_progress();
    record("button Import progress.json");
    ImGui::PopTextWrapPos();
    ImGui::EndGroup();
    ImGui::End();
}

}  // namespace impulse::gui
