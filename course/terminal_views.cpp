#include "course/terminal_views.hpp"

#include "course/item_labels.hpp"
#include "explain/format.hpp"
#include "explain/text_table.hpp"
#include "model/replay.hpp"

#include <algorithm>

namespace impulse::course {

namespace {

using model::Cursor;
using model::Stage;

std::string change_text(const Vec3& before, const Vec3& after) {
    return before == after ? explain::vector(after) : explain::vector(before) + " → " + explain::vector(after);
}

// `label` then `text` wrapped under itself.
void write_wrapped(std::ostream& out, const std::string& label, const std::string& text, int width) {
    const std::size_t column = explain::display_width(label);
    const std::size_t room = static_cast<std::size_t>(std::max(width, 40)) > column + 10
                                 ? static_cast<std::size_t>(std::max(width, 40)) - column
                                 : 10;
    const std::vector<std::string> lines = explain::wrap_words(text, room);
    for (std::size_t i = 0; i < lines.size(); ++i)
        out << (i == 0 ? label : std::string(column, ' ')) << lines[i] << '\n';
}

}  // namespace

std::string hidden_until(const Lesson& lesson, int step, int current) {
    if (step == current) return "? (hidden until you answer this step's question)";
    return "? (hidden until you answer step " + std::to_string(step + 1) + " · " +
           lesson.steps[static_cast<std::size_t>(step)].id + ")";
}

void write_bodies(std::ostream& out, const Trace& trace, const Cursor& at, const Mask& mask, int width) {
    const model::BodiesAtCursor bodies = model::bodies_at(trace, at);
    write_wrapped(out, "", "Bodies before → after this item (" + model::describe(trace, at) + ")", width);
    if (!bodies.exact) out << "  (frame start and end only: the recording's contact filter left out a move)\n";
    for (std::size_t b = 0; b < bodies.after.size(); ++b) {
        const int body = static_cast<int>(b);
        HiddenBy by = mask.body_hidden_by(at, body, false, bodies.before[b]);
        const bool hide_before = by.has_value();
        if (!by) by = mask.body_hidden_by(at, body, true, bodies.after[b]);
        const BodyState& before = bodies.before[b];
        const BodyState& after = by ? before : bodies.after[b];
        const bool moved = std::find(bodies.moved.begin(), bodies.moved.end(), body) != bodies.moved.end() && !by;
        out << "  " << trace.scene.body_names[b] << (moved ? " (moved by this item)" : "") << '\n';
        if (hide_before) {
            out << "    "
                << "? (hidden until you answer step " << *by + 1 << ")\n";
            continue;
        }
        const std::string until = by ? " → ? (hidden until you answer step " + std::to_string(*by + 1) + ")" : "";
        write_wrapped(out, "    position m     ", change_text(before.position, after.position) + until, width);
        write_wrapped(out, "    velocity m/s   ", change_text(before.velocity, after.velocity) + until, width);
        write_wrapped(out, "    ω rad/s        ", change_text(before.angular_velocity, after.angular_velocity) + until,
                      width);
    }
}

void write_contacts(std::ostream& out, const Trace& trace, const Cursor& at, const Mask& mask) {
    const int current = model::contact_at(trace, at);
    out << "Contacts before this item, status in the "
        << (at.stage == Stage::velocity   ? "velocity"
            : at.stage == Stage::position ? "position"
                                          : "first")
        << " phase (▶ this item's)\n";
    std::vector<std::vector<std::string>> rows{{"  #", "bodies", "pen. m", "Δv m/s", "|g| N·s", "status"}};
    for (const model::ContactRow& row : model::contact_rows(trace, at)) {
        const auto cell = [&](std::string_view key, double value, double scale) {
            return mask.hides_value(at, row.contact, key, value) ? std::string("?") : explain::number(value, scale);
        };
        const double desired = row.prepared->desired_terms.desired_delta_velocity;
        rows.push_back(
            {(row.contact == current ? "▶ " : "  ") + std::to_string(row.contact),
             mask.hides_bodies_of(at.frame, row.contact) ? std::string("? / ?")
                                                         : model::body_label(trace, row.prepared->bodies[0]) + " / " +
                                                               model::body_label(trace, row.prepared->bodies[1]),
             cell("penetration", row.penetration,
                  std::max(std::abs(row.prepared->penetration), std::abs(row.penetration))),
             cell("desired_delta_velocity", row.desired_delta_velocity,
                  std::max(std::abs(desired), std::abs(row.desired_delta_velocity))),
             cell("impulse_world", row.impulse_so_far.norm(), 0.0), std::string(model::status_name(row.status))});
    }
    out << explain::aligned_columns(rows);
}

void write_order(std::ostream& out, const Trace& trace, const Cursor& at, const Mask& mask, int width, int around) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(at.frame)];
    out << "Frame " << frame.frame << " in the order it ran (▶ this item)\n";
    for (const Stage stage : model::stages(frame)) {
        out << "  " << stage_label(frame, stage) << '\n';
        const int count = model::item_count(frame, stage);
        const int centre = at.stage == stage ? at.item : 0;
        const int from = std::max(0, centre - around), to = std::min(count, centre + around + 1);
        if (from > 0) out << "      … " << from << " before\n";
        for (int i = from; i < to; ++i)
            write_wrapped(out, at.stage == stage && at.item == i ? "    ▶ " : "      ",
                          item_label(trace, mask, at.frame, stage, i), width);
        if (to < count) out << "      … " << count - to << " more\n";
    }
}

}  // namespace impulse::course
