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

void go_to_lesson_step(inspect::Session& session, UiState& state, int step) {
    LessonState& l = *state.lesson;
    const int count = static_cast<int>(l.lesson->places.size());
    l.step = std::clamp(step, 0, count - 1);
    l.typed.fill('\0');
    session.move_to(l.lesson->places[static_cast<std::size_t>(l.step)]);
    if (l.progress && l.progress_file) {
        l.progress->lessons[l.lesson->lesson.name].last_step = l.step;
        try {
            lessons::save_progress(*l.progress_file, *l.progress);
        } catch (const io::InputError& e) {
            state.message = e.problem(), state.message_is_error = true;
        }
    }
}

std::string hidden_quantity(const UiState& state, const inspect::Session& session) {
    if (!state.lesson || !session.cursor()) return {};
    const LessonState& l = *state.lesson;
    const auto step = static_cast<std::size_t>(l.step);
    const lessons::Step& s = l.lesson->lesson.steps[step];
    // Hidden wherever the student looks until they answer: the same quantity also shows in later steps'
    // tables of the item and in the contacts list.
    if (!s.question || l.verdicts[step]) return {};
    return lessons::question_quantity(*s.question);
}

bool is_hidden_row(const std::string& hidden, const std::string& question_path, std::string_view quantity) {
    if (hidden.empty()) return false;
    // The rows that show the asked value: its key (both bodies' rows of a per-body one), the last key of a
    // nested path (friction_solve.cone_limit is the row cone_limit; rewind.time the row rewind_time), and the
    // impulse in the other frame.
    std::vector<std::string> names{hidden};
    const std::size_t dot = question_path.rfind('.');
    if (dot != std::string::npos) {
        const std::string last = question_path.substr(dot + 1, question_path.find('[', dot) - dot - 1);
        names.push_back(last);
        names.push_back(hidden + "_" + last);
    }
    if (hidden == "impulse_contact") names.push_back("impulse_world");
    if (hidden == "impulse_world") names.push_back("impulse_contact");
    for (const std::string& name : names)
        if (quantity == name || quantity.starts_with(name + "[")) return true;
    return false;
}

void act(inspect::Session& session, UiState& state, const inspect::Action& action, inspect::ActionHost& host) {
    try {
        inspect::perform(session, action, "", &host);
        if (action.kind == inspect::ActionKind::export_trace || action.kind == inspect::ActionKind::export_table ||
            action.kind == inspect::ActionKind::screenshot)
            state.message = "written to " + action.argument, state.message_is_error = false;
        else if (action.kind == inspect::ActionKind::set)
            state.message = inspect::rerun_text(session, action.argument, &state.message_is_error);
        else
            state.message.clear();
    } catch (const io::InputError& e) {
        state.message = e.problem();
        state.message_is_error = true;
    }
}

}  // namespace impulse::gui
