// Projected Gauss-Seidel with accumulated impulses: sequential impulses as Catto presented them (GDC 2005-
// 2014) and as Box2D v2.4 and Bullet solve contacts. Each contact keeps a running total impulse lambda in
// contact coordinates (x = normal, y and z = the basis tangents); each visit computes the impulse that would
// meet the contact's target from the velocity the bodies have now, adds it to the total, clamps the total
// (not the increment) to what a contact can do, and applies only the change of the total. A contact that an
// earlier visit pushed too hard can therefore give impulse back, which the book's methods cannot.
//
// The rows are methods/contact_rows.hpp's (normal row, two friction rows against the slip, the cone), with
//   target      = v_s + desired delta v of step 5 at preparation = -c_used (v_s - v_acc) + position_bias:
//                 the bounce judged once, on the closing speed before any impulse (restitution cut-off and
//                 velocity from acceleration as the settings say), plus Baumgarte's term when `baumgarte` is on
//   slip offset = step 4's tangential acceleration term (when the refinement is on): the bodies' last-frame
//                 acceleration does not change during the frame, so it is added as a constant.
// Applied this visit: lambda_after - lambda_before, through step 7 (velocity_change).
//
// Warm starting (settings.warm_start): before the sweeps, each contact found in the ContactMemory (by
// contact_key) starts from last frame's total, stored in world coordinates and re-projected on this frame's
// basis, normal part clamped >= 0 and tangential part to the cone, and that total is applied at once. At the
// end every contact's total is remembered in world coordinates (also without warm starting, so it can be
// switched on mid-run). When two contacts of a frame share a key (hand-written contacts have no features),
// only the first is warm started: the memory keeps the first one's total.
//
// The sweeps stop early when no visit of a whole sweep changed its own contact's velocity by more than the
// velocity epsilon, |K (lambda_after - lambda_before)| (a norm: no basis decides it); iterations_per_contact
// and velocity_iterations do not apply.
//
// Recorded per visit (and per warm start, stage warm_start), only when the recorder keeps iterations (the loop
// is compiled twice from one template, the same arithmetic both ways): a VelocityIteration with sweep
// {0, pass, stage}, accumulated {before, unclamped, after, clamp}, and a resolution whose contact_velocity is
// the velocity read from the bodies, whose desired_delta_velocity is step 5 at preparation with
// separating_velocity = the current v_n and desired_delta_velocity = target - v_n (the value compared with the
// epsilon), and whose impulse / impulse_world is the increment applied (model frictionless,
// static_friction, or sliding_friction when the cone clamped; no friction_solve: that is the book's 3x3
// solve, not this one). The updates list is filled as worst-first fills it (the linearised bookkeeping of
// every contact sharing a body), but with desired delta v read in this method's terms, target - v_n.

#include "methods/contact_rows.hpp"
#include "methods/solver_common.hpp"
#include "methods/method.hpp"
#include "methods/bookkeeping.hpp"
#include "methods/worst_first_selector.hpp"

#include <algorithm>

namespace impulse {

namespace {

ImpulseModel model_of(double friction, ImpulseClamp clamp) {
    if (friction == 0.0) return ImpulseModel::frictionless;
    return clamp == ImpulseClamp::friction || clamp == ImpulseClamp::both ? ImpulseModel::sliding_friction
                                                                          : ImpulseModel::static_friction;
}

class ProjectedGaussSeidel {
public:
    explicit ProjectedGaussSeidel(FrameContext& frame)
        : frame_(frame),
          bodies_(solver_bodies(frame.bodies, frame.mass, frame.scratch)),
          active_(frame.rows.size(), frame.scratch),
          targets_(frame.scratch),
          warm_started_(frame.scratch) {
        targets_.reserve(frame.rows.size());
        for (const RowPreparation& d : frame.rows) {
            ContactRow* row = active_.add(d, bodies_.data());
            if (!row) continue;                         // nothing can move it: no visits
            const RowVelocity& velocity = *d.velocity;  // prepared with steps 4 and 5 (the method table says so)
            row->slip_offset = velocity.tangential_acceleration_velocity;  // step 4's term: 0 with the refinement off
            targets_.push_back(prepared_normal_velocity(velocity));
        }
    }

    int active_count() const { return static_cast<int>(active_.rows.size()); }

    // Last frame's totals, re-projected and clamped, applied before the first sweep. Returns how many.
    template <bool recording>
    int warm_start(const ContactMemory& memory) {
        RememberedTotals remembered(memory, frame_.scratch);
        int started = 0;
        for (std::size_t r = 0; r < active_.rows.size(); ++r) {
            const std::optional<RowVisit> total = remembered.of(active_.rows[r], active_.keys[r]);
            if (!total) continue;
            Axes velocity;
            if constexpr (recording) velocity = row_velocity(active_.rows[r], bodies_.data());
            visit<recording>(r, *total, SweepPlace{0, 0, SolverStage::warm_start}, velocity);
            warm_started_.push_back(active_.rows[r].contact);
            ++started;
        }
        return started;
    }

    // One sweep over every active contact in index order; returns the largest |K (after - before)|^2 a visit
    // made at its own contact.
    template <bool recording>
    double sweep(int pass) {
        double largest = 0.0;
        SolverBody* bodies = bodies_.data();
        for (std::size_t r = 0; r < active_.rows.size(); ++r) {
            const Axes velocity = row_velocity(active_.rows[r], bodies);
            const RowVisit v = solve_rows(active_.rows[r], velocity, NormalTarget{targets_[r]});
            largest = std::max(largest, velocity_change_squared(active_.rows[r], v.increment()));
            visit<recording>(r, v, SweepPlace{0, pass, SolverStage::solve}, velocity);
        }
        return largest;
    }

    // Writes the velocities back to the bodies, remembers the totals.
    void finish(ContactMemory* memory) {
        store_velocities(bodies_, frame_.bodies);
        if (memory) remember_totals(active_.rows, active_.keys, *memory);
    }

    // The contacts of the last visits, in visit order: every sweep visits every active contact in index order.
    std::span<const int> last_visited(int sweeps) const {
        return sweeps > 0 ? std::span<const int>(active_.contacts) : std::span<const int>(warm_started_);
    }
    int iterations() const { return iterations_; }

private:
    // Applies the change of row r's total, v.after - v.before, and (recording) reports the visit.
    template <bool recording>
    [[gnu::always_inline]] void visit(std::size_t r, const RowVisit& v, const SweepPlace& place, const Axes& velocity) {
        ContactRow& row = active_.rows[r];
        const Axes increment = v.increment();
        const Vec3 impulse = world_impulse(row, increment);
        keep_total(row, v.after);
        if constexpr (!recording) {
            apply_impulse(row, bodies_.data(), impulse, nullptr);
        } else {
            VelocityChange change;
            apply_impulse(row, bodies_.data(), impulse, &change);
            record(r, v, place, vector_of(velocity), vector_of(increment), impulse, change);
        }
        ++iterations_;
    }

    void record(std::size_t r, const RowVisit& v, const SweepPlace& place, const Vec3& velocity, const Vec3& increment,
                const Vec3& impulse, const VelocityChange& change) {
        const int i = active_.rows[r].contact;
        const ContactPreparation& d = frame_.contacts[static_cast<std::size_t>(i)].derivation;
        VelocityResolution resolution;
        resolution.contact_velocity = velocity;
        resolution.desired_terms = d.desired_terms;
        resolution.desired_terms.separating_velocity = velocity.x();
        resolution.desired_terms.desired_delta_velocity = targets_[r] - velocity.x();
        resolution.impulse_terms.impulse_model = model_of(d.friction, v.clamp());
        resolution.impulse_terms.impulse = increment;
        resolution.impulse_terms.impulse_world = impulse;
        resolution.velocity_change_terms = change;
        VelocityIteration iteration{.iteration = iterations_,
                                    .contact = i,
                                    .desired_delta_velocity = targets_[r] - velocity.x(),
                                    .epsilon = frame_.settings.velocity_epsilon,
                                    .sweep = place,
                                    .accumulated = v.accumulated(),
                                    .resolution = resolution,
                                    .updates = {}};
        // The bookkeeping is never read by this method; it is kept up to date only to give the updates, with
        // each contact's desired delta v in this method's terms.
        if (!by_body_) {
            by_body_.emplace(frame_.contacts, frame_.bodies.size());
            target_of_.assign(frame_.contacts.size(), 0.0);
            for (std::size_t k = 0; k < active_.rows.size(); ++k)
                target_of_[static_cast<std::size_t>(active_.rows[k].contact)] = targets_[k];
        }
        by_body_->sharing(d.bodies, sharing_);
        update_contact_velocities(frame_.contacts, sharing_, d.bodies, change, frame_.settings, &iteration.updates);
        for (VelocityUpdate& u : iteration.updates) {
            const double target = target_of_[static_cast<std::size_t>(u.contact)];
            u.desired_delta_velocity_before = target - u.before.x();
            u.desired_delta_velocity_after = target - u.after.x();
        }
        frame_.recorder.velocity_iteration(iteration);
    }

    FrameContext& frame_;
    // Every buffer but the recorder's in the frame's scratch (FrameContext::scratch).
    std::pmr::vector<SolverBody> bodies_;
    ActiveRows active_;                   // the rows, in contact order, with their contacts and keys
    std::pmr::vector<double> targets_;    // per row: the normal velocity it asks for (m/s)
    std::pmr::vector<int> warm_started_;  // the contacts warm started, in order
    int iterations_ = 0;
    // Only to give the recorder its updates:
    std::optional<ContactsByBody> by_body_;
    std::vector<double> target_of_;  // per contact
    std::vector<int> sharing_;
};

template <bool recording>
PhaseOutcome solve(FrameContext& frame) {
    const ResolverSettings& settings = frame.settings;
    ProjectedGaussSeidel pgs(frame);
    const int warm_started = settings.warm_start && frame.memory ? pgs.warm_start<recording>(*frame.memory) : 0;
    PhaseOutcome outcome;
    outcome.iteration_limit = warm_started + std::max(settings.sweeps, 0) * pgs.active_count();
    const double epsilon_squared = settings.velocity_epsilon * settings.velocity_epsilon;
    bool converged = pgs.active_count() == 0;
    int sweeps = 0;
    for (; sweeps < settings.sweeps && !converged && !frame.stop_requested(); ++sweeps)
        converged = pgs.sweep<recording>(sweeps) <= epsilon_squared;
    pgs.finish(frame.memory);
    if constexpr (!recording) frame.recorder.contacts_visited(pgs.last_visited(sweeps));
    outcome.iterations_used = pgs.iterations();
    outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
    frame.recorder.end_phase(Phase::velocity, outcome);
    return outcome;
}

}  // namespace

PhaseOutcome projected_gauss_seidel_velocities(FrameContext& frame) {
    return frame.recorder.wants_updates() ? solve<true>(frame) : solve<false>(frame);
}

}  // namespace impulse
