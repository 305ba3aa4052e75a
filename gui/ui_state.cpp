#include "gui/ui_state.hpp"

#include "formats/input_error.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdlib>

namespace impulse::gui {

void refresh_mask(const model::Session& session, UiState& state) {
    if (!state.lesson) {
        state.mask = course::Mask();
        return;
    }
    LessonState& l = *state.lesson;
    if (l.reaches_revision != session.revision()) {
        l.reaches = course::question_reaches(l.run.lesson(), session.trace());
        l.reaches_revision = session.revision();
    }
    state.mask = course::Mask(l.reaches, l.run.open(), session.trace());
    ++state.mask_revision;
}

void refresh_views(const model::Session& session, UiState& state) {
    CursorViews& v = state.views;
    const std::optional<model::Cursor>& cursor = session.cursor();
    if (state.lesson && state.lesson->reaches_revision != session.revision()) refresh_mask(session, state);
    if (v.revision == session.revision() && v.cursor == cursor) return;
    const Trace& trace = session.trace();
    if (v.revision != session.revision()) v.frame = -1;
    v.revision = session.revision();
    v.cursor = cursor;
    v.scroll_to_cursor = true;
    v.hidden_rows.clear();  // another item's rows: nothing to reveal
    if (!cursor) {
        v = CursorViews{};
        v.revision = session.revision();
        return;
    }
    v.derivation = model::derivation_view(trace, *cursor);
    v.contacts = model::contact_rows(trace, *cursor);
    v.bodies = model::bodies_at(trace, *cursor);
    v.steps = model::step_tables(trace, *cursor);
    if (v.frame != cursor->frame) {
        v.frame = cursor->frame;
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(cursor->frame)];
        v.curves = model::phase_curves(frame);
        v.largest_impulse = 0.0;
        for (const VelocityIteration& it : frame.velocity.iterations)
            if (it.resolution)
                v.largest_impulse = std::max(v.largest_impulse, it.resolution->impulse_terms.impulse_world.norm());
    }
}

void go_to_lesson_step(model::Session& session, UiState& state, int step) {
    LessonState& l = *state.lesson;
    l.run.go_to(step);
    if (l.preview) {
        l.run.answered_before(l.run.step());
        refresh_mask(session, state);
    }
    // The answer last given to this step's question is shown again in its field or as its option.
    l.typed.fill('\0');
    l.chosen = -1;
    const std::string& given = l.run.given(l.run.step());
    if (const auto& q = l.run.current().question; q && !given.empty()) {
        if (q->kind == course::Question::Kind::predict)
            given.copy(l.typed.data(), std::min(given.size(), l.typed.size() - 1));
        else if (const int option = std::atoi(given.c_str());
                 option >= 1 && option <= static_cast<int>(q->options.size()))
            l.chosen = option - 1;
    }
    l.focus_answer = true;
    // The step's place in this trace: the lesson's own run, or the same place in a re-run with other settings.
    const course::Step& s = l.run.current();
    try {
        session.move_to(model::resolve_goto(session.trace(), model::parse_goto(s.at, "at"), "at"));
    } catch (const formats::InputError& e) {
        state.message = "this step's place (" + s.at + ") is not in the re-run: " + e.problem();
        state.message_is_error = true;
    }
    if (!l.run.save_problem().empty()) state.message = l.run.save_problem(), state.message_is_error = true;
    // Two steps may stand on the same place: the step's rows come into view all the same.
    state.views.scroll_to_cursor = true;
}

void act(model::Session& session, UiState& state, const model::Action& action, model::ActionHost& host) {
    try {
        model::perform(session, action, "", &host);
        if (action.kind == model::ActionKind::export_trace || action.kind == model::ActionKind::export_table ||
            action.kind == model::ActionKind::screenshot)
            state.message = "written to " + action.argument, state.message_is_error = false;
        else if (action.kind == model::ActionKind::set)
            state.message = model::rerun_text(session, action.argument, &state.message_is_error);
        else
            state.message.clear();
    } catch (const formats::InputError& e) {
        state.message = e.problem();
        state.message_is_error = true;
    }
}

void record_control(std::vector<LaidOutItem>& controls, const std::string& what) {
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    controls.push_back({what, min.x, min.y, max.x, max.y, pos.x, pos.y, pos.x + size.x, pos.y + size.y, false});
}

void record_control(UiState& state, const std::string& what) {
    if (state.record_layout) record_control(state.controls, what);
}

void record_item(UiState& state, const char* what, bool scrolls) {
    if (!state.record_layout) return;
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    state.layout.push_back({what, min.x, min.y, max.x, max.y, pos.x, pos.y, pos.x + size.x, pos.y + size.y, scrolls});
}

}  // namespace impulse::gui
