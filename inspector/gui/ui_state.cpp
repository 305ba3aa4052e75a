#include "gui/ui_state.hpp"

#include "io/input_error.hpp"

#include <algorithm>

namespace impulse::gui {

void refresh_views(const inspect::Session& session, UiState& state) {
    CursorViews& v = state.views;
    const std::optional<inspect::Cursor>& cursor = session.cursor();
    if (v.revision == session.revision() && v.cursor == cursor) return;
    const Trace& trace = session.trace();
    if (v.revision != session.revision()) v.frame = -1;
    v.revision = session.revision();
    v.cursor = cursor;
    v.scroll_to_cursor = true;
    if (!cursor) {
        v = CursorViews{session.revision(), std::nullopt, {}, {}, {}, {}, -1, {}, 0.0, false};
        return;
    }
    v.derivation = inspect::derivation_view(trace, *cursor);
    v.contacts = inspect::contact_rows(trace, *cursor);
    v.bodies = inspect::bodies_at(trace, *cursor);
    v.steps = inspect::step_tables(trace, *cursor);
    if (v.frame != cursor->frame) {
        v.frame = cursor->frame;
        const FrameRecord& frame = trace.frames[static_cast<std::size_t>(cursor->frame)];
        v.curves = inspect::phase_curves(frame);
        v.largest_impulse = 0.0;
        for (const VelocityIteration& it : frame.velocity.iterations)
            if (it.resolution)
                v.largest_impulse = std::max(v.largest_impulse, it.resolution->impulse.impulse_world.norm());
    }
}

void act(inspect::Session& session, UiState& state, const inspect::Action& action, inspect::ActionHost& host) {
    try {
        inspect::perform(session, action, "", &host);
        if (action.kind == inspect::ActionKind::export_trace || action.kind == inspect::ActionKind::export_table ||
            action.kind == inspect::ActionKind::screenshot)
            state.message = "written to " + action.argument, state.message_is_error = false;
        else if (action.kind == inspect::ActionKind::set)
            state.message = "re-ran with " + action.argument, state.message_is_error = false;
        else
            state.message.clear();
    } catch (const io::InputError& e) {
        state.message = e.problem();
        state.message_is_error = true;
    }
}

}  // namespace impulse::gui
