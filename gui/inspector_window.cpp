// The layout. The inspector alone: a toolbar across the top; the navigator and settings on the left; the
// derivation table above the scene view in the middle; contacts, bodies, plots and exports on the right.
// With a lesson, the lesson comes first: its panel down the whole left side, the derivation table beside
// it, and below that the scene and a panel of tabs for the rest. Panels tile the window at sizes set from
// the display (so a screenshot of a given size always looks the same); the borders between them are
// splitters the user can drag.

#include "gui/panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace impulse::gui {

namespace {

constexpr ImGuiWindowFlags panel_flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                         ImGuiWindowFlags_NoBringToFrontOnFocus;

bool begin_panel(const char* title, float x, float y, float w, float h, ImGuiWindowFlags extra = 0) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    return ImGui::Begin(title, nullptr, panel_flags | extra);
}

// A border between two panels the user can drag: `value` moves with the mouse along x (vertical border)
// or y, kept within [low, high]. Drawn after the panels, on top of them.
void splitter(const char* id, float x, float y, float w, float h, bool vertical, float& value, float low, float high) {
    constexpr float grip = 6.0f;
    const float gx = vertical ? x - grip / 2 : x, gy = vertical ? y : y - grip / 2;
    ImGui::SetNextWindowPos(ImVec2(gx, gy));
    ImGui::SetNextWindowSize(ImVec2(vertical ? grip : w, vertical ? h : grip));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoFocusOnAppearing);
    ImGui::InvisibleButton("grip", ImVec2(vertical ? grip : w, vertical ? h : grip));
    if (ImGui::IsItemHovered() || ImGui::IsItemActive())
        ImGui::SetMouseCursor(vertical ? ImGuiMouseCursor_ResizeEW : ImGuiMouseCursor_ResizeNS);
    if (ImGui::IsItemActive()) {
        const ImVec2 delta = ImGui::GetIO().MouseDelta;
        value = std::clamp(value + (vertical ? delta.x : delta.y), low, high);
    }
    ImGui::End();
    ImGui::PopStyleVar(2);
}

constexpr float toolbar_height = 62.0f;

void draw_lesson_layout(model::Session& session, UiState& state, model::ActionHost& host, ImVec2 screen) {
    PanelSizes& sizes = state.sizes;
    const float body = screen.y - toolbar_height;
    // The lesson's panel: a third of the window, enough for its text and options, leaving the tables room.
    const float narrowest = 300.0f, others = std::min(420.0f, screen.x * 0.45f);
    float lesson = sizes.lesson_width > 0 ? sizes.lesson_width : std::clamp(screen.x * 0.36f, 340.0f, 640.0f);
    lesson = std::clamp(lesson, narrowest, std::max(narrowest, screen.x - others));
    const float right = screen.x - lesson;
    const float share = sizes.derivation_share > 0 ? sizes.derivation_share : 0.5f;
    const float derivation = body * share;
    // The tabs beside the scene want their six names in a row (scrolled, Export hid behind arrows at 1280x800):
    // unless the splitter was moved, the scene gives way to them, down to 40 % of the row.
    const ImGuiStyle& style = ImGui::GetStyle();
    float tabs_width = style.WindowPadding.x * 2 + ImGui::GetFontSize() * 2;  // and room for the panel's edges
    for (const char* name : {"Contacts", "Bodies", "Plots", "Navigator", "Settings", "Export"})
        tabs_width += ImGui::CalcTextSize(name).x + style.FramePadding.x * 2 + style.ItemInnerSpacing.x;
    const float scene =
        sizes.scene_share > 0 ? right * sizes.scene_share : std::clamp(right - tabs_width, right * 0.4f, right * 0.55f);

    if (begin_panel("Lesson", 0, toolbar_height, lesson, body)) draw_lesson(session, state);
    ImGui::End();
    refresh_views(session, state);  // the lesson may have moved to another step

    if (begin_panel("Derivation", lesson, toolbar_height, right, derivation)) draw_derivation(session, state);
    ImGui::End();
    if (begin_panel("Scene", lesson, toolbar_height + derivation, scene, body - derivation))
        draw_scene_view(session, state);
    ImGui::End();
    if (begin_panel("##tabs", lesson + scene, toolbar_height + derivation, right - scene, body - derivation,
                    ImGuiWindowFlags_NoTitleBar) &&
        ImGui::BeginTabBar("tabs", ImGuiTabBarFlags_FittingPolicyScroll)) {
        const struct {
            const char* name;
            void (*draw)(model::Session&, UiState&, model::ActionHost&);
        } tabs[] = {
            {"Contacts", [](model::Session& s, UiState& u, model::ActionHost&) { draw_contacts(s, u); }},
            {"Bodies", [](model::Session& s, UiState& u, model::ActionHost&) { draw_bodies(s, u); }},
            {"Plots", [](model::Session& s, UiState& u, model::ActionHost&) { draw_plots(s, u); }},
            {"Navigator", [](model::Session& s, UiState& u, model::ActionHost&) { draw_navigator(s, u); }},
            {"Settings", [](model::Session& s, UiState& u, model::ActionHost& h) { draw_settings(s, u, h); }},
            {"Export", [](model::Session& s, UiState& u, model::ActionHost& h) { draw_export(s, u, h); }},
        };
        for (const auto& tab : tabs) {
            const bool open =
                ImGui::BeginTabItem(tab.name, nullptr, state.show_tab == tab.name ? ImGuiTabItemFlags_SetSelected : 0);
            record_control(state, std::string("tab ") + tab.name);
            if (open) {
                tab.draw(session, state, host);
                ImGui::EndTabItem();
            }
        }
        ImGui::EndTabBar();
        state.show_tab.clear();
    }
    ImGui::End();

    float lesson_edge = lesson, derivation_edge = derivation, scene_edge = lesson + scene;
    splitter("##lesson|", lesson, toolbar_height, 0, body, true, lesson_edge, narrowest,
             std::max(narrowest, screen.x - others));
    splitter("##derivation-", lesson, toolbar_height + derivation, right, 0, false, derivation_edge, body * 0.2f,
             body * 0.8f);
    splitter("##scene|", lesson + scene, toolbar_height + derivation, 0, body - derivation, true, scene_edge,
             lesson + right * 0.25f, lesson + right * 0.8f);
    if (lesson_edge != lesson) sizes.lesson_width = lesson_edge;
    if (derivation_edge != derivation) sizes.derivation_share = derivation_edge / body;
    if (scene_edge != lesson + scene) sizes.scene_share = (scene_edge - lesson) / right;
}

void draw_inspector_layout(model::Session& session, UiState& state, model::ActionHost& host, ImVec2 screen) {
    PanelSizes& sizes = state.sizes;
    const float body = screen.y - toolbar_height;
    // Wide enough for the navigator's rows and the settings' names (left) and the contacts list's six columns
    // (right) at 1280 px; the derivation table takes the rest.
    const float left = sizes.left_width > 0 ? sizes.left_width : std::clamp(screen.x * 0.22f, 260.0f, 420.0f);
    const float right = sizes.right_width > 0 ? sizes.right_width : std::clamp(screen.x * 0.32f, 300.0f, 540.0f);
    const float middle = screen.x - left - right;
    const float derivation = body * (sizes.derivation_share > 0 ? sizes.derivation_share : 0.5f);

    if (begin_panel("Navigator", 0, toolbar_height, left, body * 0.62f)) draw_navigator(session, state);
    ImGui::End();
    if (begin_panel("Settings", 0, toolbar_height + body * 0.62f, left, body * 0.38f))
        draw_settings(session, state, host);
    ImGui::End();
    refresh_views(session, state);

    if (begin_panel("Derivation", left, toolbar_height, middle, derivation)) draw_derivation(session, state);
    ImGui::End();
    if (begin_panel("Scene", left, toolbar_height + derivation, middle, body - derivation))
        draw_scene_view(session, state);
    ImGui::End();

    if (begin_panel("Contacts", left + middle, toolbar_height, right, body * 0.36f)) draw_contacts(session, state);
    ImGui::End();
    if (begin_panel("Bodies", left + middle, toolbar_height + body * 0.36f, right, body * 0.24f))
        draw_bodies(session, state);
    ImGui::End();
    if (begin_panel("Worst value per iteration", left + middle, toolbar_height + body * 0.60f, right, body * 0.26f))
        draw_plots(session, state);
    ImGui::End();
    if (begin_panel("Export", left + middle, toolbar_height + body * 0.86f, right, body * 0.14f))
        draw_export(session, state, host);
    ImGui::End();

    float left_edge = left, right_edge = left + middle, derivation_edge = derivation;
    splitter("##left|", left, toolbar_height, 0, body, true, left_edge, 160.0f, screen.x * 0.4f);
    splitter("##right|", left + middle, toolbar_height, 0, body, true, right_edge, screen.x * 0.5f, screen.x - 200.0f);
    splitter("##derivation-", left, toolbar_height + derivation, middle, 0, false, derivation_edge, body * 0.2f,
             body * 0.8f);
    if (left_edge != left) sizes.left_width = left_edge;
    if (right_edge != left + middle) sizes.right_width = screen.x - right_edge;
    if (derivation_edge != derivation) sizes.derivation_share = derivation_edge / body;
}

}  // namespace

void draw_inspector(model::Session& session, UiState& state, model::ActionHost& host) {
    refresh_views(session, state);
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    if (state.record_layout) state.layout.clear(), state.controls.clear();

    if (begin_panel("##toolbar", 0, 0, screen.x, toolbar_height, ImGuiWindowFlags_NoTitleBar))
        draw_toolbar(session, state, host);
    ImGui::End();
    // A move from the toolbar or a key: rebuild now, so every panel below draws the new place.
    refresh_views(session, state);

    if (state.lesson)
        draw_lesson_layout(session, state, host, screen);
    else
        draw_inspector_layout(session, state, host, screen);

    // Panels scroll to the cursor once after it moved; the contacts list may move it again (a click),
    // which the next frame shows.
    state.views.scroll_to_cursor = false;
}

}  // namespace impulse::gui
