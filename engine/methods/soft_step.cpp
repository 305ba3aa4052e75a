// Soft step (Box2D v3): sub-steps of integrate velocities, warm start, solve with the soft bias, integrate
// positions and relax; then restitution and the impulses kept for next frame. The outline and the equations
// are in soft_step.hpp; this file follows it stage by stage.

#include "methods/soft_step.hpp"

#include "body/integrate.hpp"
#include "memory/fetch_ahead.hpp"
#include "methods/contact_rows.hpp"
#include "methods/solver_common.hpp"
#include "methods/wide_records.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

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

// What soft step keeps per contact beside its rows, read on every visit. (Small: the rows and these are read
// through once per sweep, and together they must stay in the core's cache.)
struct SoftContact {
    double prepared_penetration = 0.0;  // p0: the penetration when the frame began
    double solve_velocity = 0.0;        // the normal velocity the coming solve asks for, from p (see the header)
    double relax_velocity = 0.0;        // the same for the coming relax
    double most_pushed = 0.0;           // the largest lambda_n this frame: restitution needs a contact that pushed
    bool soft = false;                  // p >= 0: the solve's target is the soft contact's (else speculative)
};

// What restitution reads once, at the end of the frame.
struct SoftBounce {
    double relative_velocity = 0.0;  // v_n when the frame began (step 4), which restitution reverses
    double restitution = 0.0;        // c
    bool cutoff_applied = false;     // c > 0, but it did not close faster than the restitution cut-off
    bool bounces = false;            // c > 0 and it closed faster than the cut-off
};

class SoftStep : public RowSolver {
public:
    // In `wide` order the rows are built one at a time into the wide records, in the order of the visits, and kept
    // as rows only when the frame is recorded (the recorder reads them); restitution builds its own.
    explicit SoftStep(FrameContext& frame)
        : RowSolver(frame, frame.settings.soft_step.order != SolveOrder::contacts,
                    frame.settings.soft_step.order != SolveOrder::wide || frame.keeping),
          substep_(frame.settings.duration / frame.settings.soft_step.substeps),
          softness_(soft_step_softness(frame.settings)),
          soft_(wide() ? 0 : moving_.size(), frame.scratch),
          bounce_(moving_.size(), frame.scratch),
          start_position_(frame.scratch),
          start_orientation_(frame.scratch),
          moved_(frame.bodies.size(), Vec3::Zero(), frame.scratch),
          turned_(frame.bodies.size(), Mat3::Identity(), frame.scratch) {
        start_position_.reserve(frame.bodies.size());
        start_orientation_.reserve(frame.bodies.size());
        for (const RigidBody& body : frame.bodies) {
            start_position_.push_back(body.position);
            start_orientation_.push_back(body.orientation);
        }
        if (wide()) {
            place_wide();
            return;
        }
        place_rows([this](const ContactRow&, std::size_t r, const PreparedContact& d) {
            SoftContact& c = soft_[r];
            c.prepared_penetration = d.penetration;
            aim_at(c, d.penetration);
            bounce_[r] = bounce_of(d);
        });
        recall([this](std::size_t r, const RowVisit& total) { rows_[r].total_impulse = total.after; });
    }

    // The totals kept for next frame: the rows', or in wide order those the records gave back in world coordinates
    // (world_: the records' g = C lambda in floats, where the rows' is found in doubles from each contact's basis,
    // which would be fetched from memory again, 60,000 of them on Box3D's large pyramid: 3 % of the profile).
    void remember(ContactMemory& memory) const {
        if (!wide()) return RowSolver::remember(memory);
        remember_world(memory, [this](std::size_t r) -> const Vec3& { return world_[r]; });
    }

    void run() {
        const Forces& f = frame_.forces;
        const int substeps = settings_.soft_step.substeps;
        for (int substep = 0; substep < substeps && !frame_.stop_requested(); ++substep) {
            for (std::size_t b = 0; b < bodies_.size(); ++b) {  // integrated, then loaded into the solver's bodies
                integrate_velocity(frame_.bodies[b], f.gravity, substep_, f.damping);
                bodies_[b].velocity = frame_.bodies[b].velocity;
                bodies_[b].angular_velocity = frame_.bodies[b].angular_velocity;
            }
            if (wide_) wide_->load(bodies_);
            warm_start(substep);
            for (int pass = 0; pass < settings_.sweeps && (pass % 64 != 0 || !frame_.stop_requested()); ++pass)
                sweep<true>({substep, pass, SolverStage::solve});
            if (wide_) wide_->store(bodies_);
            store_velocities();
            for (RigidBody& body : frame_.bodies) integrate_position(body, substep_, settings_.orientation_update);
            track_moves();
            // The first relax sweep finds each contact's p as it visits it (the bodies move only here).
            for (int pass = 0; pass < settings_.sweeps && (pass % 64 != 0 || !frame_.stop_requested()); ++pass)
                if (pass == 0)
                    sweep<false, true>({substep, pass, SolverStage::relax});
                else
                    sweep<false>({substep, pass, SolverStage::relax});
            if (wide_) wide_->store(bodies_);
            store_velocities();
        }
        if (wide_) wide_->totals(total_, most_pushed_, world_);  // for restitution and the memory
        // Every sweep visits every row in order, so the last sub-step's last sweep holds each contact's last visit
        // before restitution: stamped for LastTouch once, here (restitution stamps its own).
        stamp();
        const SweepPlace last{substeps - 1, 0, SolverStage::restitution};
        for (std::size_t r = 0; r < moving_.size(); ++r) {
            if (!bounce_[r].bounces) continue;
            if (!wide()) {
                if (soft_[r].most_pushed > 0.0) restitution(rows_[r], r, last);
            } else if (most_pushed_[r] > 0.0) {
                // The row, built again as its lanes were placed from (place_wide): the few contacts that bounce fill
                // theirs twice, where keeping every row for them would keep 264 bytes a contact all frame.
                ContactRow row;
                fill_contact_row(row, frame_.contacts[moving_[order_[r]]], bodies_.data());
                row.total_impulse = total_[r];
                restitution(row, r, last);
                total_[r] = row.total_impulse;
                world_[r] = world_impulse(row, total_[r]);
            }
        }
        store_velocities();
    }

    int visits() const { return visits_; }
    int visit_limit() const { return visits_; }  // the schedule is fixed: it always runs to its end

private:
    bool wide() const { return settings_.soft_step.order == SolveOrder::wide; }

    // Step 4's v_s, which restitution reverses, judged once against the cut-off.
    SoftBounce bounce_of(const PreparedContact& d) const {
        SoftBounce bounce;
        bounce.restitution = d.restitution;
        if (d.restitution == 0.0) return bounce;
        bounce.relative_velocity = d.contact_velocity.x();
        bounce.cutoff_applied = !(bounce.relative_velocity < -settings_.restitution_cutoff);
        bounce.bounces = !bounce.cutoff_applied;
        return bounce;
    }

    // The rows, in the order of the visits (colour by colour), become the wide records: each built from its contact
    // and its remembered total, placed in its lanes, and kept as a row only when the frame is recorded.
    void place_wide() {
        const std::size_t count = moving_.size();
        std::pmr::vector<int> colour(count, 0, frame_.scratch);
        std::pmr::vector<std::array<int, 2>> pair(count, frame_.scratch);
        for (std::size_t r = 0; r < count; ++r) {
            colour[r] = colours_[order_[r]];
            pair[r] = pairs_[order_[r]];
        }
        wide_.emplace(colour, pair, bodies_, WideSoftness(softness_, settings_.soft_step.max_push_velocity, substep_),
                      frame_.scratch);
        total_.assign(count, Axes{});
        most_pushed_.assign(count, 0.0);
        world_.resize(count);
        // One pass over the contacts, in detection's order (the order they lie in memory, and the memory's): each
        // contact's total recalled, its row built and placed.
        std::optional<RememberedTotals> remembered = remembered_totals();
        for (std::size_t k = 0; k < count; ++k) {
            const std::size_t r = slots_[k];
            const PreparedContact& d = frame_.contacts[moving_[k]];
            if (k + 6 < count) fetch_ahead(frame_.contacts[moving_[k + 6]]);  // nearly all of it is read
            // Unrecorded, the friction rows' K is left to the records (prepare, four contacts at a time in floats);
            // a recorded frame's rows have theirs, for the recorder.
            ContactRow row;
            fill_contact_row(row, d, bodies_.data(), frame_.keeping ? FrictionFill::rows : FrictionFill::coefficient);
            if (remembered)
                if (const std::optional<RowVisit> total = recalled(*remembered, k)) keep_total(row, total->after);
            wide_->place(r, row, d.penetration);
            bounce_[r] = bounce_of(d);
            if (frame_.keeping) new (rows_.data() + r) ContactRow(row);
        }
        wide_->prepare();
        if (frame_.keeping) wide_kept_.resize(count);
    }

    // After the positions moved: each body's move and turn since the frame began.
    void track_moves() {
        for (std::size_t b = 0; b < frame_.bodies.size(); ++b) {
            const RigidBody& body = frame_.bodies[b];
            moved_[b] = body.position - start_position_[b];
            turned_[b] = (body.orientation * start_orientation_[b].conjugate()).toRotationMatrix();
            if (wide_) wide_->track(b, moved_[b], turned_[b]);
        }
    }

    // p = p0 - n . [(dx0 + R0 r0 - r0) - (dx1 + R1 r1 - r1)]: the anchors turn with their bodies.
    [[gnu::always_inline]] double penetration(std::size_t r) const {
        const ContactRow& row = rows_[r];
        Vec3 separated = Vec3::Zero();  // how far body 0's anchor moved away from body 1's
        for (int i = 0; i < 2; ++i) {
            if (row.body[i] < 0) continue;
            const auto b = static_cast<std::size_t>(row.body[i]);
            separated += body_sign(i) * anchor_move(moved_[b], turned_[b], row.anchor[i]);
        }
        return soft_[r].prepared_penetration - dot(separated, normal_of(row));
    }

    // The soft bias of a point at penetration p for the coming solve and relax (soft_step.hpp's soft_aim).
    void aim_at(SoftContact& c, double penetration) const {
        const SoftAimOf<double> aim =
            soft_aim<double>(penetration, softness_.bias_rate, settings_.soft_step.max_push_velocity, substep_);
        c.soft = aim.soft;
        c.solve_velocity = aim.solve_velocity;
        c.relax_velocity = aim.relax_velocity;
    }

    // What a visit of solve (with the soft contact's bias and scales) or relax (rigid, unbiased) asks of row r.
    template <bool biased>
    [[gnu::always_inline]] NormalTarget target_of(std::size_t r) const {
        const SoftContact& c = soft_[r];
        if (biased && c.soft) return {c.solve_velocity, softness_.mass_scale, softness_.impulse_scale};
        return {biased ? c.solve_velocity : c.relax_velocity, 1.0, 0.0};
    }

    // (K lambda)_n: the normal velocity change the total lambda makes at its own contact.
    static double normal_change(const ContactRow& row, const Axes& total) {
        return row.normal_response * total.n + row.normal_to_tangent[0] * total.t1 +
               row.normal_to_tangent[1] * total.t2;
    }

    // Every contact's lambda applied again: the sub-step's velocities start without any contact impulse.
    void warm_start(int substep) {
        if (wide_) return wide_warm_start(substep);
        KeptVisit* const kept = frame_.keeping ? kept_.data() : nullptr;
        for (std::size_t r = 0; r < rows_.size(); ++r) {
            const ContactRow& row = rows_[r];
            RowVisit v;  // from 0: the total counts what this sub-step has applied
            v.unclamped = v.after = row.total_impulse;
            if (kept) [[unlikely]]
                keep_visit(kept[r], row_velocity(row, bodies_.data()), v.before);
            apply(r, v);
        }
        // The warm start has no target: the recorder is shown the normal velocity change it makes, (K lambda)_n.
        if (kept)
            for (std::size_t r = 0; r < rows_.size(); ++r) {
                const ContactRow& row = rows_[r];
                const Axes& total = row.total_impulse;  // the warm start's total after, unchanged since
                RowVisit v;
                v.unclamped = v.after = total;
                report(r, {substep, 0, SolverStage::warm_start}, kept[r].velocity, v, normal_change(row, total),
                       std::nullopt);
            }
    }

    // One sweep of solve (with the soft bias) or relax (without); `moved`: the bodies moved since the last sweep,
    // so each contact's p is found first, and what it asks of this sub-step's relax and the next one's solve. Its
    // visits are kept for the recorder in a buffer and reported after the sweep (KeptVisit), solved again with the
    // targets they had (a contact's aim changes only at the sweep that finds its p, before its visit).
    template <bool biased, bool moved = false>
    void sweep(const SweepPlace& place) {
        if (wide_) return wide_sweep<biased, moved>(place);
        KeptVisit* const kept = frame_.keeping ? kept_.data() : nullptr;
        for (std::size_t r = 0; r < rows_.size(); ++r) {
            if constexpr (moved) aim_at(soft_[r], penetration(r));
            const ContactRow& row = rows_[r];
            const Axes velocity = row_velocity(row, bodies_.data());
            const Axes before = row.total_impulse;
            if (kept) [[unlikely]]
                keep_visit(kept[r], velocity, before);
            const RowVisit v = solve_rows(row, before, velocity, target_of<biased>(r));
            apply(r, v);
        }
        if (kept)
            for (std::size_t r = 0; r < rows_.size(); ++r) {
                const NormalTarget target = target_of<biased>(r);
                const Axes& velocity = kept[r].velocity;
                report(r, place, velocity, solve_rows(rows_[r], kept[r].before, velocity, target),
                       target.velocity - velocity.n, target.velocity);
            }
    }

    // The same stages in wide records (methods/wide_records.hpp): the visits kept lane by lane when the frame is
    // recorded, and reported as above after the stage.
    void wide_warm_start(int substep) {
        WideVisit* const kept = frame_.keeping ? wide_kept_.data() : nullptr;
        wide_->warm_start(kept);
        visits_ += static_cast<int>(moving_.size());
        if (kept)
            for (std::size_t r = 0; r < moving_.size(); ++r) {
                const ContactRow& row = rows_[r];
                const Axes& total = kept[r].visit.after;
                report(r, {substep, 0, SolverStage::warm_start}, kept[r].velocity, kept[r].visit,
                       normal_change(row, total), std::nullopt);
            }
    }

    template <bool biased, bool moved>
    void wide_sweep(const SweepPlace& place) {
        WideVisit* const kept = frame_.keeping ? wide_kept_.data() : nullptr;
        wide_->sweep<biased, moved>(kept);
        visits_ += static_cast<int>(moving_.size());
        if (kept)
            for (std::size_t r = 0; r < moving_.size(); ++r)
                report(r, place, kept[r].velocity, kept[r].visit, kept[r].target_velocity - kept[r].velocity.n,
                       kept[r].target_velocity);
    }

    // Restitution's visit of row r (`row`: rows_[r], or in wide order one built for it).
    void restitution(ContactRow& row, std::size_t r, const SweepPlace& place) {
        const double c_used = bounce_[r].restitution;
        const Axes velocity = row_velocity(row, bodies_.data());
        // The target is -c v_n(before): delta lambda_n = -m_n (v_n + c v_n(before)), total kept >= 0.
        const NormalTarget target{-c_used * bounce_[r].relative_velocity};
        const RowVisit v = solve_normal_row(row, velocity.n, target);
        keep_total(row, v.after);
        apply_impulse(row, bodies_.data(), world_impulse(row, v.increment()));
        ++visits_;
        if (frame_.touch) frame_.touch->touched(row.contact);
        if (frame_.keeping) report(r, place, velocity, v, target.velocity - velocity.n, std::nullopt);
    }

    // Applies after - before to the bodies by step 7 and keeps the total.
    [[gnu::always_inline]] void apply(std::size_t r, const RowVisit& v) {
        ContactRow& row = rows_[r];
        const Vec3 impulse = world_impulse(row, v.increment());
        keep_total(row, v.after);
        soft_[r].most_pushed = std::max(soft_[r].most_pushed, v.after.n);
        apply_impulse(row, bodies_.data(), impulse);
        ++visits_;
    }

    // The visit as the recorder takes it: the velocity it read, what it aimed at (desired delta v = target - v_n,
    // and the soft bias as step 5's position bias), its totals.
    void report(std::size_t r, const SweepPlace& place, const Axes& velocity, const RowVisit& visit,
                double desired_delta_velocity, std::optional<double> position_bias) const {
        const SoftBounce& bounce = bounce_[r];
        const bool bouncing = place.stage == SolverStage::restitution;
        report_visit(r, place, velocity, visit,
                     {.separating_velocity = velocity.n,
                      .restitution = bounce.restitution,
                      .restitution_cutoff = settings_.restitution_cutoff,
                      .restitution_cutoff_applied = bounce.cutoff_applied,
                      .restitution_used = bouncing ? bounce.restitution : 0.0,
                      .velocity_from_acceleration_applied = false,
                      .velocity_from_acceleration = 0.0,
                      .position_bias = position_bias,
                      .desired_delta_velocity = desired_delta_velocity},
                     0.0, DesiredFollows::nothing, !bouncing);
    }

    double substep_;
    Softness softness_;
    // Every buffer in the frame's scratch (FrameContext::scratch), as the rows'.
    std::pmr::vector<SoftContact> soft_;   // beside each row
    std::pmr::vector<SoftBounce> bounce_;  // beside each row
    std::pmr::vector<Vec3> start_position_;
    std::pmr::vector<Quat> start_orientation_;
    std::pmr::vector<Vec3> moved_;   // per body: its move since the frame began
    std::pmr::vector<Mat3> turned_;  // per body: its turn since the frame began, R = q q0^-1
    int visits_ = 0;
    // In `wide` order, per row in the order of the visits: its total and largest lambda_n after the sweeps.
    std::optional<WideRecords> wide_;  // the rows four pairs at a time
    std::pmr::vector<Axes> total_{frame_.scratch};
    std::pmr::vector<double> most_pushed_{frame_.scratch};
    std::pmr::vector<Vec3> world_{frame_.scratch};
    std::pmr::vector<WideVisit> wide_kept_{frame_.scratch};  // per row: its visit in the stage under way, if recorded
};

}  // namespace

PhaseOutcome soft_step(FrameContext& frame) {
    return whole_step<SoftStep>(frame);
}

}  // namespace impulse
