// Soft step (Box2D v3): sub-steps of integrate velocities, warm start, solve with the soft bias, integrate
// positions and relax; then restitution and the impulses kept for next frame. The outline and the equations
// are in soft_step.hpp; this file follows it stage by stage.

#include "methods/soft_step.hpp"

#include "derivation/contact_velocity.hpp"
#include "derivation/impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "resolver/prepared_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace impulse {

Softness soft_contact(double hertz, double damping_ratio, double h) {
    if (hertz == 0.0) return {0.0, 1.0, 0.0};  // no spring: a rigid contact with no bias
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * damping_ratio + h * omega;  // 2 zeta + h omega
    const double a2 = h * omega * a1;                   // h omega (2 zeta + h omega) = (h c + h^2 k) / m
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

Softness soft_step_softness(const ResolverSettings& settings) {
    const double substep = settings.duration / settings.soft_step.substeps;
    // A spring faster than a quarter of the sub-step rate would be stepped too coarsely to stay stable.
    const double hertz = std::min(settings.soft_step.contact_hertz, 0.25 / substep);
    return soft_contact(hertz, settings.soft_step.damping_ratio, substep);
}

namespace {

// A contact as soft step carries it through the frame, beside its preparation (steps 1-5).
struct SoftContact {
    int index = 0;                    // in the prepared list
    Mat3 delta_velocity_matrix;       // K, contact coordinates, from the anchors and inertia at preparation
    double normal_mass = 0.0;         // m_n = 1 / d (step 3)
    Eigen::Vector2d tangent_mass;     // 1 / K11, 1 / K22
    double relative_velocity = 0.0;   // v_n when the frame began (step 4), which restitution reverses
    bool bounces = false;             // c > 0 and it closed faster than the restitution cut-off
    Vec3 accumulated = Vec3::Zero();  // lambda: this contact's impulse per sub-step (n, t1, t2)
    double most_pushed = 0.0;         // the largest lambda_n this frame: restitution needs a contact that pushed
};

// What one visit does to the accumulated impulse, before it is applied and recorded.
struct Visit {
    Vec3 before;
    Vec3 unclamped;
    Vec3 after;
    Vec3 contact_velocity = Vec3::Zero();  // when visited (only kept for the record by the warm start)
    ImpulseClamp clamp = ImpulseClamp::none;
    double desired_delta_velocity = 0.0;  // target - current normal velocity (see the header)
    std::optional<double> position_bias;
    bool sliding = false;
};

// The soft bias of a point at penetration p for one visit (contact_solver.c's three cases).
struct Bias {
    double bias = 0.0;  // added to v_n: the target normal velocity is -bias
    double mass_scale = 1.0;
    double impulse_scale = 0.0;
};

class SoftStep {
public:
    SoftStep(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& prepared, const ResolverSettings& settings,
             const SoftStepForces& forces, Recorder& recorder)
        : bodies_(bodies),
          prepared_(prepared),
          settings_(settings),
          forces_(forces),
          recorder_(recorder),
          substep_(settings.duration / settings.soft_step.substeps),
          softness_(soft_step_softness(settings)),
          recording_(recorder.wants_updates()) {
        for (const RigidBody& body : bodies) {
            start_position_.push_back(body.position);
            start_orientation_.push_back(body.orientation);
        }
        moved_.assign(bodies.size(), Vec3::Zero());
        turned_.assign(bodies.size(), Mat3::Identity());
    }

    void prepare(std::span<const Contact> contacts, const ContactMemory* memory) {
        const double cutoff = settings_.refinements.restitution_cutoff;
        for (std::size_t i = 0; i < prepared_.size(); ++i) {
            const PreparedContact& p = prepared_[i];
            const ContactPreparation& d = p.derivation;
            if (d.inert) continue;  // nothing can move it: no visits
            SoftContact c;
            c.index = static_cast<int>(i);
            c.delta_velocity_matrix = delta_velocity_matrix(d.basis, d.relative_position, p.mass);
            c.normal_mass = 1.0 / d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse;
            const auto inverse = [](double k) { return k > 0.0 ? 1.0 / k : 0.0; };
            c.tangent_mass = {inverse(c.delta_velocity_matrix(1, 1)), inverse(c.delta_velocity_matrix(2, 2))};
            c.relative_velocity = d.contact_velocity.contact_velocity.x();
            c.bounces = d.restitution != 0.0 && c.relative_velocity < -cutoff;
            if (memory)
                if (const std::optional<Vec3> last = memory->recall(key_of(contacts[i])))
                    c.accumulated = inside_limits(to_contact(d.basis, *last), d.friction);
            contacts_.push_back(c);
        }
    }

    void run() {
        const SoftStepForces& f = forces_;
        for (int substep = 0; substep < settings_.soft_step.substeps; ++substep) {
            for (RigidBody& body : bodies_) integrate_velocity(body, f.gravity, substep_, f.damping);
            for (SoftContact& c : contacts_) visit(c, {substep, 0, SolverStage::warm_start}, warm_start(c));
            for (int pass = 0; pass < settings_.sweeps; ++pass)
                for (SoftContact& c : contacts_) visit(c, {substep, pass, SolverStage::solve}, solve(c, true));
            for (RigidBody& body : bodies_) integrate_position(body, substep_, settings_.orientation_update);
            track_moves();
            for (int pass = 0; pass < settings_.sweeps; ++pass)
                for (SoftContact& c : contacts_) visit(c, {substep, pass, SolverStage::relax}, solve(c, false));
        }
        for (SoftContact& c : contacts_)
            if (c.bounces && c.most_pushed > 0.0)
                visit(c, {settings_.soft_step.substeps - 1, 0, SolverStage::restitution}, restitution(c));
    }

    void remember(std::span<const Contact> contacts, ContactMemory& memory) const {
        std::vector<std::pair<ContactKey, Vec3>> impulses;
        impulses.reserve(contacts_.size());
        for (const SoftContact& c : contacts_)
            impulses.emplace_back(
                key_of(contacts[static_cast<std::size_t>(c.index)]),
                to_world(prepared_[static_cast<std::size_t>(c.index)].derivation.basis, c.accumulated));
        memory.remember(impulses);
    }

    int visits() const { return visits_; }

private:
    const ContactPreparation& derivation(const SoftContact& c) const {
        return prepared_[static_cast<std::size_t>(c.index)].derivation;
    }

    // A remembered impulse whose contact turned a little since is put back inside the limits a total obeys.
    static Vec3 inside_limits(Vec3 impulse, double friction) {
        impulse.x() = std::max(impulse.x(), 0.0);
        const double tangential = impulse.tail<2>().norm(), limit = friction * impulse.x();
        if (tangential > limit) impulse.tail<2>() *= tangential > 0.0 ? limit / tangential : 0.0;
        return impulse;
    }

    void track_moves() {
        for (std::size_t b = 0; b < bodies_.size(); ++b) {
            moved_[b] = bodies_[b].position - start_position_[b];
            turned_[b] = (bodies_[b].orientation * start_orientation_[b].conjugate()).toRotationMatrix();
        }
    }

    // p = p0 - n . [(dx0 + R0 r0 - r0) - (dx1 + R1 r1 - r1)]: the anchors turn with their bodies.
    double penetration(const SoftContact& c) const {
        const ContactPreparation& d = derivation(c);
        Vec3 separated = Vec3::Zero();  // how far body 0's anchor moved away from body 1's
        for (int i = 0; i < 2; ++i) {
            if (d.bodies[i] == world_body) continue;
            const auto b = static_cast<std::size_t>(d.bodies[i]);
            const Vec3& r = *d.relative_position[i];
            separated += body_sign(i) * (moved_[b] + (turned_[b] * r - r));
        }
        return d.penetration - separated.dot(d.normal);
    }

    // Step 4 on the bodies' current motion, with the anchors fixed at preparation and no acceleration term.
    Vec3 current_velocity(const SoftContact& c) const {
        const ContactPreparation& d = derivation(c);
        PerBody<BodyMotion> motion;
        for (int i = 0; i < 2; ++i) {
            if (d.bodies[i] == world_body) continue;
            const RigidBody& body = bodies_[static_cast<std::size_t>(d.bodies[i])];
            motion[i] = BodyMotion{body.velocity, body.angular_velocity, Vec3::Zero()};
        }
        return contact_velocity(d.basis, d.relative_position, motion, 0.0, false).contact_velocity;
    }

    Bias bias_at(double penetration, bool use_bias) const {
        // Speculative: a gap of -p may close at up to -p / h_s in this sub-step, and no push is asked for.
        if (penetration < 0.0) return {-penetration / substep_, 1.0, 0.0};
        if (!use_bias) return {};
        return {std::max(-softness_.bias_rate * penetration, -settings_.soft_step.max_push_velocity),
                softness_.mass_scale, softness_.impulse_scale};
    }

    static Visit unchanged(const SoftContact& c, const Vec3& velocity) {
        Visit v;
        v.before = v.unclamped = v.after = c.accumulated;
        v.contact_velocity = velocity;
        return v;
    }

    Visit warm_start(const SoftContact& c) const {
        // The sub-step's velocities start without any contact impulse: the warm start applies all of lambda.
        Visit v;
        v.before = Vec3::Zero();
        v.unclamped = v.after = c.accumulated;
        if (recording_) {
            v.contact_velocity = current_velocity(c);
            v.desired_delta_velocity = c.delta_velocity_matrix.row(0).dot(c.accumulated);
        }
        return v;
    }

    Visit solve(const SoftContact& c, bool use_bias) const {
        const ContactPreparation& d = derivation(c);
        const Vec3 velocity = current_velocity(c);
        const Bias b = bias_at(penetration(c), use_bias);
        Visit v = unchanged(c, velocity);
        // delta lambda_n = -m_n mass_scale (v_n + bias) - impulse_scale lambda_n, total kept >= 0
        v.unclamped.x() = c.accumulated.x() - c.normal_mass * b.mass_scale * (velocity.x() + b.bias) -
                          b.impulse_scale * c.accumulated.x();
        v.after.x() = std::max(v.unclamped.x(), 0.0);
        const bool pulled = v.unclamped.x() < 0.0;
        bool coned = false;
        if (d.friction != 0.0) {
            // The tangential velocity once the normal increment has acted, then -v_t / K_tt per row.
            const double normal_increment = v.after.x() - c.accumulated.x();
            const Eigen::Vector2d sliding =
                velocity.tail<2>() + c.delta_velocity_matrix.block<2, 1>(1, 0) * normal_increment;
            v.unclamped.tail<2>() = c.accumulated.tail<2>() - c.tangent_mass.cwiseProduct(sliding);
            const double tangential = v.unclamped.tail<2>().norm(), limit = d.friction * v.after.x();
            coned = tangential > limit;
            v.after.tail<2>() =
                coned ? Eigen::Vector2d(v.unclamped.tail<2>() * (tangential > 0.0 ? limit / tangential : 0.0))
                      : Eigen::Vector2d(v.unclamped.tail<2>());
        }
        v.clamp = pulled && coned ? ImpulseClamp::both
                  : pulled        ? ImpulseClamp::push_only
                  : coned         ? ImpulseClamp::friction
                                  : ImpulseClamp::none;
        v.sliding = coned;
        if (recording_) {
            v.position_bias = -b.bias;
            v.desired_delta_velocity = -b.bias - velocity.x();
        }
        return v;
    }

    Visit restitution(const SoftContact& c) const {
        const double c_used = derivation(c).restitution;
        const Vec3 velocity = current_velocity(c);
        // The target is -c v_n(before): delta lambda_n = -m_n (v_n + c v_n(before)), total kept >= 0.
        Visit v = unchanged(c, velocity);
        v.unclamped.x() = c.accumulated.x() - c.normal_mass * (velocity.x() + c_used * c.relative_velocity);
        v.after.x() = std::max(v.unclamped.x(), 0.0);
        if (v.unclamped.x() < 0.0) v.clamp = ImpulseClamp::push_only;
        if (recording_) v.desired_delta_velocity = -c_used * c.relative_velocity - velocity.x();
        return v;
    }

    // Applies after - before to the bodies by step 7, keeps the total, and records the visit.
    void visit(SoftContact& c, const SweepPlace& place, const Visit& v) {
        const PreparedContact& p = prepared_[static_cast<std::size_t>(c.index)];
        const ContactPreparation& d = p.derivation;
        const Vec3 increment = v.after - v.before;
        const Vec3 world = to_world(d.basis, increment);
        const VelocityChange change = velocity_change(world, d.relative_position, p.mass);
        for (int i = 0; i < 2; ++i) {
            if (d.bodies[i] == world_body) continue;
            RigidBody& body = bodies_[static_cast<std::size_t>(d.bodies[i])];
            body.velocity += *change.velocity_change[i];
            body.angular_velocity += *change.rotation_change[i];
        }
        c.accumulated = v.after;
        c.most_pushed = std::max(c.most_pushed, c.accumulated.x());
        if (recording_) record(c, place, v, increment, world, change);
        ++visits_;
    }

    void record(const SoftContact& c, const SweepPlace& place, const Visit& v, const Vec3& increment, const Vec3& world,
                const VelocityChange& change) {
        const ContactPreparation& d = derivation(c);
        const bool bouncing = place.stage == SolverStage::restitution;
        VelocityResolution r;
        r.contact_velocity = v.contact_velocity;
        r.desired_delta_velocity = {.separating_velocity = v.contact_velocity.x(),
                                    .restitution = d.restitution,
                                    .restitution_cutoff = settings_.refinements.restitution_cutoff,
                                    .restitution_cutoff_applied = d.restitution != 0.0 && !c.bounces,
                                    .restitution_used = bouncing ? d.restitution : 0.0,
                                    .velocity_from_acceleration_applied = false,
                                    .velocity_from_acceleration = 0.0,
                                    .desired_delta_velocity = v.desired_delta_velocity};
        r.position_bias = v.position_bias;
        const bool tangential = d.friction != 0.0 && !bouncing;
        r.impulse = {.model = !tangential ? ImpulseModel::frictionless
                              : v.sliding ? ImpulseModel::sliding_friction
                                          : ImpulseModel::static_friction,
                     .friction = std::nullopt,
                     .impulse_contact = increment,
                     .impulse_world = world};
        r.velocity_change = change;
        const VelocityIteration iteration{.iteration = visits_,
                                          .contact = c.index,
                                          .desired_delta_velocity = v.desired_delta_velocity,
                                          .epsilon = 0.0,
                                          .sweep = place,
                                          .accumulated = AccumulatedImpulse{v.before, v.unclamped, v.after, v.clamp},
                                          .resolution = r,
                                          .updates = {}};
        recorder_.velocity_iteration(iteration);
    }

    std::vector<RigidBody>& bodies_;
    std::vector<PreparedContact>& prepared_;
    const ResolverSettings& settings_;
    const SoftStepForces& forces_;
    Recorder& recorder_;
    double substep_;
    Softness softness_;
    bool recording_;
    std::vector<SoftContact> contacts_;
    std::vector<Vec3> start_position_;
    std::vector<Quat> start_orientation_;
    std::vector<Vec3> moved_;   // per body: its move since the frame began
    std::vector<Mat3> turned_;  // per body: its turn since the frame began, R = q q0^-1
    int visits_ = 0;
};

}  // namespace

ResolutionSummary solve_soft_step(std::vector<RigidBody>& bodies, std::span<const Contact> contacts,
                                  const ResolverSettings& settings, const SoftStepForces& forces, Recorder& recorder,
                                  int frame, ContactMemory* memory) {
    const std::vector<MassProperties> mass = mass_properties(bodies);
    recorder.begin_frame(frame, bodies, mass);
    std::vector<PreparedContact> prepared = prepare_contacts(contacts, bodies, mass, settings);
    recorder.contacts_prepared(prepared);

    ResolutionSummary summary;
    // Soft step has no position phase: the soft bias inside the velocity solve pushes the bodies apart.
    summary.position = {0, 0, StopReason::resolved};  // no position phase: the soft contact pushes
    recorder.end_phase(Phase::position, summary.position);

    SoftStep step(bodies, prepared, settings, forces, recorder);
    step.prepare(contacts, settings.warm_start ? memory : nullptr);
    step.run();
    if (memory) {
        if (settings.warm_start)
            step.remember(contacts, *memory);
        else
            memory->clear();
    }

    // Every visit of every stage is an iteration; the schedule is fixed, so it always runs to its end.
    summary.velocity = {step.visits(), step.visits(), StopReason::sweeps_complete};
    recorder.end_phase(Phase::velocity, summary.velocity);
    recorder.end_frame(bodies);
    return summary;
}

}  // namespace impulse
