#include "gui/fonts.hpp"
#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"
#include "formats/input_error.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace impulse::gui {

namespace {

// The chapter's equation number as "eq. 14.3", never "(14.3)": in parentheses under a formula it read like a
// value (and "(7.5)" stood above a question whose answer was 7.5).
std::string equation_text(const std::string& equation) {
    if (equation.size() > 2 && equation.front() == '(' && equation.back() == ')')
        return "eq. " + equation.substr(1, equation.size() - 2);
    return equation;
}

// Column widths: the quantity's name and the equation whole; value, other frame and formula at least their widest
// word (no number, name or word of them is split); then each column grows towards its longest line, the meaning first
// to take what is left. When even the least is wider than the panel, the table scrolls sideways instead of cutting a
// value. The other frame is left out when no row has one.
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

Columns column_widths(const model::DerivationView& view, const std::vector<std::string>& hidden,
                      const std::vector<bool>& other_hidden, float available) {
    enum { quantity, value, other, formula, equation, meaning };
    std::array<float, 6> least{}, natural{};
    least[quantity] = natural[quantity] = ImGui::CalcTextSize("Quantity").x;
    least[equation] = natural[equation] = ImGui::CalcTextSize("eq. 14.3").x;
    least[formula] = least[meaning] = ImGui::CalcTextSize("Formula").x;
    least[value] = least[other] = ImGui::CalcTextSize("Value").x;
    bool any_other = false;
    ImGui::PushFont(value_font());
    for (std::size_t i = 0; i < view.rows.size(); ++i) {
        const explain::Row& r = view.rows[i].row;
        const bool is_hidden = !hidden[i].empty();
        const std::string_view shown = is_hidden ? std::string_view(hidden[i]) : std::string_view(r.value);
        // No word of a value is split ("frictionless"), a number least of all.
        least[value] = std::max(least[value], widest_word(is_hidden ? std::string_view(hidden[i]) : r.value));
        // A hidden value's words read as a phrase, not one to a line.
        if (is_hidden) least[value] = std::max(least[value], ImGui::CalcTextSize("? hidden until you").x);
        natural[value] = std::max(natural[value], longest_line(shown));
        any_other = any_other || !r.other_frame.empty();
        if (!other_hidden[i]) {
            least[other] = std::max(least[other], widest_word(r.other_frame));
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
        // A formula's words are names and never split; a meaning's plain words are split only when even the
        // column's least width cannot hold them.
        least[formula] = std::max(least[formula], widest_word(r.row.formula));
        least[meaning] = std::max(least[meaning], std::min(widest_word(r.row.meaning), 120.0f));
        least[quantity] = std::max(least[quantity], ImGui::CalcTextSize(r.row.quantity.c_str()).x);
        least[equation] = std::max(least[equation], std::min(longest_line(equation_text(r.row.equation)), 90.0f));
        natural[formula] = std::max(natural[formula], longest_line(r.row.formula));
        natural[meaning] = std::max(natural[meaning], longest_line(r.row.meaning));
    }
    least[quantity] = natural[quantity] = std::min(least[quantity], 280.0f);
    natural[equation] = least[equation];
    if (c.compact) natural[formula] = std::max(natural[formula], natural[equation]);
    // The headers are read whole too.
    if (c.compact) least[formula] = std::max(least[formula], ImGui::CalcTextSize("Formula (eq.)").x);
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

// Where a lesson's open question hides a value: which step to answer, as a link to it.
std::string hidden_text(const UiState& state, int step) {
    if (!state.lesson) return "? (hidden)";
    if (step == state.lesson->run.step()) return "? hidden until you answer this step's question";
    const course::Step& s = state.lesson->run.lesson().lesson.steps[static_cast<std::size_t>(step)];
    return "? hidden until you answer step " + std::to_string(step + 1) + " (" + s.id + ")";
}

// Scrolls the table (the current window) so the rows between `top` and `bottom` (screen y, as drawn at the current
// scroll) are in view below the header's `header` (screen y of its bottom), with `context` above them (the step's
// heading row), moving as little as it can; a range taller than the view shows its top.
void bring_into_view(float top, float bottom, float header, float context) {
    const float pad = ImGui::GetStyle().CellPadding.y * 2;
    const float view_top = header + context, view_bottom = ImGui::GetWindowPos().y + ImGui::GetWindowHeight() - pad;
    float delta = 0.0f;
    if (bottom - top > view_bottom - view_top || top < view_top)
        delta = top - view_top;
    else if (bottom > view_bottom)
        delta = bottom - view_bottom;
    if (delta != 0.0f) ImGui::SetScrollY(std::max(ImGui::GetScrollY() + delta, 0.0f));
}

}  // namespace

void draw_derivation(const model::Session& /*session*/, UiState& state) {
    CursorViews& v = state.views;
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

    // A lesson's open question hides its value, and what gives it away (the other frame's reading too), until it
    // is answered or skipped; the cell says which step's question to answer.
    std::vector<std::string> hidden(view.rows.size());
    std::vector<course::HiddenBy> hidden_by(view.rows.size());
    std::vector<bool> other_hidden(view.rows.size()), hidden_now(view.rows.size());
    for (std::size_t i = 0; i < view.rows.size(); ++i) {
        hidden_by[i] = state.mask.row_hidden_by(*v.cursor, view.rows[i].row);
        if (hidden_by[i]) hidden[i] = hidden_text(state, *hidden_by[i]);
        hidden_now[i] = hidden_by[i].has_value();
        other_hidden[i] = state.mask.other_frame_hidden_by(*v.cursor, view.rows[i].row).has_value();
    }
    // Rows an answer or a skip just revealed are brought into view, as a move brings the step's rows.
    // Those of the step's own rows when it has any (an answer reveals its step's value; rows further up are what
    // the student already read).
    std::vector<bool> revealed(view.rows.size(), false);
    bool any_revealed = false;
    if (v.hidden_rows_mask != state.mask_revision && v.hidden_rows.size() == hidden_now.size()) {
        for (std::size_t i = 0; i < hidden_now.size(); ++i) revealed[i] = v.hidden_rows[i] && !hidden_now[i];
        bool in_step = false;
        for (std::size_t i = 0; i < revealed.size(); ++i) in_step |= revealed[i] && view.rows[i].changed;
        for (std::size_t i = 0; i < revealed.size(); ++i) {
            if (in_step && !view.rows[i].changed) revealed[i] = false;
            any_revealed |= revealed[i];
        }
    }
    v.hidden_rows = hidden_now;
    v.hidden_rows_mask = state.mask_revision;
    const Columns columns = column_widths(view, hidden, other_hidden, ImGui::GetContentRegionAvail().x);

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
    const float header = ImGui::GetItemRectMax().y;
    // The table's column for each of the six, or -1 when left out.
    std::array<int, 6> column{-1, -1, -1, -1, -1, -1};
    for (std::size_t k = 0; k < columns.shown.size(); ++k)
        column[static_cast<std::size_t>(columns.shown[k])] = static_cast<int>(k);

    const ImVec4 dim = ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
    const ImVec4 link(0.6f, 0.85f, 1.0f, 1.0f);
    const ImU32 highlight = IM_COL32(70, 90, 40, 255);
    // The rows to bring into view: the revealed ones, or after a move the step's own (a lesson's step that names a
    // quantity, step=friction_solve.sliding_direction, is about that row).
    if (any_revealed) {
        v.bring_rows = revealed, v.bring_frames = 3, v.bring_context = 0.0f;
    } else if (v.scroll_to_cursor) {
        std::string named;
        if (state.lesson) try {
                named = model::parse_goto(state.lesson->run.current().at, "at").step.value_or("");
            } catch (const formats::InputError&) {
            }
        const bool named_shown = std::any_of(view.rows.begin(), view.rows.end(), [&](const model::ViewRow& r) {
            return r.changed && !named.empty() && r.row.key == named;
        });
        v.bring_rows.assign(view.rows.size(), false);
        for (std::size_t i = 0; i < view.rows.size(); ++i)
            v.bring_rows[i] = view.rows[i].changed && (!named_shown || view.rows[i].row.key == named);
        v.bring_frames = 3, v.bring_context = ImGui::GetTextLineHeightWithSpacing();
    }
    const bool bring = v.bring_frames > 0 && v.bring_rows.size() == view.rows.size();
    float top = -1.0f, bottom = -1.0f;
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
        if (!r.changed) ImGui::PushStyleColor(ImGuiCol_Text, dim);
        ImGui::TableSetColumnIndex(0);
        const float row_top = ImGui::GetCursorPosY() + ImGui::GetScrollY();
        float row_bottom = row_top;
        const auto grow = [&] {
            row_bottom =
                std::max(row_bottom, ImGui::GetItemRectMax().y - ImGui::GetWindowPos().y + ImGui::GetScrollY());
        };
        ImGui::TextUnformatted(r.row.quantity.c_str());
        grow();
        ImGui::PushFont(value_font());
        ImGui::TableSetColumnIndex(column[1]);
        if (hidden_by[i]) {
            ImGui::PushStyleColor(ImGuiCol_Text, link);
            wrapped_text(hidden[i]);
            ImGui::PopStyleColor();
            if (state.lesson && *hidden_by[i] != state.lesson->run.step()) {
                if (ImGui::IsItemHovered()) {
                    ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
                    ImGui::SetTooltip("Go to step %d", *hidden_by[i] + 1);
                }
                if (ImGui::IsItemClicked()) state.lesson->go_to_request = *hidden_by[i];
            }
        } else {
            wrapped_text(r.row.value);
            if (ImGui::IsItemHovered() && !r.row.exact.empty() && r.row.exact != r.row.value)
                ImGui::SetTooltip("exactly %s", r.row.exact.c_str());
        }
        grow();
        const std::string& other = other_hidden[i] && !hidden_by[i] ? std::string("?") : r.row.other_frame;
        if (columns.compact && !hidden_by[i] && !r.row.other_frame.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, dim);
            wrapped_text(other_hidden[i] ? "other frame: ? (hidden until you answer)" : r.row.other_frame);
            ImGui::PopStyleColor();
            grow();
        }
        if (column[2] >= 0 && ImGui::TableSetColumnIndex(column[2]) && !hidden_by[i]) wrapped_text(other), grow();
        ImGui::PopFont();
        ImGui::TableSetColumnIndex(column[3]);
        wrapped_text(r.row.formula);
        grow();
        if (columns.compact && !r.row.equation.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, dim);
            wrapped_text(equation_text(r.row.equation));
            ImGui::PopStyleColor();
            grow();
        }
        if (column[4] >= 0) {
            ImGui::TableSetColumnIndex(column[4]);
            wrapped_text(equation_text(r.row.equation));
            grow();
        }
        ImGui::TableSetColumnIndex(column[5]);
        wrapped_text(r.row.meaning);
        grow();
        if (!r.changed) ImGui::PopStyleColor();
        if (bring && v.bring_rows[i]) {
            if (top < 0) top = row_top;
            bottom = row_bottom;
        }
    }
    if (top >= 0) bring_into_view(top, bottom, header, v.bring_context);
    if (v.bring_frames > 0) --v.bring_frames;
    ImGui::EndTable();
}

}  // namespace impulse::gui
