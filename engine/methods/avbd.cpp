// Augmented vertex block descent (AVBD: Giles, Diaz and Yuksel, "Augmented Vertex Block Descent", ACM TOG 44(4),
// SIGGRAPH 2025; the reference demo savant117/avbd-demo2d), for rigid bodies in 3D. It answers the chapter's
// question ("how much, and how fast, do we push these bodies apart?") on positions and per body rather than per
// contact: every body in turn solves a 6x6 block for where it should be, given its inertia and the forces of its
// contacts, and each contact's force is an augmented Lagrangian whose multiplier lambda and stiffness k grow until
// the contact holds. It owns the whole step (integration included), like soft step. The equations, with the
// paper's numbers, are in the derivation steps of engine/derivation/avbd/ and in docs/methods.md; per frame of
// h = settings.duration:
//   1. the contacts' rows, linearised at the frame's start (Sec. 4): derivation/avbd/contact_constraint.hpp;
//   2. warm start (Eq. 19): each contact's lambda and k from the contact memory, decayed by alpha gamma and
//      gamma, or lambda = 0 and k = k_min for a new one (derivation/avbd/dual_update.hpp), with beta, k_min and
//      k_max the settings' per-kilogram numbers times the lighter body's mass
//      (derivation/avbd/mass_scaled_penalty.hpp);
//   3. each body's inertial target y = x + h v + h^2 g (Eq. 2) and its initial guess (VBD's adaptive one):
//      derivation/avbd/implicit_euler.hpp;
//   4. `avbd.iterations` times: a primal sweep, every body in index order solving its block
//      H delta x = f (Eqs. 4-6, 13, 17: derivation/avbd/body_block.hpp, block_solve.hpp) against its contacts'
//      forces at the other bodies' current positions (Gauss-Seidel); then a dual sweep, every contact's lambda
//      and k updated (Eqs. 11, 16);
//   5. the velocities from the displacements, v = delta p / h, w = delta theta / h (BDF1);
//      with `avbd.post_stabilize`, one more primal sweep with alpha = 0 then moves the bodies out of what
//      penetration is left, after the velocities were taken;
//   6. the positions written: p = p- + delta p, q turned by delta theta (settings.orientation_update);
//   7. restitution, which AVBD does not model (its step is implicit Euler, which ends a collision at rest): as soft
//      step does after its sub-steps, a contact that closed faster than the restitution cut-off when the frame
//      began and pushed is visited once on velocities with the target -c v_n(before) (steps 3, 4 and 7);
//   8. lambda (world coordinates) and k remembered in the contact memory for the next frame.
// A body that cannot move (inverse mass and inverse inertia 0) moves by its velocity and is not solved; a body
// with no contact lands on its inertial target.
// When the recorder keeps the frame, each body visit, dual update and bounce is reported as it happens (one
// `if (frame_.keeping)` in each; record/avbd_records.hpp): the trace steps through a sweep body by body.

#include "derivation/avbd/block_solve.hpp"
#include "derivation/avbd/body_block.hpp"
#include "derivation/avbd/contact_constraint.hpp"
#include "derivation/avbd/contact_force.hpp"
#include "derivation/avbd/dual_update.hpp"
#include "derivation/avbd/implicit_euler.hpp"
#include "derivation/avbd/mass_scaled_penalty.hpp"
#include "derivation/contact_velocity.hpp"
#include "derivation/delta_velocity_per_unit_impulse.hpp"
#include "derivation/velocity_change.hpp"
#include "methods/method.hpp"
#include "methods/solver_common.hpp"
#include "record/avbd_records.hpp"

#include <algorithm>
#include <limits>

namespace impulse {

namespace {

// A contact as AVBD carries it through the frame: its rows, fixed at the frame's start, and its dual variables.
struct AvbdContact {
    int contact = 0;                   // index in the prepared list
    std::array<int, 2> bodies{0, -1};  // -1 = the world
    ConstraintJacobian jacobian;       // the rows' gradients (Sec. 4)
    double initial_normal = 0.0;       // C_n(x-) = slop - penetration (m)
    double friction = 0.0;             // mu
    PenaltyParameters penalty;         // its beta, k_min and k_max: the settings' per kg times the lighter body's mass
    DualVariables dual;                // lambda (N) and k (N/m)
};

class Avbd {
public:
    explicit Avbd(FrameContext& frame)
        : frame_(frame),
          settings_(frame.settings),
          avbd_(frame.settings.avbd),
          h_(frame.settings.duration),
          contacts_(frame.scratch),
          keys_(frame.scratch),
          target_(frame.bodies.size(), frame.scratch),
          displacement_(frame.bodies.size(), frame.scratch),
          velocity_(frame.bodies.size(), frame.scratch),
          mass_(frame.bodies.size(), frame.scratch),
          solved_(frame.scratch),
          bounced_(frame.scratch) {
        prepare_bodies();
        prepare_contacts();
        list_solved_bodies();
    }

    void run() {
        const int iterations = avbd_.iterations;
        const int total = iterations + (avbd_.post_stabilize ? 1 : 0);
        bool velocities_taken = iterations <= 0;
        if (velocities_taken) take_velocities();
        for (int it = 0; it < total && sweep(it); ++it) {
            if (it == iterations - 1) {
                take_velocities();
                velocities_taken = true;
            }
        }
        // Cut short (FrameContext::stop): the bodies go where the sweeps got them, at the velocities that implies,
        // and the frame's restitution, judged on finished velocities, is not run.
        if (!velocities_taken) take_velocities();
        write_bodies();
        if (!frame_.cut_short) restitution();
        for (const int b : solved_) {
            RigidBody& body = frame_.bodies[static_cast<std::size_t>(b)];
            body.last_frame_acceleration = (body.velocity - velocity_[static_cast<std::size_t>(b)].before) / h_;
        }
        stamp_visits();
    }

    void remember(ContactMemory& memory) const {
        memory.remember(
            std::span<const ContactKey>(keys_),
            [this](std::size_t k) -> Vec3 {
                const AvbdContact& c = contacts_[k];
                return to_world(basis_of(c), c.dual.lambda);
            },
            [this](std::size_t k) -> std::array<double, 2> {
                const Stiffness& s = contacts_[k].dual.stiffness;
                return {s.normal, s.tangential};
            });
    }

    // Every block solve, dual update and bounce is an iteration (each is one of the trace's iterations).
    int visits() const { return visits_ + dual_updates_ + static_cast<int>(bounced_.size()); }
    int visit_limit() const {
        // Saturated: a count of sweeps set to stop only by the stop flag would overflow an int.
        const long long sweeps = static_cast<long long>(avbd_.iterations) + (avbd_.post_stabilize ? 1 : 0);
        const long long contacts = static_cast<long long>(contacts_.size());
        const long long limit =
            static_cast<long long>(solved_.size()) * sweeps + contacts * std::max(avbd_.iterations, 0) + contacts;
        return static_cast<int>(std::min<long long>(limit, std::numeric_limits<int>::max()));
    }

private:
    // A body's velocities before the frame and as the displacement gives them (BDF1).
    struct Velocities {
        Vec3 before = Vec3::Zero();
        Vec3 linear = Vec3::Zero();
        Vec3 angular = Vec3::Zero();
    };

    void prepare_bodies() {
        const Forces& f = frame_.forces;
        for (std::size_t b = 0; b < frame_.bodies.size(); ++b) {
            const RigidBody& body = frame_.bodies[b];
            velocity_[b].before = body.velocity;
            if (is_immovable(body)) {
                // It moves by its own velocity, which nothing changes: a contact sees it where it is going.
                displacement_[b] = {body.velocity * h_, body.angular_velocity * h_};
                continue;
            }
            const InertialTarget t = inertial_target(body, f.gravity, h_, f.damping);  // (Eq. 2)
            target_[b] = t.inertial_target;
            displacement_[b] = t.initial_guess;
            mass_[b] = body_mass(body, frame_.mass[b]);
        }
    }

    void prepare_contacts() {
        contacts_.reserve(frame_.contacts.size());
        keys_.reserve(frame_.contacts.size());
        std::ptrdiff_t hint = 0;
        for (const PreparedContact& row : frame_.contacts) {
            const std::array<int, 2> body = row.bodies;
            const bool moves0 = !is_immovable(frame_.bodies[static_cast<std::size_t>(body[0])]);
            const bool moves1 =
                body[1] != world_body && !is_immovable(frame_.bodies[static_cast<std::size_t>(body[1])]);
            if (!moves0 && !moves1) continue;  // nothing it could push
            AvbdContact& c = contacts_.emplace_back();
            c.contact = row.contact;
            c.bodies = body;
            c.jacobian = constraint_jacobian(row.basis, row.relative_position);
            c.initial_normal = avbd_.slop - row.penetration;
            c.friction = row.friction;
            c.penalty = mass_scaled_penalty(avbd_, {mass_of(body[0]), mass_of(body[1])});
            const ContactKey key = contact_key(row);
            keys_.push_back(key);
            std::optional<RememberedDual> remembered;
            if (settings_.warm_start && frame_.memory) {
                const std::ptrdiff_t slot = frame_.memory->slot_of(key, hint);
                if (slot >= 0) {
                    hint = slot + 1;
                    const std::optional<std::array<double, 2>> k = frame_.memory->stiffness_at(slot);
                    remembered = RememberedDual{
                        to_contact(row.basis, frame_.memory->impulse_at(slot)),
                        k ? Stiffness{(*k)[0], (*k)[1]} : Stiffness{c.penalty.stiffness_min, c.penalty.stiffness_min}};
                }
            }
            c.dual = warm_start(remembered, c.friction, avbd_, c.penalty);  // (Eq. 19)
        }
    }

    // The bodies that take part in the sweeps: the movable ones with a contact. A movable body with none lands on its
    // inertial target (its block would be M/h^2 alone).
    void list_solved_bodies() {
        by_body_.emplace(contacts_, frame_.bodies.size());
        for (std::size_t b = 0; b < frame_.bodies.size(); ++b) {
            if (is_immovable(frame_.bodies[b])) continue;
            if (has_contacts(b))
                solved_.push_back(static_cast<int>(b));
            else
                displacement_[b] = target_[b];
        }
    }

    bool has_contacts(std::size_t body) const { return !by_body_->contacts_of(static_cast<int>(body)).empty(); }
    // Which of a contact's bodies `body` is (0 or 1).
    static int slot_of(const AvbdContact& c, std::size_t body) { return c.bodies[0] == static_cast<int>(body) ? 0 : 1; }

    // A body's mass as its block takes it (kg): 0 for the world and for a body that cannot translate.
    double mass_of(int body) const { return body == world_body ? 0.0 : mass_[static_cast<std::size_t>(body)].mass; }

    const Displacement& displacement_of(int body) const {
        static const Displacement world{};
        return body == world_body ? world : displacement_[static_cast<std::size_t>(body)];
    }

    ConstraintValue constraint_of(const AvbdContact& c, double alpha) const {
        return constraint_value(c.jacobian, c.initial_normal,
                                {displacement_of(c.bodies[0]), displacement_of(c.bodies[1])}, alpha);
    }

    // Sweep `it`: every body's primal update, then, in the iterations, every contact's dual update.
    // Post-stabilisation: the iterations correct nothing (alpha 1), the extra sweep all of it (alpha 0).
    // False when the stop flag cut it short (looked at every stop_check_visits block solves and once a sweep).
    bool sweep(int it) {
        const bool iteration = it < avbd_.iterations;  // else the post-stabilisation sweep
        const double alpha = !avbd_.post_stabilize ? avbd_.alpha : iteration ? 1.0 : 0.0;
        if (frame_.stop_requested()) return false;
        const SweepPlace place{0, it, iteration ? SolverStage::solve : SolverStage::stabilize};
        for (const int b : solved_) {
            if (visits_ % stop_check_visits == 0 && visits_ > 0 && frame_.stop_requested()) return false;
            visit(static_cast<std::size_t>(b), alpha, place);
        }
        if (iteration) update_duals(alpha, it);
        return true;
    }

    // The primal update of one body (Eqs. 4-6, 13, 17): its block against its contacts as they are now, solved.
    void visit(std::size_t b, double alpha, const SweepPlace& place) {
        Displacement& x = displacement_[b];
        BodyBlock block = inertial_block(mass_[b], h_, target_[b], x);
        for (const int k : by_body_->contacts_of(static_cast<int>(b))) {
            const AvbdContact& c = contacts_[static_cast<std::size_t>(k)];
            const ConstraintValue value = constraint_of(c, alpha);
            add_contact_force(c.jacobian, slot_of(c, b),
                              contact_force(c.dual.lambda, c.dual.stiffness, value.constraint, c.friction), block);
        }
        if (!mass_[b].translates || !mass_[b].turns_freely) hold_fixed_directions(mass_[b], block);
        const BlockSolution solution = block_solve(block);  // (Eq. 4)
        if (frame_.keeping) report_visit(b, alpha, block, solution.position_change, place);
        x.linear += solution.position_change.linear;
        x.angular += solution.position_change.angular;
        ++visits_;
    }

    // The dual update of every contact (Eqs. 11, 16), at the bodies' new positions.
    void update_duals(double alpha, int it) {
        for (AvbdContact& c : contacts_) {
            const ConstraintValue value = constraint_of(c, alpha);
            const ContactForce force = contact_force(c.dual.lambda, c.dual.stiffness, value.constraint, c.friction);
            const DualVariables updated = dual_update(force, c.dual.stiffness, value.constraint, c.penalty);
            if (frame_.keeping)
                frame_.recorder.dual_visit({0, it, SolverStage::dual}, {rows_of(c, 0, value, force), updated});
            c.dual = updated;
            ++dual_updates_;
        }
    }

    // A contact's rows as a visit read them, for the recorder.
    static AvbdContactRows rows_of(const AvbdContact& c, int slot, const ConstraintValue& value,
                                   const ContactForce& force) {
        return {c.contact, slot, value.constraint, c.dual.stiffness, c.dual.lambda, force.force, c.friction};
    }

    // A body visit as the recorder takes it, before the body moves: its contacts read again as its block read them
    // (the same functions on the same displacements), its block and its move.
    void report_visit(std::size_t b, double alpha, const BodyBlock& block, const Displacement& change,
                      const SweepPlace& place) const {
        BodyVisitRecord r;
        r.body = static_cast<int>(b);
        for (const int k : by_body_->contacts_of(static_cast<int>(b))) {
            const AvbdContact& c = contacts_[static_cast<std::size_t>(k)];
            const ConstraintValue value = constraint_of(c, alpha);
            r.gathered.push_back(rows_of(c, slot_of(c, b), value,
                                         contact_force(c.dual.lambda, c.dual.stiffness, value.constraint, c.friction)));
        }
        r.block_matrix = block.block_matrix;
        r.block_force = block.block_force;
        r.position_change = change;
        const Displacement& x = displacement_[b];
        r.displacement = {x.linear + change.linear, x.angular + change.angular};
        frame_.recorder.body_visit(place, r);
    }

    // BDF1: v = delta p / h, w = delta theta / h.
    void take_velocities() {
        for (const int b : solved_) {
            const auto u = static_cast<std::size_t>(b);
            const Bdf1Velocity v = velocity_from_displacement(frame_.bodies[u], displacement_[u], h_);
            velocity_[u].linear = v.velocity;
            velocity_[u].angular = v.angular_velocity;
        }
    }

    void write_bodies() {
        const OrientationUpdate update = settings_.orientation_update;
        for (std::size_t b = 0; b < frame_.bodies.size(); ++b) {
            RigidBody& body = frame_.bodies[b];
            const Displacement& d = displacement_[b];
            if (!is_immovable(body)) {
                const bool solved = has_contacts(b);
                body.velocity = solved ? velocity_[b].linear : Vec3(d.linear / h_);
                body.angular_velocity = solved ? velocity_[b].angular : Vec3(d.angular / h_);
            }
            body.position += d.linear;
            body.orientation = rotated(body.orientation, d.angular, update);
        }
    }

    // Not AVBD's (implicit Euler ends a collision at rest): soft step's bounce, once, on the velocities.
    void restitution() {
        const double cutoff = settings_.restitution_cutoff;
        for (const AvbdContact& c : contacts_) {
            // Step 4's v_n when the frame began, as prepared (nothing updates it), is the one that bounces.
            const PreparedContact& row = frame_.contacts[static_cast<std::size_t>(c.contact)];
            if (row.restitution == 0.0 || row.contact_velocity.x() >= -cutoff || !(c.dual.lambda.x() > 0.0)) continue;
            const double d = row.delta_velocity_per_unit_impulse;  // step 3 (the frame's mass, as prepared)
            if (!(d > 0.0)) continue;                              // no impulse can move it
            const PerBody<Vec3> relative = relative_positions(row);
            // Step 4 on the velocities now; g = (-c v_n(before) - v_n) / d along n, push only.
            const Vec3 velocity =
                contact_velocity(row.basis, relative, contact_motion(row.bodies, frame_.bodies), h_, false)
                    .contact_velocity;
            const double impulse = (-row.restitution * row.contact_velocity.x() - velocity.x()) / d;
            if (!(impulse > 0.0)) continue;
            if (frame_.keeping) report_bounce(row, velocity, impulse);
            apply_velocity_change(
                frame_.bodies, c.bodies,
                velocity_change(row.basis.normal() * impulse, relative, impulse::mass_of(row, frame_.mass)));  // step 7
            bounced_.push_back(c.contact);
        }
    }

    // A bounce as the recorder takes it: an impulse along the normal, as soft step's restitution visit.
    void report_bounce(const PreparedContact& row, const Vec3& velocity, double impulse) const {
        const double desired = -row.restitution * row.contact_velocity.x() - velocity.x();
        frame_.recorder.velocity_visit(
            {.contact = row.contact,
             .sweep = SweepPlace{0, 0, SolverStage::restitution},
             .epsilon = 0.0,
             .updates = DesiredFollows::nothing,
             .resolution = nullptr,
             .contact_velocity = velocity,
             .desired_terms = {.separating_velocity = velocity.x(),
                               .restitution = row.restitution,
                               .restitution_cutoff = settings_.restitution_cutoff,
                               .restitution_cutoff_applied = false,
                               .restitution_used = row.restitution,
                               .velocity_from_acceleration_applied = false,
                               .velocity_from_acceleration = 0.0,
                               .position_bias = std::nullopt,
                               .desired_delta_velocity = desired},
             .accumulated = {Vec3::Zero(), Vec3(impulse, 0.0, 0.0), Vec3(impulse, 0.0, 0.0), ImpulseClamp::none},
             .friction_rows = false});
    }

    // For LastTouch (world/non_finite_check.hpp), stamped once at the end: each solved body's contacts in the last
    // sweep's order, then the bounces.
    void stamp_visits() const {
        if (!frame_.touch) return;
        for (const int b : solved_)
            for (const int k : by_body_->contacts_of(b))
                frame_.touch->touched(contacts_[static_cast<std::size_t>(k)].contact);
        for (const int c : bounced_) frame_.touch->touched(c);
    }

    const Basis& basis_of(const AvbdContact& c) const {
        return frame_.contacts[static_cast<std::size_t>(c.contact)].basis;
    }

    FrameContext& frame_;
    const ResolverSettings& settings_;
    const AvbdSettings& avbd_;
    double h_;
    // Every buffer in the frame's scratch (FrameContext::scratch).
    std::pmr::vector<AvbdContact> contacts_;
    std::pmr::vector<ContactKey> keys_;            // beside each contact
    std::pmr::vector<Displacement> target_;        // per body: y - x-
    std::pmr::vector<Displacement> displacement_;  // per body: x - x-, the iterations' unknown
    std::pmr::vector<Velocities> velocity_;        // per body
    std::pmr::vector<BodyMass> mass_;              // per body
    std::pmr::vector<int> solved_;                 // the bodies the sweeps visit, in index order
    std::optional<ContactsByBody> by_body_;        // each body's contacts, in contact order
    std::pmr::vector<int> bounced_;                // the contacts restitution visited
    int visits_ = 0;                               // block solves
    int dual_updates_ = 0;                         // contacts' dual updates
};

}  // namespace

PhaseOutcome avbd_step(FrameContext& frame) {
    return whole_step<Avbd>(frame);
}

}  // namespace impulse
