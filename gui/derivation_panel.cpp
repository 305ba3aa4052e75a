#include "gui/fonts.hpp"
#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace impulse::gui {

namespace {

// Column widths: the quantity's name and the equation whole; value and other frame at least their widest
// number (a number is never split); then each column grows towards its longest line, the meaning first to
// take what is left. When even the least is wider than the panel, the table scrolls sideways instead of
// cutting a value. The other frame is left out when no row has one.
struct Columns {
    std::vector<int> shown;  // indices into the six columns
    std::array<float, 6> width{};
    bool scroll_x = false;
    // A narrow panel: the other frame goes under the value and the equation after the formula, four columns.
    bool compact = false;
};

// Below this width the table has four columns instead of six.
constexpr float compact_width = 900.0f;

float longest_line(std::string_view text) {
    float widest = 0.0f;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        widest = std::max(widest, ImGui::CalcTextSize(text.data() + start, text.data() + end).x);
        start = end + 1;
    }
    return widest;
}

Columns column_widths(const model::DerivationView& view, const std::vector<bool>& hidden, float available) {
    enum { quantity, value, other, formula, equation, meaning };
    const char* hidden_text = "? (hidden until you answer)";
    std::array<float, 6> least{}, natural{};
    least[quantity] = natural[quantity] = ImGui::CalcTextSize("Quantity").x;
    least[equation] = natural[equation] = ImGui::CalcTextSize("(14.3)").x;
    least[formula] = least[meaning] = ImGui::CalcTextSize("Formula").x;
    least[value] = least[other] = ImGui::CalcTextSize("Value").x;
    bool any_other = false;
    ImGui::PushFont(value_font());
    for (std::size_t i = 0; i < view.rows.size(); ++i) {
        const explain::Row& r = view.rows[i].row;
        const std::string_view shown = hidden[i] ? std::string_view(hidden_text) : std::string_view(r.value);
        least[value] =
            std::max(least[value], hidden[i] ? ImGui::CalcTextSize("(hidden until").x : widest_unbreakable(r.value));
        natural[value] = std::max(natural[value], longest_line(shown));
        any_other = any_other || !r.other_frame.empty();
        if (!hidden[i]) {
            least[other] = std::max(least[other], widest_unbreakable(r.other_frame));
            natural[other] = std::max(natural[other], longest_line(r.other_frame));
        }
    }
    ImGui::PopFont();
    Columns c;
    c.compact = available < compact_width;
    if (c.compact) {
        least[value] = std::max(least[value], least[other]);
        natural[value] = std::max(natural[value], natural[other]);
    }
    for (const model::ViewRow& r : view.rows) {
        // Words of a formula or a meaning are split only when even their column's least width cannot hold them.
        least[formula] = std::max(least[formula], std::min(widest_word(r.row.formula), 150.0f));
        least[meaning] = std::max(least[meaning], std::min(widest_word(r.row.meaning), 120.0f));
        least[quantity] = std::max(least[quantity], ImGui::CalcTextSize(r.row.quantity.c_str()).x);
        least[equation] = std::max(least[equation], std::min(longest_line(r.row.equation), 90.0f));
        natural[formula] = std::max(natural[formula], longest_line(r.row.formula));
        natural[meaning] = std::max(natural[meaning], longest_line(r.row.meaning));
    }
    least[quantity] = natural[quantity] = std::min(least[quantity], 280.0f);
    natural[equation] = least[equation];
    if (c.compact) natural[formula] = std::max(natural[formula], natural[equation]);
    for (int i = 0; i < 6; ++i)
        if (c.compact ? i != other && i != equation : i != other || any_other) c.shown.push_back(i);
    const ImGuiStyle& style = ImGui::GetStyle();
    const float padding = style.CellPadding.x * 2.0f * static_cast<float>(c.shown.size()) + style.ScrollbarSize + 4.0f;
    float sum = 0.0f;
    for (int i : c.shown)
        sum += least[static_cast<std::size_t>(i)],
            c.width[static_cast<std::size_t>(i)] = least[static_cast<std::size_t>(i)];
    float spare = available - padding - sum;
    if (spare < 0.0f) {
        c.scroll_x = true;
        return c;
    }
    // Towards each column's longest line, in proportion to what it lacks; what is left to the meaning and
    // the formula.
    float lacking = 0.0f;
    for (int i : c.shown) lacking += natural[static_cast<std::size_t>(i)] - least[static_cast<std::size_t>(i)];
    const float share = lacking > 0.0f ? std::min(1.0f, spare / lacking) : 0.0f;
    for (int i : c.shown) {
        const auto k = static_cast<std::size_t>(i);
        const float grow = (natural[k] - least[k]) * share;
        c.width[k] += grow;
        spare -= grow;
    }
    c.width[meaning] += spare * 0.6f;
    c.width[formula] += spare * 0.4f;
    return c;
}

}  // namespace

void draw_derivation(const model::Session& /*session*/, UiState& state) {
    const CursorViews& v = state.views;
    if (!v.cursor) return;
    const model::DerivationView& view = v.derivation;
    wrapped_text(view.step_title);
    // The hint beside the title when the line has room for it, else on a line of its own.
    const char* hint = "(highlighted: what this step computed)";
    ImGui::SameLine();
    if (ImGui::CalcTextSize(hint).x > ImGui::GetContentRegionAvail().x) ImGui::NewLine();
    ImGui::TextDisabled("%s", hint);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The rows above the highlighted ones are the earlier steps of this item, dimmed.");

    // A lesson's open question hides its value, and what gives it away, until it is answered or skipped.
    std::vector<bool> hidden(view.rows.size());
    for (std::size_t i = 0; i < view.rows.size(); ++i) hidden[i] = state.mask.hides_row(*v.cursor, view.rows[i].row);
    const Columns columns = column_widths(view, hidden, ImGui::GetContentRegionAvail().x);

    ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_BordersOuterH |
                            ImGuiTableFlags_ScrollY | ImGuiTableFlags_SizingFixedFit;
    if (columns.scroll_x) flags |= ImGuiTableFlags_ScrollX;
    // A table keeps its column widths once made, so each set of widths (in steps of 10 px) is its own table.
    std::string table_id = "derivation";
    for (int c : columns.shown)
        table_id +=
            " " + std::to_string(static_cast<int>(std::ceil(columns.width[static_cast<std::size_t>(c)] / 10.0f)));
    if (!ImGui::BeginTable(table_id.c_str(), static_cast<int>(columns.shown.size()), flags)) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    const char* names[6] = {"Quantity", "Value",  "Other frame", columns.compact ? "Formula (eq.)" : "Formula",
                            "Eq.",      "Meaning"};
    for (int c : columns.shown)
        ImGui::TableSetupColumn(names[c], ImGuiTableColumnFlags_WidthFixed, columns.width[static_cast<std::size_t>(c)]);
    ImGui::TableHeadersRow();
    // The table's column for each of the six, or -1 when left out.
    std::array<int, 6> column{-1, -1, -1, -1, -1, -1};
    for (std::size_t k = 0; k < columns.shown.size(); ++k)
        column[static_cast<std::size_t>(columns.shown[k])] = static_cast<int>(k);

    const ImVec4 dim = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    const ImU32 highlight = IM_COL32(70, 90, 40, 255);
    bool scrolled = false;
    std::string previous_step;
    for (std::size_t i = 0; i < view.rows.size(); ++i) {
        const model::ViewRow& r = view.rows[i];
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
        ImGui::TableSetColumnIndex(column[1]);
        if (hidden[i]) {
            wrapped_text("? (hidden until you answer)");
        } else {
            wrapped_text(r.row.value);
            if (ImGui::IsItemHovered() && !r.row.exact.empty() && r.row.exact != r.row.value)
                ImGui::SetTooltip("exactly %s", r.row.exact.c_str());
        }
        if (columns.compact && !hidden[i] && !r.row.other_frame.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, dim);
            wrapped_text(r.row.other_frame);
            ImGui::PopStyleColor();
        }
        if (column[2] >= 0 && ImGui::TableSetColumnIndex(column[2]) && !hidden[i]) wrapped_text(r.row.other_frame);
        ImGui::PopFont();
        ImGui::TableSetColumnIndex(column[3]);
        wrapped_text(r.row.formula);
        if (columns.compact && !r.row.equation.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, dim);
            wrapped_text(r.row.equation);
            ImGui::PopStyleColor();
        }
        if (column[4] >= 0) {
            ImGui::TableSetColumnIndex(column[4]);
            wrapped_text(r.row.equation);
        }
        ImGui::TableSetColumnIndex(column[5]);
        wrapped_text(r.row.meaning);
        if (!r.changed) ImGui::PopStyleColor();
    }
    ImGui::EndTable();
}

}  // namespace impulse::gui
