// The settings a student changes to see what they do, and the exports. A change is an action like
// `set NAME VALUE` in a script: the scene runs again and the cursor stays on the same contact and step.

#include "explain/format.hpp"
#include "gui/panels.hpp"
#include "resolver/settings_names.hpp"

#include <imgui.h>

#include <cstdio>

namespace impulse::gui {

namespace {

void set(inspect::Session& session, UiState& state, inspect::ActionHost& host, const std::string& name,
         const std::string& value) {
    act(session, state, inspect::Action{inspect::ActionKind::set, name + "=" + value}, host);
}

template <typename Enum, std::size_t N>
void enum_combo(inspect::Session& session, UiState& state, inspect::ActionHost& host, const char* label,
                const std::string& name, const NameTable<Enum, N>& names, Enum current) {
    const std::string shown(name_of(names, current));
    if (!ImGui::BeginCombo(label, shown.c_str())) return;
    for (const auto& [value, text] : names)
        if (ImGui::Selectable(std::string(text).c_str(), value == current) && value != current)
            set(session, state, host, name, std::string(text));
    ImGui::EndCombo();
}

// A number applied when Enter is pressed, so typing does not re-run the scene at every key.
void number_field(inspect::Session& session, UiState& state, inspect::ActionHost& host, const char* label,
                  const std::string& name, double current) {
    double value = current;
    if (ImGui::InputDouble(label, &value, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) && value != current) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", value);
        set(session, state, host, name, text);
    }
}

void integer_field(inspect::Session& session, UiState& state, inspect::ActionHost& host, const char* label,
                   const std::string& name, int current) {
    int value = current;
    if (ImGui::InputInt(label, &value, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) && value != current)
        set(session, state, host, name, std::to_string(value));
}

}  // namespace

void draw_settings(inspect::Session& session, UiState& state, inspect::ActionHost& host) {
    const ResolverSettings s = session.settings();  // a copy: a change re-runs and replaces the trace
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::BeginCombo("preset", s.preset.c_str())) {
        for (std::string_view name : preset_names())
            if (ImGui::Selectable(std::string(name).c_str(), name == s.preset))
                set(session, state, host, "preset", std::string(name));
        ImGui::EndCombo();
    }
    enum_combo(session, state, host, "phase order", "phase_order", phase_order_names, s.phase_order);
    enum_combo(session, state, host, "position method", "position_method", position_method_names, s.position_method);
    enum_combo(session, state, host, "velocity method", "velocity_method", velocity_method_names, s.velocity_method);
    enum_combo(session, state, host, "angular limit", "angular_limit.policy", angular_limit_policy_names,
               s.angular_limit.policy);
    number_field(session, state, host, "limit factor", "angular_limit.factor", s.angular_limit.factor);
    number_field(session, state, host, "position ε (m)", "position_epsilon", s.position_epsilon);
    number_field(session, state, host, "velocity ε (m/s)", "velocity_epsilon", s.velocity_epsilon);
    // Each method's own knobs, shown only where they apply.
    const VelocityMethod v = s.velocity_method;
    if (v == VelocityMethod::worst_first) {
        integer_field(session, state, host, "iterations/contact", "iterations_per_contact", s.iterations.per_contact);
        enum_combo(session, state, host, "worst-first search", "worst_first_search", worst_first_search_names,
                   s.worst_first_search);
    } else if (v == VelocityMethod::soft_step) {
        integer_field(session, state, host, "sub-steps", "soft_step.substeps", s.soft_step.substeps);
        number_field(session, state, host, "contact hertz", "soft_step.contact_hertz", s.soft_step.contact_hertz);
        number_field(session, state, host, "damping ratio", "soft_step.damping_ratio", s.soft_step.damping_ratio);
    }
    if (v != VelocityMethod::worst_first || s.position_method == PositionMethod::split_impulse)
        integer_field(session, state, host, "sweeps", "sweeps", s.sweeps);
    if (v == VelocityMethod::projected_gauss_seidel || v == VelocityMethod::soft_step) {
        bool warm = s.warm_start;
        if (ImGui::Checkbox("warm start", &warm)) set(session, state, host, "warm_start", warm ? "true" : "false");
    }
    const bool biased =
        s.position_method == PositionMethod::baumgarte || s.position_method == PositionMethod::split_impulse;
    if (biased && v != VelocityMethod::soft_step) {  // the soft contact carries its own push
        number_field(session, state, host, "bias factor β", "position_bias.factor", s.position_bias.factor);
        number_field(session, state, host, "slop (m)", "position_bias.slop", s.position_bias.slop);
    }
    if (s.position_method == PositionMethod::relaxation) {
        number_field(session, state, host, "relaxation fraction", "relaxation.fraction", s.relaxation.fraction);
        integer_field(session, state, host, "relaxation passes", "relaxation.passes", s.relaxation.passes);
    }
    number_field(session, state, host, "restitution cut-off", "restitution_cutoff", s.refinements.restitution_cutoff);
    bool from_acceleration = s.refinements.velocity_from_acceleration;
    if (ImGui::Checkbox("velocity from acceleration", &from_acceleration))
        set(session, state, host, "velocity_from_acceleration", from_acceleration ? "true" : "false");
    enum_combo(session, state, host, "orientation update", "orientation_update", orientation_update_names,
               s.orientation_update);
    ImGui::PopItemWidth();
    ImGui::TextDisabled("A change re-runs %s.", session.kind() == inspect::SourceKind::scene_file ? "the scene"
                                                : session.kind() == inspect::SourceKind::case_file
                                                    ? "the case"
                                                    : "the trace's scene");
}

void draw_export(inspect::Session& session, UiState& state, inspect::ActionHost& host) {
    using inspect::ActionKind;
    struct Row {
        const char* button;
        ActionKind kind;
        std::array<char, 512>* path;
    };
    const Row rows[] = {{"Export trace", ActionKind::export_trace, &state.trace_path},
                        {"Export table", ActionKind::export_table, &state.table_path},
                        {"Screenshot", ActionKind::screenshot, &state.screenshot_path}};
    for (const Row& r : rows) {
        ImGui::PushID(r.button);
        if (ImGui::Button(r.button, ImVec2(110, 0))) act(session, state, {r.kind, std::string(r.path->data())}, host);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        ImGui::InputText("##path", r.path->data(), r.path->size());
        ImGui::PopID();
    }
}

}  // namespace impulse::gui
