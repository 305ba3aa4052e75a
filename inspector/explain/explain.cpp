#include "explain/explain.hpp"

#include "explain/format.hpp"
#include "explain/text_table.hpp"
#include "formats/settings_names.hpp"

#include <string>

namespace impulse::explain {

namespace {

std::string body_name(const Trace& trace, int body) {
    return body == world_body ? "the world" : trace.scene.body_names[static_cast<std::size_t>(body)];
}

std::string feature_text(const Feature& f) {
    switch (f.kind) {
        case FeatureKind::face:
            return "face " + std::to_string(f.index);
        case FeatureKind::edge:
            return "edge " + std::to_string(f.index);
        case FeatureKind::vertex:
            return "vertex " + std::to_string(f.index);
        case FeatureKind::sphere:
            return "its surface";
        case FeatureKind::plane:
            return "the ground plane";
        case FeatureKind::none:
            return "";
    }
    return "";
}

// "made by box_half_space: vertex 3 of body 0 against the ground plane"
std::string origin_text(const ContactOrigin& o) {
    if (o.test == CollisionTest::explicit_contact) return "written in the file";
    std::string text = "made by " + std::string(formats::name_of(formats::collision_test_names, o.test)) + ": " +
                       feature_text(o.features[0]) + " of body 0 against ";
    text += o.features[1].kind == FeatureKind::plane ? feature_text(o.features[1])
                                                     : feature_text(o.features[1]) + " of body 1";
    const bool box = o.features[0].index >= 0 || o.features[1].index >= 0;
    return box ? text + " (box features numbered as in docs/scenes.md)" : text;
}

std::string describe_settings(const ResolverSettings& s) {
    std::string text =
        "preset " + s.preset + ": " +
        (s.phase_order == PhaseOrder::positions_first ? "positions then velocities" : "velocities then positions") +
        ", " + std::string(formats::name_of(formats::position_method_names, position_method_in_effect(s))) +
        " (angular limit " + std::string(formats::name_of(formats::angular_limit_policy_names, s.angular_limit.policy));
    if (s.angular_limit.policy != AngularLimitPolicy::none) text += " " + number(s.angular_limit.factor);
    text += "), " + std::string(formats::name_of(formats::velocity_method_names, s.velocity_method)) +
            " velocities, ε " + number(s.position_epsilon) + " m / " + number(s.velocity_epsilon) + " m/s";
    return text;
}

std::string stop_text(const PhaseOutcome& o) {
    const std::string used =
        std::to_string(o.iterations_used) + " of " + std::to_string(o.iteration_limit) + " iterations";
    switch (o.stop) {
        case StopReason::resolved:
            return "nothing left above ε after " + used;
        case StopReason::iteration_limit:
            return "iteration limit reached (" + used + "), something still above ε";
        case StopReason::passes_complete:
            return "all relaxation passes done (" + used + "), penetration left by design";
        case StopReason::unmovable_left:
            return "what is left above ε this method cannot move (" + used + ")";
        case StopReason::sweeps_complete:
            return "all sweeps done (" + used + ")";
    }
    return used;
}

void write_position_phase(std::ostream& out, const Trace& trace, const FrameRecord& frame) {
    // (A velocity method that owns the whole step runs no position method: `none`.)
    out << "\n== Position phase: "
        << formats::name_of(formats::position_method_names, position_method_in_effect(trace.scene.settings)) << " ==\n";
    for (const PositionIteration& it : frame.position.iterations) {
        out << "\nIteration " << it.iteration << (it.pass ? " (pass " + std::to_string(*it.pass) + ")" : "");
        if (it.slop)  // the split impulse pushes every contact in turn, aiming short of the slop
            out << " · contact " << it.contact << " is pushed: penetration " << number(it.penetration) << " m, slop "
                << number(*it.slop) << " m\n";
        else
            out << " · contact " << it.contact << " is the deepest: penetration " << number(it.penetration) << " m > ε "
                << number(it.epsilon) << " m\n";
        for (const StepTable& t : position_iteration_tables(it)) write_table(out, t);
    }
    out << "Position phase ends: " << stop_text(frame.position.outcome) << '\n';
}

void write_velocity_phase(std::ostream& out, const Trace& trace, const FrameRecord& frame) {
    out << "\n== Velocity phase: "
        << formats::name_of(formats::velocity_method_names, trace.scene.settings.velocity_method) << " ==\n";
    for (const VelocityIteration& it : frame.velocity.iterations) {
        if (it.sweep)
            out << "\nIteration " << it.iteration << " · " << sweep_text(*it.sweep, trace.scene.settings)
                << " visits contact " << it.contact << ": desired Δv " << number(it.desired_delta_velocity) << " m/s\n";
        else
            out << "\nIteration " << it.iteration << " · contact " << it.contact
                << " needs the largest change: desired Δv " << number(it.desired_delta_velocity) << " m/s > ε "
                << number(it.epsilon) << " m/s\n";
        for (const StepTable& t : velocity_iteration_tables(it)) write_table(out, t);
    }
    out << "Velocity phase ends: " << stop_text(frame.velocity.outcome) << '\n';
}

void write_bodies_after(std::ostream& out, const Trace& trace, const FrameRecord& frame) {
    out << "\n== Bodies after resolution ==\n";
    for (std::size_t i = 0; i < frame.bodies_after.size(); ++i) {
        const BodyState& before = frame.bodies_before[i];
        const BodyState& after = frame.bodies_after[i];
        out << "  " << trace.scene.body_names[i] << ": position " << vector(after.position) << " m (moved "
            << vector(after.position - before.position) << "), velocity " << vector(after.velocity)
            << " m/s, angular velocity " << vector(after.angular_velocity) << " rad/s, orientation "
            << quaternion(after.orientation) << '\n';
    }
}

}  // namespace

void write_explanation(std::ostream& out, const Trace& trace) {
    out << describe_settings(trace.scene.settings) << '\n';
    for (const FrameRecord& frame : trace.frames) {
        for (const ContactPreparation& c : frame.contacts) {
            out << "\n== Contact " << c.contact << ": " << body_name(trace, c.bodies[0]) << " (body 0) against "
                << body_name(trace, c.bodies[1]) << " (body 1) ==\n"
                << "  point " << vector(c.point) << " m, normal " << vector(c.normal) << ", penetration "
                << number(c.penetration) << " m, restitution " << number(c.restitution) << ", friction "
                << number(c.friction) << '\n'
                << "  " << origin_text(c.origin) << '\n';
            if (c.body1_point)
                out << "  body 1 is touched at " << vector(*c.body1_point)
                    << " m (body1_point): a recycled contact keeps each body's own anchor\n";
            if (c.swapped)
                out << "  (given with the world as body 0: bodies swapped and the normal reversed, so it points "
                       "towards body 0)\n";
            if (c.inert) out << "  (both bodies are immovable: nothing can resolve this contact, it is skipped)\n";
            for (const StepTable& t : preparation_tables(c)) write_table(out, t);
        }
        if (frame.phase_order == PhaseOrder::positions_first) {
            write_position_phase(out, trace, frame);
            write_velocity_phase(out, trace, frame);
        } else {
            write_velocity_phase(out, trace, frame);
            write_position_phase(out, trace, frame);
        }
        write_bodies_after(out, trace, frame);
    }
}

void write_summary(std::ostream& out, const Trace& trace) {
    out << describe_settings(trace.scene.settings) << '\n';
    for (const FrameRecord& frame : trace.frames) {
        out << "position phase: " << stop_text(frame.position.outcome) << '\n'
            << "velocity phase: " << stop_text(frame.velocity.outcome) << '\n';
        write_bodies_after(out, trace, frame);
    }
}

}  // namespace impulse::explain
