#include "gui/panels.hpp"

#include "course/item_labels.hpp"

#include <imgui.h>

#include <algorithm>

namespace impulse::gui {

namespace {

using model::Cursor;
using model::Stage;

// An item's row: its label on one line when it fits the panel, else in two, broken before its arrow
// ("sub-step 0 · warm_start" / "→ contact 3 (Δv 0.117 m/s)"). Returns whether it was clicked.
bool item_row(const std::string& label, bool current, bool two_lines) {
    if (!two_lines) return ImGui::Selectable(label.c_str(), current);
    const std::size_t arrow = label.find(" → ");
    const std::string first = label.substr(0, arrow),
                      second = arrow == std::string::npos ? "" : label.substr(arrow + 1);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const float line = ImGui::GetTextLineHeight();
    const bool clicked = ImGui::Selectable("##row", current, 0, ImVec2(0, 2 * line));
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 ink = ImGui::GetColorU32(ImGuiCol_Text);
    draw->AddText(at, ink, first.c_str());
    draw->AddText(ImVec2(at.x, at.y + line), ink, second.c_str());
    return clicked;
}

// The items of one stage, clipped so a stage of thousands of iterations costs only the visible rows (each of the
// same height: a stage whose labels do not fit on one line has all its rows in two).
void draw_items(model::Session& session, UiState& state, int f, Stage stage) {
    const Trace& trace = session.trace();
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
    const Cursor& at = *session.cursor();
    const bool here = at.frame == f && at.stage == stage;
    const int count = model::item_count(frame, stage);
    float widest = 0.0f;
    for (const int i : {0, count - 1, here ? at.item : 0})
        if (i >= 0 && i < count)
            widest =
                std::max(widest, ImGui::CalcTextSize(course::item_label(trace, state.mask, f, stage, i).c_str()).x);
    const bool two_lines = widest > ImGui::GetContentRegionAvail().x;
    ImGuiListClipper clipper;
    clipper.Begin(count);
    if (here && state.views.scroll_to_cursor) clipper.ForceDisplayRangeByIndices(at.item, at.item + 1);
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const bool current = here && at.item == i;
            ImGui::PushID(i);
            if (item_row(course::item_label(trace, state.mask, f, stage, i), current, two_lines))
                session.move_to(Cursor{f, stage, i, 0});
            if (current && state.views.scroll_to_cursor) ImGui::SetScrollHereY(0.4f);
            ImGui::PopID();
        }
}

}  // namespace

void draw_navigator(model::Session& session, UiState& state) {
    if (!session.cursor()) {
        ImGui::TextWrapped("The trace records nothing to step through: no contact in the recorded frames.");
        return;
    }
    const Trace& trace = session.trace();
    const float steps_height = ImGui::GetTextLineHeightWithSpacing() * 7.5f;
    ImGui::BeginChild("tree", ImVec2(0, -steps_height), false);
    // A narrow indent: the rows, three levels in, keep the width for their labels.
    ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 12.0f);
    for (int f = 0; f < static_cast<int>(trace.frames.size()); ++f) {
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
        const Cursor& at = *session.cursor();
        if (state.views.scroll_to_cursor && at.frame == f) ImGui::SetNextItemOpen(true);
        ImGui::PushID(f);
        const std::string label = "Frame " + std::to_string(frame.frame) + " (" + std::to_string(frame.contact_count) +
                                  (frame.contact_count == 1 ? " contact)" : " contacts)");
        if (ImGui::TreeNodeEx("frame", at.frame == f ? ImGuiTreeNodeFlags_Selected : 0, "%s", label.c_str())) {
            for (Stage stage : model::stages(frame)) {
                ImGui::PushID(static_cast<int>(stage));
                if (state.views.scroll_to_cursor && at.frame == f && at.stage == stage) ImGui::SetNextItemOpen(true);
                if (ImGui::TreeNode("stage", "%s", course::stage_label(frame, stage).c_str())) {
                    draw_items(session, state, f, stage);
                    ImGui::TreePop();
                }
                ImGui::PopID();
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    ImGui::PopStyleVar();
    ImGui::EndChild();

    ImGui::Separator();
    ImGui::TextDisabled("Derivation steps of this item");
    const Cursor at = *session.cursor();
    const std::vector<explain::StepTable>& steps = state.views.steps;
    // Each step by its name (the whole title, "impulse — in contact and world coordinates", when the panel is wide
    // enough, else in a tooltip).
    for (int s = 0; s < static_cast<int>(steps.size()); ++s) {
        const explain::StepTable& step = steps[static_cast<std::size_t>(s)];
        const bool whole = ImGui::CalcTextSize(step.title.c_str()).x <= ImGui::GetContentRegionAvail().x;
        ImGui::PushID(1000000 + s);
        if (ImGui::Selectable(whole ? step.title.c_str() : step.step.c_str(), at.step == s))
            session.move_to(Cursor{at.frame, at.stage, at.item, s});
        if (!whole && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", step.title.c_str());
        ImGui::PopID();
    }
}

}  // namespace impulse::gui
