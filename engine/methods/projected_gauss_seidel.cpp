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
// Reported per visit (and per warm start, stage warm_start), when the recorder keeps the frame: the place
// {0, pass, stage}, the totals, the contact velocity read, and step 5 as this method judges the visit
// (separating_velocity = the current v_n, desired_delta_velocity = target - v_n, the value the epsilon is compared
// with); record/visit_records.hpp builds the impulse, step 7 and the other contacts' updates from them.

#include "methods/contact_rows.hpp"
#include "methods/method.hpp"
#include "preparation/bookkeeping.hpp"

#include <algorithm>

namespace impulse {

namespace {

class ProjectedGaussSeidel : RowSolver {
public:
    explicit ProjectedGaussSeidel(FrameContext& frame)
        : RowSolver(frame, false), targets_(rows_.size(), frame.scratch) {
        place_rows([this](ContactRow& row, std::size_t r, const PreparedContact& c) {
            row.slip_offset = c.tangential_acceleration_velocity;  // step 4's term: 0 with the refinement off
            targets_[r] = prepared_normal_velocity(c);
        });
    }

    // Warm start, then sweeps until one changes no contact's velocity by more than the epsilon; then the velocities
    // written back and the totals remembered.
    PhaseOutcome run() {
        // Last frame's totals, re-projected and clamped, applied before the first sweep. The warm start has no target;
        // the recorder is shown the velocity it started from.
        recall([this](std::size_t r, const RowVisit& total) {
            if (frame_.keeping)
                report(r, row_velocity(rows_[r], bodies_.data()), total, SweepPlace{0, 0, SolverStage::warm_start});
            apply(rows_[r], bodies_.data(), total);
            ++iterations_;
        });
        PhaseOutcome outcome;
        outcome.iteration_limit = iterations_ + std::max(settings_.sweeps, 0) * static_cast<int>(rows_.size());
        const double epsilon_squared = settings_.velocity_epsilon * settings_.velocity_epsilon;
        bool converged = rows_.empty();
        for (int pass = 0; pass < settings_.sweeps && !converged && !frame_.stop_requested(); ++pass)
            converged = sweep(pass) <= epsilon_squared;
        // The velocities written back, the totals remembered. Every sweep visits every active contact in index order,
        // so the last visit of each contact is the last sweep's (or the warm start's, without sweeps): they are
        // stamped for LastTouch once, here, in that order.
        store_velocities();
        if (frame_.memory) remember(*frame_.memory);
        stamp();
        outcome.iterations_used = iterations_;
        outcome.stop = converged ? StopReason::resolved : StopReason::sweeps_complete;
        return outcome;
    }

private:
    // One sweep over every active contact in index order; returns the largest |K (after - before)|^2 a visit
    // made at its own contact. The loop reads its data through locals and keeps its visits for the recorder in a
    // buffer (KeptVisit), so that recording or not, it makes no call.
    double sweep(int pass) {
        ContactRow* const rows = rows_.data();
        const std::size_t count = rows_.size();
        SolverBody* const bodies = bodies_.data();
        const double* const targets = targets_.data();
        KeptVisit* const kept = frame_.keeping ? kept_.data() : nullptr;
        double largest = 0.0;
        for (std::size_t r = 0; r < count; ++r) {
            const Axes velocity = row_velocity(rows[r], bodies);
            const Axes before = rows[r].total_impulse;
            if (kept) [[unlikely]]
                keep_visit(kept[r], velocity, before);
            const RowVisit v = solve_rows(rows[r], before, velocity, NormalTarget{targets[r]});
            largest = std::max(largest, velocity_change_squared(rows[r], v.increment()));
            apply(rows[r], bodies, v);
        }
        iterations_ += static_cast<int>(count);
        if (kept)
            for (std::size_t r = 0; r < count; ++r)  // each visit solved again from what it read (KeptVisit)
                report(r, kept[r].velocity,
                       solve_rows(rows[r], kept[r].before, kept[r].velocity, NormalTarget{targets[r]}),
                       SweepPlace{0, pass, SolverStage::solve});
        return largest;
    }

    // Applies the change of the row's total, v.after - v.before, to the bodies, and keeps the total.
    [[gnu::always_inline]] static void apply(ContactRow& row, SolverBody* bodies, const RowVisit& v) {
        apply_impulse(row, bodies, world_impulse(row, v.increment()));
        keep_total(row, v.after);
    }

    void report(std::size_t r, const Axes& velocity, const RowVisit& totals, const SweepPlace& place) const {
        const PreparedContact& c = frame_.contacts[static_cast<std::size_t>(rows_[r].contact)];
        DesiredDeltaVelocity terms = desired_again(c, velocity_refinements(settings_));
        terms.separating_velocity = velocity.n;
        terms.desired_delta_velocity = targets_[r] - velocity.n;
        report_visit(r, place, velocity, totals, terms, settings_.velocity_epsilon, DesiredFollows::row_target);
    }

    std::pmr::vector<double> targets_;  // per row: the normal velocity it asks for (m/s)
    int iterations_ = 0;
};

}  // namespace

PhaseOutcome projected_gauss_seidel_velocities(FrameContext& frame) {
    return ProjectedGaussSeidel(frame).run();
}

}  // namespace impulse
