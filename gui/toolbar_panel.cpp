#include "gui/keys.hpp"
#include "gui/panels.hpp"

#include <filesystem>
#include <imgui.h>

namespace impulse::gui {

namespace {

using model::Action;
using model::ActionKind;

struct Button {
    const char* label;
    ActionKind kind;
    const char* tip;
};

constexpr Button buttons[] = {
    {"|◀ First", ActionKind::first, "The first step of the trace (Home)"},
    {"◀◀ Phase", ActionKind::previous_phase, "The start of this phase, or the previous phase (Page Up)"},
    {"◀ Iteration", ActionKind::previous_iteration, "The previous iteration (↑ moves by item: iteration or contact)"},
    {"◀ Contact", ActionKind::previous_contact, "The previous contact"},
    {"◀ Step", ActionKind::previous_step, "The previous derivation step (←; with a lesson open, this button)"},
    {"Step ▶", ActionKind::next_step, "The next derivation step (→; with a lesson open, this button)"},
    {"Contact ▶", ActionKind::next_contact, "The next contact (in a phase: the next iteration on another contact)"},
    {"Iteration ▶", ActionKind::next_iteration, "The next iteration (↓ moves by item: iteration or contact)"},
    {"Phase ▶▶", ActionKind::next_phase, "The next phase (Page Down)"},
    {"Last ▶|", ActionKind::last, "The last step of the trace (End)"},
};

// The move a navigation key makes; count 0 for any other key.
Action key_action(int scancode) {
    struct Key {
        int code;
        ActionKind kind;
    };
    constexpr Key keys[] = {
        {key::right, ActionKind::next_step},      {key::left, ActionKind::previous_step},
        {key::down, ActionKind::next_item},       {key::up, ActionKind::previous_item},
        {key::page_down, ActionKind::next_phase}, {key::page_up, ActionKind::previous_phase},
        {key::home, ActionKind::first},           {key::end, ActionKind::last},
    };
    for (const Key& k : keys)
        if (scancode == k.code) return {k.kind};
    return {ActionKind::quit, {}, 0};
}

}  // namespace

void draw_toolbar(model::Session& session, UiState& state, model::ActionHost& host) {
    for (const Button& b : buttons) {
        if (ImGui::Button(b.label)) act(session, state, Action{b.kind}, host);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", b.tip);
        ImGui::SameLine();
    }
    ImGui::NewLine();
    // Keys move the cursor unless the user is typing in a field (a setting, an export path). With a lesson
    // open the keys belong to the lesson (its panel reads them) and the inspector moves by its buttons.
    if (!state.lesson) {
        if (!ImGui::GetIO().WantTextInput)
            for (int key : state.pressed_keys)
                if (const Action pressed = key_action(key); pressed.count > 0) act(session, state, pressed, host);
        state.pressed_keys.clear();
    }
    const CursorViews& v = state.views;
    // A lesson's file is the lesson's, not the student's: the scene's name is enough.
    const std::string file = state.lesson ? std::filesystem::path(session.path()).filename().string() : session.path();
    ImGui::TextUnformatted(file.c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("·");
    ImGui::SameLine();
    if (v.cursor)
        ImGui::TextUnformatted(v.derivation.where.c_str());
    else
        ImGui::TextUnformatted("nothing recorded to step through");
    if (!state.message.empty()) {
        ImGui::SameLine(0.0f, 24.0f);
        ImGui::TextColored(state.message_is_error ? ImVec4(1.0f, 0.45f, 0.4f, 1.0f) : ImVec4(0.5f, 0.9f, 0.5f, 1.0f),
                           "%s", state.message.c_str());
    }
}

}  // namespace impulse::gui
