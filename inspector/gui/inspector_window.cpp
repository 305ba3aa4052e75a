// The layout: a toolbar across the top; the navigator and settings on the left; the derivation table
// above the scene view in the middle; contacts, bodies, plots and exports on the right. Fixed panels
// sized from the display, so a screenshot of a given size always looks the same.

#include "gui/panels.hpp"

#include <imgui.h>

namespace impulse::gui {

namespace {

constexpr ImGuiWindowFlags panel_flags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

bool begin_panel(const char* title, float x, float y, float w, float h, ImGuiWindowFlags extra = 0) {
    ImGui::SetNextWindowPos(ImVec2(x, y));
    ImGui::SetNextWindowSize(ImVec2(w, h));
    return ImGui::Begin(title, nullptr, panel_flags | extra);
}

}  // namespace

void draw_inspector(inspect::Session& session, UiState& state, inspect::ActionHost& host) {
    refresh_views(session, state);
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    const float toolbar = 62.0f;
    const float left = screen.x * (state.lesson ? 0.25f : 0.19f), right = screen.x * 0.25f,
                middle = screen.x - left - right;
    const float body = screen.y - toolbar;

    if (begin_panel("##toolbar", 0, 0, screen.x, toolbar, ImGuiWindowFlags_NoTitleBar))
        draw_toolbar(session, state, host);
    ImGui::End();
    // A move from the toolbar or a key: rebuild now, so every panel below draws the new place.
    refresh_views(session, state);

    if (state.lesson) {
        // A lesson takes the navigator's place; the navigator and the settings share the panel below it.
        if (begin_panel("Lesson", 0, toolbar, left, body * 0.58f)) draw_lesson(session, state);
        ImGui::End();
        if (begin_panel("##tools", 0, toolbar + body * 0.58f, left, body * 0.42f, ImGuiWindowFlags_NoTitleBar) &&
            ImGui::BeginTabBar("tools")) {
            if (ImGui::BeginTabItem("Navigator")) {
                draw_navigator(session, state);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem("Settings")) {
                draw_settings(session, state, host);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        ImGui::End();
    } else {
        if (begin_panel("Navigator", 0, toolbar, left, body * 0.62f)) draw_navigator(session, state);
        ImGui::End();
        if (begin_panel("Settings", 0, toolbar + body * 0.62f, left, body * 0.38f)) draw_settings(session, state, host);
        ImGui::End();
    }
    refresh_views(session, state);

    if (begin_panel("Derivation", left, toolbar, middle, body * 0.5f)) draw_derivation(session, state);
    ImGui::End();
    if (begin_panel("Scene", left, toolbar + body * 0.5f, middle, body * 0.5f)) draw_scene_view(session, state);
    ImGui::End();

    if (begin_panel("Contacts", left + middle, toolbar, right, body * 0.36f)) draw_contacts(session, state);
    ImGui::End();
    if (begin_panel("Bodies", left + middle, toolbar + body * 0.36f, right, body * 0.24f)) draw_bodies(session, state);
    ImGui::End();
    if (begin_panel("Worst value per iteration", left + middle, toolbar + body * 0.60f, right, body * 0.26f))
        draw_plots(session, state);
    ImGui::End();
    if (begin_panel("Export", left + middle, toolbar + body * 0.86f, right, body * 0.14f))
        draw_export(session, state, host);
    ImGui::End();

    // Panels scroll to the cursor once after it moved; the contacts list may move it again (a click),
    // which the next frame shows.
    state.views.scroll_to_cursor = false;
}

}  // namespace impulse::gui
