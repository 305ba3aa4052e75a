// The settings a student changes to see what they do, and the exports. A change is an action like
// `set NAME VALUE` in a script: the scene runs again and the cursor stays on the same contact and step.

#include "explain/format.hpp"
#include "gui/panels.hpp"
#include "formats/atomic_file.hpp"
#include "formats/input_error.hpp"
#include "model/derivation_view.hpp"
#include "formats/settings_names.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

namespace impulse::gui {

namespace {

// A field's label: beside it when the panel is wide, else on its own line above a field as wide as the panel, so
// no name ("restitution cut-off") and no value ("positions_first") is cut at the panel's edge. Returns the
// widget's own label.
std::string labelled(const char* label) {
    const float width = ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
    if (width >= 380.0f) return label;
    ImGui::TextUnformatted(label);
    ImGui::SetNextItemWidth(-1.0f);
    return std::string("##") + label;
}

void set(model::Session& session, UiState& state, model::ActionHost& host, const std::string& name,
         const std::string& value) {
    act(session, state, model::Action{model::ActionKind::set, name + "=" + value}, host);
}

template <typename Enum, std::size_t N>
void enum_combo(model::Session& session, UiState& state, model::ActionHost& host, const char* label,
                const std::string& name, const formats::NameTable<Enum, N>& names, Enum current) {
    const std::string shown(formats::name_of(names, current));
    if (!ImGui::BeginCombo(labelled(label).c_str(), shown.c_str())) return;
    for (const auto& [value, text] : names)
        if (ImGui::Selectable(std::string(text).c_str(), value == current) && value != current)
            set(session, state, host, name, std::string(text));
    ImGui::EndCombo();
}

// A number applied when Enter is pressed, so typing does not re-run the scene at every key.
void number_field(model::Session& session, UiState& state, model::ActionHost& host, const char* label,
                  const std::string& name, double current) {
    double value = current;
    if (ImGui::InputDouble(labelled(label).c_str(), &value, 0.0, 0.0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue) &&
        value != current) {
        char text[64];
        std::snprintf(text, sizeof text, "%.17g", value);
        set(session, state, host, name, text);
    }
}

void integer_field(model::Session& session, UiState& state, model::ActionHost& host, const char* label,
                   const std::string& name, int current) {
    int value = current;
    if (ImGui::InputInt(labelled(label).c_str(), &value, 1, 10, ImGuiInputTextFlags_EnterReturnsTrue) &&
        value != current)
        set(session, state, host, name, std::to_string(value));
}

void bool_field(model::Session& session, UiState& state, model::ActionHost& host, const char* label,
                const std::string& name, bool current) {
    bool value = current;
    if (ImGui::Checkbox(label, &value)) set(session, state, host, name, value ? "true" : "false");
}

// The widget of each setting a method may read (methods/method_table.hpp lists which), in the order shown.
void method_setting(model::Session& session, UiState& state, model::ActionHost& host, std::string_view key,
                    const ResolverSettings& s) {
    const std::string name(key);
    if (key == "position_epsilon") number_field(session, state, host, "position ε (m)", name, s.position_epsilon);
    if (key == "velocity_epsilon") number_field(session, state, host, "velocity ε (m/s)", name, s.velocity_epsilon);
    if (key == "iterations_per_contact")
        integer_field(session, state, host, "iterations/contact", name, s.iterations_per_contact);
    if (key == "worst_first_search")
        enum_combo(session, state, host, "worst-first search", name, formats::worst_first_search_names,
                   s.worst_first_search);
    if (key == "sliding_friction")
        enum_combo(session, state, host, "sliding friction", name, formats::sliding_friction_names, s.sliding_friction);
    if (key == "angular_limit.policy")
        enum_combo(session, state, host, "angular limit", name, formats::angular_limit_policy_names,
                   s.angular_limit.policy);
    if (key == "angular_limit.factor") number_field(session, state, host, "limit factor", name, s.angular_limit.factor);
    if (key == "relaxation.fraction")
        number_field(session, state, host, "relaxation fraction", name, s.relaxation.fraction);
    if (key == "relaxation.passes") integer_field(session, state, host, "relaxation passes", name, s.relaxation.passes);
    if (key == "sweeps") integer_field(session, state, host, "sweeps", name, s.sweeps);
    if (key == "warm_start") bool_field(session, state, host, "warm start", name, s.warm_start);
    if (key == "soft_step.substeps") integer_field(session, state, host, "sub-steps", name, s.soft_step.substeps);
    if (key == "soft_step.contact_hertz")
        number_field(session, state, host, "contact hertz", name, s.soft_step.contact_hertz);
    if (key == "soft_step.damping_ratio")
        number_field(session, state, host, "damping ratio", name, s.soft_step.damping_ratio);
    if (key == "soft_step.order")
        enum_combo(session, state, host, "solve order", name, formats::solve_order_names, s.soft_step.order);
    if (key == "avbd.iterations") integer_field(session, state, host, "iterations", name, s.avbd.iterations);
    if (key == "avbd.alpha") number_field(session, state, host, "stabilisation α", name, s.avbd.alpha);
    if (key == "avbd.beta") number_field(session, state, host, "stiffness ramp β (N/m² per kg)", name, s.avbd.beta);
    if (key == "avbd.gamma") number_field(session, state, host, "warm-start decay γ", name, s.avbd.gamma);
    if (key == "avbd.stiffness_min")
        number_field(session, state, host, "stiffness min (N/m per kg)", name, s.avbd.stiffness_min);
    if (key == "avbd.stiffness_max")
        number_field(session, state, host, "stiffness max (N/m per kg)", name, s.avbd.stiffness_max);
    if (key == "avbd.slop") number_field(session, state, host, "slop (m)", name, s.avbd.slop);
    if (key == "avbd.post_stabilize") bool_field(session, state, host, "post-stabilise", name, s.avbd.post_stabilize);
    if (key == "baumgarte") bool_field(session, state, host, "Baumgarte bias (step 5)", name, s.baumgarte);
    if (key == "position_bias.factor")
        number_field(session, state, host, "bias factor β", name, s.position_bias.factor);
    if (key == "position_bias.slop") number_field(session, state, host, "slop (m)", name, s.position_bias.slop);
}

}  // namespace

void draw_settings(model::Session& session, UiState& state, model::ActionHost& host) {
    const ResolverSettings s = session.settings();  // a copy: a change re-runs and replaces the trace
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    if (ImGui::BeginCombo(labelled("preset").c_str(), s.preset.c_str())) {
        for (std::string_view name : preset_names())
            if (ImGui::Selectable(std::string(name).c_str(), name == s.preset))
                set(session, state, host, "preset", std::string(name));
        ImGui::EndCombo();
    }
    enum_combo(session, state, host, "phase order", "phase_order", formats::phase_order_names, s.phase_order);
    enum_combo(session, state, host, "velocity method", "velocity_method", formats::velocity_method_names,
               s.velocity_method);
    // A velocity method that owns the whole step runs no position phase: the choice is kept but not used.
    const bool owns_step = method_row(s.velocity_method).scope == MethodScope::whole_step;
    if (owns_step) ImGui::BeginDisabled();
    enum_combo(session, state, host, "position method", "position_method", formats::position_method_names,
               s.position_method);
    if (owns_step) ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", std::string(method_row(position_method_in_effect(s)).description).c_str());
    // Each method's own settings, shown only where the methods that run read them; the Baumgarte bias's
    // factor and slop only when it is on (or the split impulse pushes with them).
    constexpr std::string_view shown[] = {"position_epsilon",
                                          "velocity_epsilon",
                                          "iterations_per_contact",
                                          "worst_first_search",
                                          "sliding_friction",
                                          "angular_limit.policy",
                                          "angular_limit.factor",
                                          "relaxation.fraction",
                                          "relaxation.passes",
                                          "sweeps",
                                          "warm_start",
                                          "soft_step.substeps",
                                          "soft_step.contact_hertz",
                                          "soft_step.damping_ratio",
                                          "soft_step.order",
                                          "avbd.iterations",
                                          "avbd.post_stabilize",
                                          "avbd.alpha",
                                          "avbd.beta",
                                          "avbd.gamma",
                                          "avbd.stiffness_min",
                                          "avbd.stiffness_max",
                                          "avbd.slop",
                                          "baumgarte",
                                          "position_bias.factor",
                                          "position_bias.slop"};
    // The bias's factor and slop matter to a velocity method only through step 5's Baumgarte term: shown when it
    // is on, or when the position method pushes with them.
    const auto& position_reads = method_row(position_method_in_effect(s)).reads;
    const bool position_biased =
        std::find(position_reads.begin(), position_reads.end(), "position_bias.factor") != position_reads.end();
    for (const std::string_view key : shown) {
        if (!reads_setting(s, key)) continue;
        if (key.starts_with("position_bias.") && !s.baumgarte && !position_biased) continue;
        method_setting(session, state, host, key, s);
    }
    // Contact recycling is the world's detection, not a method's: any method may use it (its angle once it is on).
    number_field(session, state, host, "recycle distance (m)", "recycling.distance", s.recycling.distance);
    if (s.recycling.on()) number_field(session, state, host, "recycle angle (°)", "recycling.angle", s.recycling.angle);
    // Also detection's: two boxes' face contact keeps its points up to this far apart (speculative to the soft step).
    number_field(session, state, host, "speculative margin (m)", "speculative_margin", s.speculative_margin);
    number_field(session, state, host, "restitution cut-off", "restitution_cutoff", s.restitution_cutoff);
    bool from_acceleration = s.velocity_from_acceleration;
    if (ImGui::Checkbox("velocity from acceleration", &from_acceleration))
        set(session, state, host, "velocity_from_acceleration", from_acceleration ? "true" : "false");
    enum_combo(session, state, host, "orientation update", "orientation_update", formats::orientation_update_names,
               s.orientation_update);
    ImGui::PopItemWidth();
    ImGui::TextDisabled("A change re-runs %s.", session.kind() == model::SourceKind::scene_file  ? "the scene"
                                                : session.kind() == model::SourceKind::case_file ? "the case"
                                                                                                 : "the trace's scene");
}

// The table at the cursor as CSV with what a lesson's open questions hide as "?", like the window shows it.
std::string masked_table(const model::Session& session, const UiState& state) {
    if (!session.cursor()) throw formats::InputError("export table", "the trace records nothing to show");
    model::DerivationView view = model::derivation_view(session.trace(), *session.cursor());
    for (model::ViewRow& r : view.rows) {
        if (state.mask.hides_row(*session.cursor(), r.row)) r.row.value = r.row.exact = "?";
        if (state.mask.other_frame_hidden_by(*session.cursor(), r.row) && !r.row.other_frame.empty())
            r.row.other_frame = "?";
    }
    return model::derivation_csv(view);
}

void draw_export(model::Session& session, UiState& state, model::ActionHost& host) {
    using model::ActionKind;
    struct Row {
        const char* button;
        ActionKind kind;
        std::array<char, 512>* path;
    };
    const Row rows[] = {{"Export trace", ActionKind::export_trace, &state.trace_path},
                        {"Export table", ActionKind::export_table, &state.table_path},
                        {"Screenshot", ActionKind::screenshot, &state.screenshot_path}};
    // A copy is a reading too: with a lesson's question open the trace (every answer) waits, and the table is
    // written as shown.
    const bool secrets = !state.mask.empty();
    for (const Row& r : rows) {
        ImGui::PushID(r.button);
        const bool withheld = secrets && r.kind == ActionKind::export_trace;
        ImGui::BeginDisabled(withheld);
        const bool pressed = ImGui::Button(r.button, ImVec2(110, 0));
        record_control(state, std::string("button ") + r.button);
        if (pressed) {
            if (secrets && r.kind == ActionKind::export_table) {
                try {
                    formats::write_file_atomically(r.path->data(), masked_table(session, state), r.path->data());
                    host.written(r.path->data());  // a browser offers it as a download
                    state.message = "written to " + std::string(r.path->data()), state.message_is_error = false;
                } catch (const formats::InputError& e) {
                    state.message = e.problem(), state.message_is_error = true;
                }
            } else {
                act(session, state, {r.kind, std::string(r.path->data())}, host);
            }
        }
        ImGui::EndDisabled();
        if (withheld && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip(
                "The trace holds every answer: it can be exported once the lesson's questions are "
                "answered or skipped.");
        ImGui::SameLine();
        ImGui::SetNextItemWidth(-1);
        ImGui::InputText("##path", r.path->data(), r.path->size());
        ImGui::PopID();
    }
}

}  // namespace impulse::gui
