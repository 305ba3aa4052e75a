#include "gui/fonts.hpp"
#include "gui/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace impulse::gui {

void draw_derivation(const inspect::Session& session, UiState& state) {
    const CursorViews& v = state.views;
    if (!v.cursor) return;
    const inspect::DerivationView& view = v.derivation;
    ImGui::TextUnformatted(view.step_title.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("(highlighted: what this step computed)");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The rows above the highlighted ones are the earlier steps of this item, dimmed.");

    constexpr ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                                      ImGuiTableFlags_BordersOuterH | ImGuiTableFlags_ScrollY |
                                      ImGuiTableFlags_SizingStretchProp;
    // The quantity column fits its longest name (vocabulary names do not wrap); the rest share the width.
    // A table keeps its column widths once made, so each width (in steps of 10 px) gets its own table.
    float quantity_width = ImGui::CalcTextSize("Quantity").x;
    for (const inspect::ViewRow& r : view.rows)
        quantity_width = std::max(quantity_width, ImGui::CalcTextSize(r.row.quantity.c_str()).x);
    quantity_width = std::min(std::ceil(quantity_width / 10.0f) * 10.0f, 260.0f);
    const std::string table_id = "derivation " + std::to_string(static_cast<int>(quantity_width));
    if (!ImGui::BeginTable(table_id.c_str(), 6, flags)) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("Quantity", ImGuiTableColumnFlags_WidthFixed, quantity_width);
    ImGui::TableSetupColumn("Value", ImGuiTableColumnFlags_WidthStretch, 2.2f);
    ImGui::TableSetupColumn("Other frame", ImGuiTableColumnFlags_WidthStretch, 1.7f);
    ImGui::TableSetupColumn("Formula", ImGuiTableColumnFlags_WidthStretch, 1.5f);
    ImGui::TableSetupColumn("Eq.", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("(14.3)").x);
    ImGui::TableSetupColumn("Meaning", ImGuiTableColumnFlags_WidthStretch, 2.0f);
    ImGui::TableHeadersRow();

    const ImVec4 dim = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    // A lesson's open question hides its quantity (both bodies' rows of a per-body one) until answered.
    const std::string hidden = hidden_quantity(state, session);
    const std::string question_path =
        hidden.empty()
            ? std::string()
            : state.lesson->lesson->lesson.steps[static_cast<std::size_t>(state.lesson->step)].question->value;
    const auto is_hidden = [&](const std::string& quantity) { return is_hidden_row(hidden, question_path, quantity); };
    const ImU32 highlight = IM_COL32(70, 90, 40, 255);
    bool scrolled = false;
    std::string previous_step;
    for (const inspect::ViewRow& r : view.rows) {
        // A thin heading row wherever the step changes, so earlier steps stay readable as a derivation.
        if (r.step != previous_step) {
            previous_step = r.step;
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextColored(r.changed ? ImVec4(0.75f, 0.95f, 0.55f, 1.0f) : dim, "%s", r.step.c_str());
        }
        ImGui::TableNextRow();
        if (r.changed) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, highlight);
        if (r.changed && !scrolled && v.scroll_to_cursor) {
            ImGui::SetScrollHereY(0.1f);
            scrolled = true;
        }
        if (!r.changed) ImGui::PushStyleColor(ImGuiCol_Text, dim);
        ImGui::TableSetColumnIndex(0);
        ImGui::TextUnformatted(r.row.quantity.c_str());
        ImGui::PushFont(value_font());
        const bool secret = is_hidden(r.row.quantity);
        ImGui::TableSetColumnIndex(1);
        ImGui::TextWrapped("%s", secret ? "? (answer the lesson's question first)" : r.row.value.c_str());
        ImGui::TableSetColumnIndex(2);
        ImGui::TextWrapped("%s", secret ? "" : r.row.other_frame.c_str());
        ImGui::PopFont();
        ImGui::TableSetColumnIndex(3);
        ImGui::TextWrapped("%s", r.row.formula.c_str());
        ImGui::TableSetColumnIndex(4);
        ImGui::TextWrapped("%s", r.row.equation.c_str());
        ImGui::TableSetColumnIndex(5);
        ImGui::TextWrapped("%s", r.row.meaning.c_str());
        if (!r.changed) ImGui::PopStyleColor();
    }
    ImGui::EndTable();
}

}  // namespace impulse::gui
