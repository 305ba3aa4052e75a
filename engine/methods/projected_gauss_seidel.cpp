// Projected Gauss-Seidel with accumulated impulses: sequential impulses as Catto presented them (GDC 2005-
// 2014) and as Box2D v2.4 and Bullet solve contacts. Each contact keeps a running total impulse lambda in
// contact coordinates (x = normal, y and z = the basis tangents); each visit computes the impulse that would
// meet the contact's target from the velocity the bodies have now, adds it to the total, clamps the total
// (not the increment) to what a contact can do, and applies only the change of the total. A contact that an
// earlier visit pushed too hard can therefore give impulse back, which the book's methods cannot.
//
// Normal row (the book's step 3 gives K_n = d, the delta velocity per unit impulse):
//   target      = v_restitution + position_bias
//                 v_restitution = v_s + desired delta v of step 5 at preparation, i.e. -c_used (v_s - v_acc):
//                 the bounce judged once, on the closing speed before any impulse (restitution cut-off and
//                 velocity from acceleration as the settings say); position_bias = beta max(d - slop, 0)/h
//                 when position_method is baumgarte, else 0
//   d lambda_n  = (target - v_n) / K_n
//   lambda_n    = max(lambda_n + d lambda_n, 0)                               (push only)
// Friction rows, on the tangential velocity the normal change leaves, v_t' = v_t + K_tn (change of lambda_n):
//   d lambda_t  = -K_tt^-1 v_t'          (K_tt the 2x2 tangent block of the 3x3 K; its diagonal if singular)
//   lambda_t    = lambda_t + d lambda_t, scaled back onto |lambda_t| <= mu lambda_n    (friction cone)
// Applied this visit: lambda_after - lambda_before, through step 7 (velocity_change).
//
// Warm starting (settings.warm_start): before the sweeps, each contact found in the ContactMemory (by
// contact_key) starts from last frame's total, stored in world coordinates and re-projected on this frame's
// basis, normal part clamped >= 0 and tangential part to the cone, and that total is applied at once. At the
// end every contact's total is remembered in world coordinates (also without warm starting, so it can be
// switched on mid-run). When two contacts of a frame share a key (hand-written contacts have no features),
// only the first is warm started: the memory keeps the first one's total.
//
// The contact velocity is read from the bodies at every visit (step 4 on their current motion), never from
// the linearised bookkeeping, so recorded and unrecorded runs compute the same bits. The sweeps stop early
// when no visit of a whole sweep changed its own contact's velocity by more than the velocity epsilon
// (|K (lambda_after - lambda_before)| per component); settings.iterations does not apply.
//
// Recorded per visit (and per warm start, stage warm_start): a VelocityIteration with sweep {0, pass, stage},
// accumulated {before, unclamped, after, clamp}, and a resolution whose contact_velocity is the velocity read
// from the bodies, whose desired_delta_velocity is step 5 at preparation with separating_velocity = the
// current v_n and desired_delta_velocity = target - v_n (the value compared with the epsilon), whose
// position_bias is the Baumgarte bias (when on), and whose impulse_contact / impulse_world is the increment
// applied (model frictionless, static_friction, or sliding_friction when the cone clamped; no friction_solve:
// that is the book's 3x3 solve, not this one). The updates list is filled as worst-first fills it (the
// linearised bookkeeping of every contact sharing a body), but with desired delta v read in this method's
// terms, target - v_n; it costs a scan of the contacts per visit and is made only while recording.

#include "derivation/impulse.hpp"
#include "methods/solver_common.hpp"
#include "resolver/bookkeeping.hpp"
#include "resolver/phases.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace impulse {

namespace {

// What a contact's rows need, fixed for the whole phase.
struct ContactRows {
    bool active;                    // not inert: an impulse changes its velocity
    double target_normal_velocity;  // v_restitution + position bias (m/s)
    Mat3 delta_velocity_matrix;     // K, contact coordinates
    Vec3 total = Vec3::Zero();      // lambda: the accumulated impulse, contact coordinates (N s)
};

ContactRows rows_for(const PreparedContact& contact) {
    const ContactPreparation& d = contact.derivation;
    ContactRows rows{};
    rows.active = !d.inert;
    rows.target_normal_velocity = d.desired_delta_velocity.separating_velocity +
                                  d.desired_delta_velocity.desired_delta_velocity + contact.position_bias.value_or(0.0);
    rows.delta_velocity_matrix = delta_velocity_matrix(d.basis, d.relative_position, contact.mass);
    rows.total = Vec3::Zero();
    return rows;
}

// Scales the tangential part of `total` back onto the cone |lambda_t| <= mu lambda_n; true when it had to.
bool clamp_to_cone(Vec3& total, double friction) {
    const double limit = friction * total.x();
    const double tangential = std::hypot(total.y(), total.z());
    if (tangential <= limit) return false;
    const double scale = tangential > 0.0 ? std::max(limit, 0.0) / tangential : 0.0;
    total.y() *= scale;
    total.z() *= scale;
    return true;
}

ImpulseClamp clamp_of(bool push_only, bool friction) {
    return push_only && friction ? ImpulseClamp::both
           : push_only           ? ImpulseClamp::push_only
           : friction            ? ImpulseClamp::friction
                                 : ImpulseClamp::none;
}

// The accumulated-impulse update of one visit: normal row, then the friction rows on what it leaves.
AccumulatedImpulse visit_rows(const ContactRows& rows, const ContactPreparation& d, const Vec3& velocity) {
    AccumulatedImpulse a;
    a.before = rows.total;
    a.unclamped = rows.total;
    a.unclamped.x() += (rows.target_normal_velocity - velocity.x()) /
                       d.velocity_per_unit_impulse.delta_velocity_per_unit_impulse;  // (target - v_n) / K_n
    a.after = a.unclamped;
    const bool push_only = a.after.x() < 0.0;
    if (push_only) a.after.x() = 0.0;
    bool friction = false;
    if (d.friction != 0.0) {
        const Mat3& k = rows.delta_velocity_matrix;
        // The tangential velocity once the normal change is applied: v_t + K_tn (lambda_n after - before).
        const Eigen::Vector2d sliding =
            Eigen::Vector2d(velocity.y(), velocity.z()) + k.block<2, 1>(1, 0) * (a.after.x() - a.before.x());
        const Eigen::Matrix2d k_tt = k.block<2, 2>(1, 1);
        Eigen::Vector2d change = Eigen::Vector2d::Zero();
        if (k_tt.determinant() > 0.0) {
            change = -k_tt.inverse() * sliding;  // d lambda_t = -K_tt^-1 v_t'
        } else {
            for (int t = 0; t < 2; ++t)
                if (k_tt(t, t) > 0.0) change(t) = -sliding(t) / k_tt(t, t);
        }
        a.unclamped.y() += change.x();
        a.unclamped.z() += change.y();
        a.after.y() = a.unclamped.y();
        a.after.z() = a.unclamped.z();
        friction = clamp_to_cone(a.after, d.friction);
    } else {
        a.after.y() = a.after.z() = 0.0;
    }
    a.clamp = clamp_of(push_only, friction);
    return a;
}

ImpulseModel model_of(const ContactPreparation& d, ImpulseClamp clamp) {
    if (d.friction == 0.0) return ImpulseModel::frictionless;
    return clamp == ImpulseClamp::friction || clamp == ImpulseClamp::both ? ImpulseModel::sliding_friction
                                                                          : ImpulseModel::static_friction;
}

class PgsSolver {
public:
    PgsSolver(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts, const ResolverSettings& settings,
              Recorder& recorder)
        : bodies_(bodies), contacts_(contacts), settings_(settings), recorder_(recorder) {
        if (recorder_.wants_updates()) by_body_.emplace(contacts, bodies.size());
        rows_.reserve(contacts.size());
        for (const PreparedContact& c : contacts) rows_.push_back(rows_for(c));
    }

    int active_count() const {
        return static_cast<int>(
            std::count_if(rows_.begin(), rows_.end(), [](const ContactRows& r) { return r.active; }));
    }

    // Last frame's totals, re-projected and clamped, applied before the first sweep. Returns how many.
    int warm_start(const ContactMemory& memory) {
        int started = 0;
        std::unordered_set<ContactKey, ContactKeyHash> seen;
        for (int i = 0; i < static_cast<int>(contacts_.size()); ++i) {
            ContactRows& rows = rows_[static_cast<std::size_t>(i)];
            const ContactPreparation& d = contacts_[static_cast<std::size_t>(i)].derivation;
            const ContactKey key = contact_key(d);
            if (!seen.insert(key).second || !rows.active) continue;
            const std::optional<Vec3> remembered = memory.recall(key);
            if (!remembered) continue;
            AccumulatedImpulse a;
            a.before = Vec3::Zero();
            a.unclamped = to_contact(d.basis, *remembered);
            a.after = a.unclamped;
            const bool push_only = a.after.x() < 0.0;
            if (push_only) a.after.x() = 0.0;
            bool friction = false;
            if (d.friction == 0.0) {
                friction = a.after.y() != 0.0 || a.after.z() != 0.0;
                a.after.y() = a.after.z() = 0.0;
            } else {
                friction = clamp_to_cone(a.after, d.friction);
            }
            a.clamp = clamp_of(push_only, friction);
            visit(i, a, SweepPlace{0, 0, SolverStage::warm_start},
                  current_contact_velocity(contacts_[static_cast<std::size_t>(i)], bodies_, settings_));
            ++started;
        }
        return started;
    }

    // One sweep over every active contact in index order; returns the largest velocity change a visit made at
    // its own contact.
    double sweep(int pass) {
        double largest = 0.0;
        for (int i = 0; i < static_cast<int>(contacts_.size()); ++i) {
            const ContactRows& rows = rows_[static_cast<std::size_t>(i)];
            if (!rows.active) continue;
            const PreparedContact& contact = contacts_[static_cast<std::size_t>(i)];
            const Vec3 velocity = current_contact_velocity(contact, bodies_, settings_);
            const AccumulatedImpulse a = visit_rows(rows, contact.derivation, velocity);
            const Vec3 change = rows.delta_velocity_matrix * (a.after - a.before);
            largest = std::max(largest, change.cwiseAbs().maxCoeff());
            visit(i, a, SweepPlace{0, pass, SolverStage::solve}, velocity);
        }
        return largest;
    }

    void remember(ContactMemory& memory) const {
        std::vector<std::pair<ContactKey, Vec3>> totals;
        totals.reserve(contacts_.size());
        for (std::size_t i = 0; i < contacts_.size(); ++i)
            if (rows_[i].active)
                totals.emplace_back(contact_key(contacts_[i].derivation),
                                    to_world(contacts_[i].derivation.basis, rows_[i].total));
        memory.remember(totals);
    }

    int iterations() const { return iterations_; }

private:
    // Applies the change of contact i's total, a.after - a.before, and reports the visit.
    void visit(int i, const AccumulatedImpulse& a, const SweepPlace& place, const Vec3& velocity) {
        ContactRows& rows = rows_[static_cast<std::size_t>(i)];
        const PreparedContact& contact = contacts_[static_cast<std::size_t>(i)];
        const ContactPreparation& d = contact.derivation;
        VelocityResolution r;
        r.contact_velocity = velocity;
        r.desired_delta_velocity = d.desired_delta_velocity;
        r.desired_delta_velocity.separating_velocity = velocity.x();
        r.desired_delta_velocity.desired_delta_velocity = rows.target_normal_velocity - velocity.x();
        r.position_bias = contact.position_bias;
        r.impulse.model = model_of(d, a.clamp);
        r.impulse.impulse_contact = a.after - a.before;
        r.impulse.impulse_world = to_world(d.basis, r.impulse.impulse_contact);
        r.velocity_change = velocity_change(r.impulse.impulse_world, d.relative_position, contact.mass);
        rows.total = a.after;

        VelocityIteration record{.iteration = iterations_,
                                 .contact = i,
                                 .desired_delta_velocity = r.desired_delta_velocity.desired_delta_velocity,
                                 .epsilon = settings_.velocity_epsilon,
                                 .sweep = place,
                                 .accumulated = a,
                                 .resolution = r,
                                 .updates = {}};
        apply_velocity_change(bodies_, d.bodies, r.velocity_change);
        if (recorder_.wants_updates()) {
            // The bookkeeping is never read by this method; it is kept up to date only to give the updates.
            by_body_->sharing(d.bodies, sharing_);
            update_contact_velocities(contacts_, sharing_, d.bodies, r.velocity_change, settings_, &record.updates);
            for (VelocityUpdate& u : record.updates) {
                const double target = rows_[static_cast<std::size_t>(u.contact)].target_normal_velocity;
                u.desired_delta_velocity_before = target - u.before.x();
                u.desired_delta_velocity_after = target - u.after.x();
            }
        }
        recorder_.velocity_iteration(record);
        ++iterations_;
    }

    std::vector<RigidBody>& bodies_;
    std::vector<PreparedContact>& contacts_;
    const ResolverSettings& settings_;
    Recorder& recorder_;
    std::vector<ContactRows> rows_;
    std::optional<ContactsByBody> by_body_;  // only to give the recorder its updates
    std::vector<int> sharing_;
    int iterations_ = 0;
};

}  // namespace

PhaseOutcome pgs_velocities(std::vector<RigidBody>& bodies, std::vector<PreparedContact>& contacts,
                            const ResolverSettings& settings, Recorder& recorder, ContactMemory* memory) {
    PgsSolver solver(bodies, contacts, settings, recorder);
    const int warm_started = settings.warm_start && memory ? solver.warm_start(*memory) : 0;
    PhaseOutcome outcome;
    outcome.iteration_limit = warm_started + std::max(settings.sweeps, 0) * solver.active_count();
    bool converged = solver.active_count() == 0;
    for (int pass = 0; pass < settings.sweeps && !converged; ++pass)
        converged = solver.sweep(pass) <= settings.velocity_epsilon;
    if (memory) solver.remember(*memory);
    outcome.iterations_used = solver.iterations();
    outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
    recorder.end_phase(Phase::velocity, outcome);
    return outcome;
}

}  // namespace impulse
