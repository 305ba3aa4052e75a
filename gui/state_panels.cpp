// The state of the frame at the cursor: the contacts list, the bodies before and after, the phase plots.

#include "explain/format.hpp"
#include "gui/fonts.hpp"
#include "gui/panels.hpp"
#include "gui/text_wrap.hpp"

#include <imgui.h>

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <cmath>
#include <cstdio>

namespace impulse::gui {

namespace {

ImVec4 status_colour(model::ContactStatus status) {
    switch (status) {
        case model::ContactStatus::chosen:
            return {1.0f, 0.9f, 0.25f, 1.0f};
        case model::ContactStatus::waiting:
            return {0.95f, 0.55f, 0.25f, 1.0f};
        case model::ContactStatus::below_epsilon:
            return {0.55f, 0.78f, 0.55f, 1.0f};
    }
    return {1, 1, 1, 1};
}

// Goes to a contact: in the preparation, its steps; in a phase, the first iteration that resolves it.
void go_to_contact(model::Session& session, int row, int contact) {
    const model::Cursor at = *session.cursor();
    if (at.stage != model::Stage::preparation) {
        const Trace& trace = session.trace();
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(at.frame)];
        for (int i = 0; i < model::item_count(frame, at.stage); ++i)
            if (model::contact_at(trace, model::Cursor{at.frame, at.stage, i, 0}) == contact) {
                session.move_to(model::Cursor{at.frame, at.stage, i, 0});
                return;
            }
    }
    session.move_to(model::Cursor{at.frame, model::Stage::preparation, row, 0});
}

// "a → b" when the value changed, else "a".
std::string change_text(const Vec3& before, const Vec3& after) {
    return before == after ? explain::vector(after) : explain::vector(before) + " → " + explain::vector(after);
}
std::string change_text(const Quat& before, const Quat& after) {
    return explain::quaternion(before) + " → " + explain::quaternion(after);
}

struct Column {
    const char* name;
    float weight;
};

// A scrolling list with a frozen header row, its columns sharing the width by weight; `fit`: each column as
// wide as its content instead, the list scrolling sideways when the panel is narrower (no value is cut).
bool begin_list_table(const char* id, std::initializer_list<Column> columns, bool fit = false) {
    constexpr ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV;
    if (!ImGui::BeginTable(id, static_cast<int>(columns.size()),
                           flags | (fit ? ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX
                                        : ImGuiTableFlags_SizingStretchProp)))
        return false;
    ImGui::TableSetupScrollFreeze(0, 1);
    for (const Column& c : columns)
        ImGui::TableSetupColumn(c.name, fit ? ImGuiTableColumnFlags_WidthFixed : ImGuiTableColumnFlags_WidthStretch,
                                fit ? 0.0f : c.weight);
    ImGui::TableHeadersRow();
    return true;
}

}  // namespace

void draw_contacts(model::Session& session, UiState& state) {
    const CursorViews& v = state.views;
    if (!v.cursor) return;
    const Trace& trace = session.trace();
    const int current = model::contact_at(trace, *v.cursor);
    const course::Mask& mask = state.mask;  // what a lesson's open questions hide
    // Wrapped: at 1024 px wide the tab is narrower than the sentence.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    wrapped_text(std::string("Before this item, status in the ") +
                 (v.cursor->stage == model::Stage::velocity   ? "velocity"
                  : v.cursor->stage == model::Stage::position ? "position"
                                                              : "first") +
                 " phase. Click to go.");
    ImGui::PopStyleColor();
    if (!begin_list_table(
            "contacts",
            {{"#", 0.35f}, {"bodies", 1.2f}, {"pen. mm", 0.9f}, {"Δv m/s", 0.9f}, {"|g| N·s", 0.8f}, {"status", 0.75f}},
            true))
        return;
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(v.contacts.size()));
    int current_row = -1;
    for (std::size_t r = 0; r < v.contacts.size(); ++r)
        if (v.contacts[r].contact == current) current_row = static_cast<int>(r);
    if (current_row >= 0 && v.scroll_to_cursor) clipper.ForceDisplayRangeByIndices(current_row, current_row + 1);
    while (clipper.Step())
        for (int r = clipper.DisplayStart; r < clipper.DisplayEnd; ++r) {
            const model::ContactRow& row = v.contacts[static_cast<std::size_t>(r)];
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::PushID(r);
            const std::string id = std::to_string(row.contact);
            if (ImGui::Selectable(id.c_str(), row.contact == current, ImGuiSelectableFlags_SpanAllColumns))
                go_to_contact(session, r, row.contact);
            if (row.contact == current && v.scroll_to_cursor) ImGui::SetScrollHereY(0.4f);
            ImGui::PopID();
            ImGui::TableSetColumnIndex(1);
            if (mask.hides_bodies_of(v.cursor->frame, row.contact))
                ImGui::TextUnformatted("? / ?");
            else
                ImGui::Text("%s / %s", model::body_label(trace, row.prepared->bodies[0]).c_str(),
                            model::body_label(trace, row.prepared->bodies[1]).c_str());
            ImGui::PushFont(value_font());
            // Each value at the scale of the contact's own value as prepared: what rounding leaves of a
            // resolved penetration is 0.
            // Four significant digits (the list is narrow; every digit is in the tooltip and the tables), the
            // penetration in mm.
            const auto cell = [&](std::string_view key, double value, double scale, double factor = 1.0) {
                if (const course::HiddenBy by = mask.value_hidden_by(*v.cursor, row.contact, key, value)) {
                    ImGui::TextUnformatted("?");
                    if (ImGui::IsItemHovered()) ImGui::SetTooltip("hidden until you answer step %d", *by + 1);
                    return;
                }
                char digits[32];
                std::snprintf(digits, sizeof digits, "%.4g", value * factor);
                const std::string text = explain::number(value, scale) == "0" ? std::string("0") : digits;
                ImGui::TextUnformatted(text.c_str());
                if (ImGui::IsItemHovered())
                    ImGui::SetTooltip("exactly %s %s", explain::exact(value).c_str(),
                                      key == "penetration"     ? "m"
                                      : key == "impulse_world" ? "N·s"
                                                               : "m/s");
            };
            ImGui::TableSetColumnIndex(2);
            cell("penetration", row.penetration,
                 std::max(std::abs(row.prepared->penetration), std::abs(row.penetration)), 1e3);
            ImGui::TableSetColumnIndex(3);
            const double desired = row.prepared->desired_terms.desired_delta_velocity;
            cell("desired_delta_velocity", row.desired_delta_velocity,
                 std::max(std::abs(desired), std::abs(row.desired_delta_velocity)));
            ImGui::TableSetColumnIndex(4);
            cell("impulse_world", row.impulse_so_far.norm(), 0.0);
            ImGui::PopFont();
            ImGui::TableSetColumnIndex(5);
            ImGui::TextColored(status_colour(row.status), "%s", std::string(model::status_name(row.status)).c_str());
        }
    ImGui::EndTable();
}

void draw_bodies(const model::Session& session, UiState& state) {
    const CursorViews& v = state.views;
    if (!v.cursor) return;
    const Trace& trace = session.trace();
    if (!v.bodies.exact)
        ImGui::TextColored(ImVec4(1.0f, 0.5f, 0.4f, 1.0f),
                           "Frame start and end only: the recording's contact filter left out a move.");
    if (!begin_list_table(
            "bodies",
            {{"body", 0.6f}, {"position m (before → after)", 2.0f}, {"velocity m/s, ω rad/s (before → after)", 2.0f}}))
        return;
    // A lesson's open question hides the state of the bodies a hidden change moved, from that change on.
    const course::Mask& mask = state.mask;
    std::vector<char> moved(v.bodies.after.size(), 0);
    for (int b : v.bodies.moved) moved[static_cast<std::size_t>(b)] = 1;
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(v.bodies.after.size()));
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const auto b = static_cast<std::size_t>(i);
            course::HiddenBy by = mask.body_hidden_by(*v.cursor, i, false, v.bodies.before[b]);
            const bool hide_before = by.has_value();
            if (!by) by = mask.body_hidden_by(*v.cursor, i, true, v.bodies.after[b]);
            const bool hide_after = by.has_value();
            const BodyState& before = v.bodies.before[b];
            const BodyState& after = hide_after ? before : v.bodies.after[b];
            ImGui::TableNextRow();
            if (moved[b] && !hide_after) ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0, IM_COL32(90, 60, 20, 255));
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(trace.scene.body_names[b].c_str());
            if (hide_before || hide_after) {
                ImGui::TableSetColumnIndex(1);
                const std::string until = "? (hidden until you answer step " + std::to_string(*by + 1) + ")";
                wrapped_text(hide_before ? until : "as before → " + until);
                ImGui::TableSetColumnIndex(2);
                ImGui::TextWrapped("?");
                if (hide_before) continue;
            }
            ImGui::PushFont(value_font());
            if (!hide_after) {
                ImGui::TableSetColumnIndex(1);
                wrapped_text(change_text(before.position, after.position) + " m");
                if (before.orientation.coeffs() != after.orientation.coeffs())
                    wrapped_text("q " + change_text(before.orientation, after.orientation));
                ImGui::TableSetColumnIndex(2);
                wrapped_text("v " + change_text(before.velocity, after.velocity) + " m/s");
                wrapped_text("ω " + change_text(before.angular_velocity, after.angular_velocity) + " rad/s");
            }
            ImGui::PopFont();
        }
    ImGui::EndTable();
}

void draw_plots(const model::Session& session, UiState& state) {
    const CursorViews& v = state.views;
    if (!v.cursor) return;
    if (v.curves.empty()) {
        ImGui::TextDisabled("No iterations in this frame: every contact was below ε.");
        return;
    }
    const float width = ImGui::GetContentRegionAvail().x / static_cast<float>(v.curves.size()) - 8.0f;
    const float line = ImGui::GetTextLineHeight();
    // Below each plot a line for its iteration axis.
    const float height =
        std::max(ImGui::GetContentRegionAvail().y - ImGui::GetTextLineHeightWithSpacing() - line - 2.0f, 30.0f);
    const Trace& trace = session.trace();
    const ImU32 label_colour = IM_COL32(200, 200, 200, 255), epsilon_colour = IM_COL32(130, 190, 130, 255);
    for (std::size_t k = 0; k < v.curves.size(); ++k) {
        const model::PhaseCurve& c = v.curves[k];
        // A lesson's open question hides the values it would give away: those points are not drawn.
        const std::string_view key = c.stage == model::Stage::position ? "penetration" : "desired_delta_velocity";
        const char* unit = c.stage == model::Stage::position ? "m" : "m/s";
        std::vector<char> shown(c.worst.size(), 1);
        for (std::size_t i = 0; i < c.worst.size(); ++i) {
            const model::Cursor item{v.cursor->frame, c.stage, static_cast<int>(i), 0};
            shown[i] = !state.mask.hides_value(item, model::contact_at(trace, item), key, c.worst[i]);
        }
        if (k > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        const bool position = c.stage == model::Stage::position;
        ImGui::Text("%s: worst %s", position ? "positions" : "velocities", position ? "penetration (m)" : "Δv (m/s)");
        const ImVec2 a = ImGui::GetCursorScreenPos();
        const ImVec2 b(a.x + width, a.y + height);
        ImGui::Dummy(ImVec2(width, height + line + 2.0f));
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddRectFilled(a, b, IM_COL32(24, 26, 32, 255));
        // The scale's top is the largest value shown (or ε), with room above it; its label is that value.
        std::optional<std::size_t> largest_at;
        for (std::size_t i = 0; i < c.worst.size(); ++i)
            if (shown[i] && (!largest_at || c.worst[i] > c.worst[*largest_at])) largest_at = i;
        const double largest = largest_at ? std::max(c.worst[*largest_at], c.epsilon) : c.epsilon;
        // Room above the largest for its label's line.
        const double top = largest * (height - 4.0f) / std::max(height - 4.0f - line - 6.0f, 1.0f);
        const auto y_of = [&](double value) { return b.y - static_cast<float>(value / top) * (height - 4.0f) - 2.0f; };
        const auto x_of = [&](std::size_t i) {
            return a.x + 2.0f +
                   (width - 4.0f) * (c.worst.size() > 1 ? static_cast<float>(i) / (c.worst.size() - 1) : 0.5f);
        };
        draw->PushClipRect(a, ImVec2(b.x, b.y + line + 2.0f), true);
        draw->AddLine(ImVec2(a.x, y_of(c.epsilon)), ImVec2(b.x, y_of(c.epsilon)), IM_COL32(130, 190, 130, 200), 1.0f);
        // Thousands of iterations: at most one line segment per pixel column is drawn.
        const std::size_t stride =
            std::max<std::size_t>(1, c.worst.size() / static_cast<std::size_t>(std::max(width, 1.0f)));
        for (std::size_t i = stride; i < c.worst.size(); i += stride)
            if (shown[i - stride] && shown[i])
                draw->AddLine(ImVec2(x_of(i - stride), y_of(c.worst[i - stride])), ImVec2(x_of(i), y_of(c.worst[i])),
                              IM_COL32(240, 160, 70, 255), 1.5f);
        if (c.worst.size() == 1 && shown[0])
            draw->AddCircleFilled(ImVec2(x_of(0), y_of(c.worst[0])), 3.0f, IM_COL32(240, 160, 70, 255));
        if (v.cursor->stage == c.stage) {
            const auto i = static_cast<std::size_t>(v.cursor->item);
            draw->AddLine(ImVec2(x_of(i), a.y), ImVec2(x_of(i), b.y), IM_COL32(255, 230, 60, 160), 1.0f);
            if (shown[i]) draw->AddCircleFilled(ImVec2(x_of(i), y_of(c.worst[i])), 4.0f, IM_COL32(255, 230, 60, 255));
        }
        // Labels are values, never a scale's round number, and none covers another: the largest value at the top
        // left, ε at its line's right end (below the line when the top label is in the way), the iteration axis
        // under the plot.
        const bool any_hidden = std::find(shown.begin(), shown.end(), 0) != shown.end();
        const std::string peak = largest_at ? "largest " + explain::number(c.worst[*largest_at]) + " " + unit +
                                                  " (iteration " + std::to_string(*largest_at) + ")" +
                                                  (any_hidden ? ", some hidden" : "")
                                            : std::string("values hidden until you answer");
        // Each on a backing of the plot's colour, so a curve passing under it does not strike it through.
        const auto label = [&](ImVec2 at, ImU32 colour, const std::string& text) {
            const ImVec2 size = ImGui::CalcTextSize(text.c_str());
            draw->AddRectFilled(ImVec2(at.x - 2, at.y), ImVec2(at.x + size.x + 2, at.y + size.y),
                                IM_COL32(24, 26, 32, 220));
            draw->AddText(at, colour, text.c_str());
        };
        const ImVec2 peak_at(a.x + 4, a.y + 2);
        label(peak_at, label_colour, peak);
        const std::string eps = "ε " + explain::number(c.epsilon) + " " + unit;
        const ImVec2 eps_size = ImGui::CalcTextSize(eps.c_str());
        ImVec2 eps_at(b.x - eps_size.x - 4, y_of(c.epsilon) - line - 1);
        const float peak_right = peak_at.x + ImGui::CalcTextSize(peak.c_str()).x;
        if (eps_at.y < peak_at.y + line + 2 && eps_at.x < peak_right + 8) eps_at.y = y_of(c.epsilon) + 2;
        label(eps_at, epsilon_colour, eps);
        const std::string first = "iteration 0";
        const std::string last = "iteration " + std::to_string(c.worst.empty() ? 0 : c.worst.size() - 1);
        draw->AddText(ImVec2(a.x, b.y + 1), label_colour, first.c_str());
        const float last_width = ImGui::CalcTextSize(last.c_str()).x;
        if (c.worst.size() > 1 && last_width + ImGui::CalcTextSize(first.c_str()).x + 8 < width)
            draw->AddText(ImVec2(b.x - last_width, b.y + 1), label_colour, last.c_str());
        draw->PopClipRect();
        ImGui::EndGroup();
    }
}

}  // namespace impulse::gui
