#pragma once
// The inspector's panels, each drawn into the current ImGui window by one function. The layout
// (inspector_window.cpp) places them; all of them read `state.views`, rebuilt once per cursor move.

#include "gui/ui_state.hpp"

namespace impulse::gui {

// Buttons for every move, the location, the status message; and, without a lesson, the keys: ←/→ step,
// ↑/↓ item, PgUp/PgDn phase, Home/End first/last.
void draw_toolbar(model::Session& session, UiState& state, model::ActionHost& host);
// Frame → phase → iteration or contact, and the current item's derivation steps.
void draw_navigator(model::Session& session, UiState& state);
// The derivation table at the cursor: quantity, value, other frame, formula, equation, meaning.
void draw_derivation(const model::Session& session, UiState& state);
// The bodies, contacts, normals, impulses and penetrations, in a chosen plane or a rotatable view.
void draw_scene_view(const model::Session& session, UiState& state);
// Every contact with its bookkeeping and status; clicking one goes to it.
void draw_contacts(model::Session& session, UiState& state);
// Each body before and after the cursor's item.
void draw_bodies(const model::Session& session, UiState& state);
// The worst value against iteration, per phase, with the epsilon and the cursor marked.
void draw_plots(const model::Session& session, UiState& state);
// Preset, methods, limit policy, epsilons, iteration limits: a change re-runs the scene.
void draw_settings(model::Session& session, UiState& state, model::ActionHost& host);
// Trace JSON, table CSV and screenshot PNG to the paths typed in.
void draw_export(model::Session& session, UiState& state, model::ActionHost& host);

// The open lesson's step: its text, its question, back and next; and the keys while a lesson is open:
// →/PgDn/Enter next, ←/PgUp back, Enter checks, Tab/↑/↓ between options, Esc closes the window.
void draw_lesson(model::Session& session, UiState& state);

// The whole window: every panel in its place for the current display size.
void draw_inspector(model::Session& session, UiState& state, model::ActionHost& host);

}  // namespace impulse::gui
