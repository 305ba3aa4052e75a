#include "course/item_labels.hpp"

#include "explain/derivation_table.hpp"
#include "explain/format.hpp"

namespace impulse::course {

using model::Cursor;
using model::Stage;

std::string stage_label(const FrameRecord& frame, Stage stage) {
    const int n = model::item_count(frame, stage);
    if (stage == Stage::preparation) return "Preparation: " + std::to_string(n) + (n == 1 ? " contact" : " contacts");
    const PhaseOutcome& o = stage == Stage::position ? frame.position.outcome : frame.velocity.outcome;
    return std::string(stage == Stage::position ? "Position phase: " : "Velocity phase: ") + std::to_string(n) +
           " of " + std::to_string(o.iteration_limit) + " iterations";
}

std::string item_label(const Trace& trace, const Mask& mask, int f, Stage stage, int item) {
    const FrameRecord& frame = trace.frames[static_cast<std::size_t>(f)];
    const auto i = static_cast<std::size_t>(item);
    const Cursor at{f, stage, item, 0};
    if (stage == Stage::preparation) {
        const ContactPreparation& c = frame.contacts[i];
        if (mask.hides_bodies_of(f, c.contact)) return "contact " + std::to_string(c.contact) + " · ? / ?";
        return "contact " + std::to_string(c.contact) + " · " + model::body_label(trace, c.bodies[0]) + " / " +
               model::body_label(trace, c.bodies[1]);
    }
    if (stage == Stage::position) {
        const PositionIteration& it = frame.position.iterations[i];
        const bool secret = mask.hides_value(at, it.contact, "penetration", it.penetration);
        return "iteration " + std::to_string(it.iteration) + " → contact " + std::to_string(it.contact) +
               (secret ? "" : " (" + explain::number(it.penetration) + " m)");
    }
    const VelocityIteration& it = frame.velocity.iterations[i];
    // AVBD: a sweep over the bodies, each visit a body with the contacts it gathered, then the contacts' dual update.
    if (const auto& v = it.body_visit) {
        const std::size_t n = v->gathered.size();
        return explain::sweep_text(*it.sweep, trace.scene.settings) + " → body " + std::to_string(v->body) + " (" +
               std::to_string(n) + (n == 1 ? " contact)" : " contacts)");
    }
    if (it.sweep && it.sweep->stage == SolverStage::dual)
        return explain::sweep_text(*it.sweep, trace.scene.settings) + " → contact " + std::to_string(it.contact);
    const bool secret = mask.hides_value(at, it.contact, "desired_delta_velocity", it.desired_delta_velocity);
    const std::string value = secret ? "" : " (Δv " + explain::number(it.desired_delta_velocity) + " m/s)";
    if (it.sweep)
        return explain::sweep_text(*it.sweep, trace.scene.settings) + " → contact " + std::to_string(it.contact) +
               value;
    return "iteration " + std::to_string(it.iteration) + " → contact " + std::to_string(it.contact) + value;
}

}  // namespace impulse::course
