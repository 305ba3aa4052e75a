#include "gui/panels.hpp"

#include "course/item_labels.hpp"

#include <imgui.h>

namespace impulse::gui {

namespace {

using model::Cursor;
using model::Stage;

// The items of one stage, clipped so a stage of thousands of iterations costs only the visible rows.
void draw_items(model::Session& session, UiState& state, int f, Stage stage) {
    const Trace& trace = session.trace();
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
    const Cursor& at = *session.cursor();
    const bool here = at.frame == f && at.stage == stage;
    ImGuiListClipper clipper;
    clipper.Begin(model::item_count(frame, stage));
    if (here && state.views.scroll_to_cursor) clipper.ForceDisplayRangeByIndices(at.item, at.item + 1);
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const bool current = here && at.item == i;
            ImGui::PushID(i);
            if (ImGui::Selectable(course::item_label(trace, state.mask, f, stage, i).c_str(), current))
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
    ImGui::EndChild();

    ImGui::Separator();
    ImGui::TextDisabled("Derivation steps of this item");
    const Cursor at = *session.cursor();
    const std::vector<explain::StepTable>& steps = state.views.steps;
    for (int s = 0; s < static_cast<int>(steps.size()); ++s) {
        ImGui::PushID(1000000 + s);
        if (ImGui::Selectable(steps[static_cast<std::size_t>(s)].title.c_str(), at.step == s))
            session.move_to(Cursor{at.frame, at.stage, at.item, s});
        ImGui::PopID();
    }
}

}  // namespace impulse::gui
