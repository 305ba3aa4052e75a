#include "model/replay.hpp"

#include "math/rotation.hpp"

#include <algorithm>

namespace impulse::model {

namespace {

// Calls `visit(stage, iteration index)` for every iteration the frame ran before the cursor's item, in the
// order they ran.
template <typename Visit>
void for_each_iteration_before(const FrameRecord& frame, const Cursor& cursor, Visit visit) {
    if (cursor.stage == Stage::preparation) return;
    for (Stage stage : stages(frame)) {
        if (stage == Stage::preparation) continue;
        const int end = stage == cursor.stage ? cursor.item : item_count(frame, stage);
        for (int i = 0; i < end; ++i) visit(stage, static_cast<std::size_t>(i));
        if (stage == cursor.stage) return;
    }
}

// Row index of a contact in the frame's recorded list, or -1.
int row_of(const FrameRecord& frame, int contact) {
    const ContactPreparation* p = preparation_of(frame, contact);
    return p ? static_cast<int>(p - frame.contacts.data()) : -1;
}

// Applies a recorded move or impulse to the bodies; false when its derivation was not recorded.
bool apply_iteration(const FrameRecord& frame, Stage stage, std::size_t i, OrientationUpdate orientation_update,
                     std::vector<BodyState>& bodies, std::vector<int>* moved) {
    if (stage == Stage::position) {
        const PositionIteration& it = frame.position.iterations[i];
        const ContactPreparation* p = preparation_of(frame, it.contact);
        if (!it.resolution || !p) return false;
        for (int b = 0; b < 2; ++b) {
            if (p->bodies[b] == world_body) continue;
            BodyState& body = bodies[static_cast<std::size_t>(p->bodies[b])];
            // Exactly as the position phase applies it, so the replay reproduces the resolver's bits.
            body.position += *it.resolution->change.linear_change[b];
            body.orientation = rotated(body.orientation, *it.resolution->change.angular_change[b], orientation_update);
            if (moved) moved->push_back(p->bodies[b]);
        }
        return true;
    }
    const VelocityIteration& it = frame.velocity.iterations[i];
    const ContactPreparation* p = preparation_of(frame, it.contact);
    if (!it.resolution || !p) return false;
    for (int b = 0; b < 2; ++b) {
        if (p->bodies[b] == world_body) continue;
        BodyState& body = bodies[static_cast<std::size_t>(p->bodies[b])];
        body.velocity += *it.resolution->velocity_change_terms.velocity_change[b];
        body.angular_velocity += *it.resolution->velocity_change_terms.rotation_change[b];
        if (moved) moved->push_back(p->bodies[b]);
    }
    return true;
}

}  // namespace

std::string_view status_name(ContactStatus status) {
    switch (status) {
        case ContactStatus::chosen:
            return "chosen";
        case ContactStatus::waiting:
            return "waiting";
        case ContactStatus::below_epsilon:
            return "below ε";
    }
    return "";
}

std::vector<ContactRow> contact_rows(const Trace& trace, const Cursor& cursor) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(cursor.frame)];
    std::vector<ContactRow> rows;
    rows.reserve(frame.contacts.size());
    for (const ContactPreparation& p : frame.contacts)
        rows.push_back({p.contact, &p, p.penetration, p.desired_terms.desired_delta_velocity, ContactStatus::waiting,
                        Vec3::Zero()});

    for_each_iteration_before(frame, cursor, [&](Stage stage, std::size_t i) {
        if (stage == Stage::position) {
            for (const PenetrationUpdate& u : frame.position.iterations[i].updates)
                if (const int r = row_of(frame, u.contact); r >= 0)
                    rows[static_cast<std::size_t>(r)].penetration = u.after;
        } else {
            const VelocityIteration& it = frame.velocity.iterations[i];
            for (const VelocityUpdate& u : it.updates)
                if (const int r = row_of(frame, u.contact); r >= 0)
                    rows[static_cast<std::size_t>(r)].desired_delta_velocity = u.desired_delta_velocity_after;
            if (const int r = row_of(frame, it.contact); r >= 0 && it.resolution)
                rows[static_cast<std::size_t>(r)].impulse_so_far += it.resolution->impulse_terms.impulse_world;
        }
    });

    // Statuses belong to a phase: the cursor's, or in preparation the phase that runs first.
    Stage phase = cursor.stage;
    if (phase == Stage::preparation)
        phase = frame.phase_order == PhaseOrder::positions_first ? Stage::position : Stage::velocity;
    const ResolverSettings& s = trace.scene.settings;
    const int chosen = cursor.stage == Stage::preparation ? -1 : contact_at(trace, cursor);
    for (ContactRow& row : rows) {
        const double value = phase == Stage::position ? row.penetration : row.desired_delta_velocity;
        const double epsilon = phase == Stage::position ? s.position_epsilon : s.velocity_epsilon;
        row.status = row.contact == chosen ? ContactStatus::chosen
                     : value > epsilon     ? ContactStatus::waiting
                                           : ContactStatus::below_epsilon;
    }
    return rows;
}

BodiesAtCursor bodies_at(const Trace& trace, const Cursor& cursor) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(cursor.frame)];
    const OrientationUpdate update = trace.scene.settings.orientation_update;
    BodiesAtCursor result{frame.bodies_before, {}, {}, true};
    for_each_iteration_before(frame, cursor, [&](Stage stage, std::size_t i) {
        if (result.exact) result.exact = apply_iteration(frame, stage, i, update, result.before, nullptr);
    });
    if (!result.exact) {
        result.before = frame.bodies_before;
        result.after = frame.bodies_after;
        return result;
    }
    result.after = result.before;
    if (cursor.stage != Stage::preparation &&
        !apply_iteration(frame, cursor.stage, static_cast<std::size_t>(cursor.item), update, result.after,
                         &result.moved)) {
        result.exact = false;
        result.before = frame.bodies_before;
        result.after = frame.bodies_after;
        result.moved.clear();
    }
    return result;
}

std::vector<PhaseCurve> phase_curves(const FrameRecord& frame) {
    std::vector<PhaseCurve> curves;
    for (Stage stage : stages(frame)) {
        if (stage == Stage::position) {
            const PositionIteration& first = frame.position.iterations.front();
            PhaseCurve c{stage, {}, first.slop.value_or(first.epsilon)};
            for (const PositionIteration& it : frame.position.iterations) c.worst.push_back(it.penetration);
            curves.push_back(std::move(c));
        } else if (stage == Stage::velocity) {
            PhaseCurve c{stage, {}, frame.velocity.iterations.front().epsilon};
            for (const VelocityIteration& it : frame.velocity.iterations) c.worst.push_back(it.desired_delta_velocity);
            curves.push_back(std::move(c));
        }
    }
    return curves;
}

}  // namespace impulse::model
