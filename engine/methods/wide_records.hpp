#pragma once
// Soft step's visits four pairs at a time, in single precision: the order `soft_step.order = wide` (Box3D's
// b3ContactConstraintWide, contact_solver.c). The pairs of a colour (methods/graph_colouring.hpp) share no moving
// body, so four of them are solved side by side, one in each lane of a 4-float register: a record holds four pairs,
// gathers their bodies' velocities once, visits every point of the four on them and writes them back once.
//
// A lane does what a visit of methods/contact_rows.hpp does, by the same functions: K's friction entries
// (derivation/impulse.hpp's delta_velocity_matrix_of and contact_rows.hpp's friction_matrix, over four floats from the
// placed anchors, basis and masses, as Box3D prepares its constraints in floats), step 4's point velocity
// (derivation/contact_velocity.hpp), the rows (solve_rows, over four floats: a point here has a ContactRow's fields,
// four lanes each), step 7's velocity change (derivation/velocity_change.hpp), soft step's aim and anchor move
// (methods/soft_step.hpp); the products sum in math/products.hpp's order. The lanes never mix, so a pair gets the
// same numbers in a record of four as alone. Single precision needs three guards: two in the cone's projection
// (contact_rows.hpp), and one here: a body's velocity change is added to its double velocities, so a body no
// contact moved keeps its bits (docs/bench.md, "Four pairs at a time in single precision").
//
// The overflow's pairs (colour -1, which may share bodies) and pairs of more than four points get records of their
// own, one lane, four points at a time. When the recorder keeps the frame every lane's visit is kept, in doubles, for
// the method to report after the sweep (WideVisit): the kernel with the keeping compiled in, the same operations.

#include "math/lanes.hpp"
#include "methods/contact_rows.hpp"
#include "methods/soft_step.hpp"

#include <array>
#include <cstdint>
#include <memory_resource>
#include <span>
#include <vector>

namespace impulse {

// Point p of four pairs, lane by lane: what a visit reads, by ContactRow's names, and the total it keeps. A lane with
// no point p is zero throughout, so its visit applies nothing. Every sweep reads all of it, 14,964 of them (5 MB) on
// Box3D's large pyramid: what a visit can do without is kept elsewhere (K_tt, which only a sliding visit reads), found
// again (the aim, from p) or kept once for the four pairs' points (the basis, RecordX4::basis).
struct PointX4 {
    Vec3x4 anchor[2];  // r_i (zero for a static body)
    Float4 normal_mass, friction;
    Float4 normal_to_tangent[2];  // K_tn
    Float4 tangent_mass[3];       // K_tt^-1 (11, 12, 22)
    Mask4 tangent_invertible;
    Float4 prepared_penetration;  // p0
    Float4 penetration;           // p: p0, then as the sub-step's first relax sweep finds it (soft_aim's input)
    AxesOf<Float4> total;         // lambda
    Float4 most_pushed;           // the largest lambda_n this frame
};

// Four pairs: their bodies (-1: a static body, or an empty lane), masses and points.
struct RecordX4 {
    std::int32_t body[2][4];
    Float4 inverse_mass[2];
    SymmetricMat3x4 inverse_inertia[2];  // I^-1 (world)
    std::uint32_t first_point, point_count;
    // Point p's step 1 contact_to_world is bases[basis + p * basis_step]: a step of 0 when each pair's points have
    // one basis (a face's points share its normal: every record of Box3D's large pyramid), so a sweep reads 144 bytes
    // a record where it read them for every point quad (WideRecords::prepare).
    std::uint32_t basis, basis_step;
};

// A lane's visit as the recorder is shown it: the velocity it read, its totals, the normal velocity it aimed for.
struct WideVisit {
    Axes velocity;
    RowVisit visit;
    double target_velocity = 0.0;
};

// The soft contact's numbers for a sweep, in each lane.
struct WideSoftness {
    Float4 bias_rate, mass_scale, impulse_scale, max_push_velocity, substep;
    WideSoftness(const Softness& softness, double max_push_velocity, double substep);
};

class WideRecords {
public:
    // The records' layout for the rows in colour order, from each row's `colour` (-1: the overflow) and its two bodies
    // (ContactRow::body): a record takes four pairs of a colour, a pair being a run of rows with the same bodies. Every
    // row is then placed (place) before the first stage.
    WideRecords(std::span<const int> colour, std::span<const std::array<int, 2>> pair,
                std::span<const SolverBody> bodies, const WideSoftness& softness, std::pmr::memory_resource* scratch);
    ~WideRecords();
    WideRecords(const WideRecords&) = delete;
    WideRecords& operator=(const WideRecords&) = delete;

    // Row r's lanes: what a visit reads (its basis among them), its total so far (row.total_impulse) and p0. The
    // friction rows' entries of K are not read from the row (fill_contact_row's FrictionFill::coefficient leaves them
    // out): prepare finds them. Every row is placed once: its lanes are written nowhere else (the points' storage is
    // not cleared first, only the points with an empty lane).
    void place(std::size_t r, const ContactRow& row, double prepared_penetration);
    // Once every row is placed: a record's bases kept once if each of its pairs' points share one; each point's
    // friction rows' K (friction_matrix of delta_velocity_matrix_of, in its lanes, from its anchors, basis and bodies'
    // masses as placed), and p0 as its p for the first solve.
    void prepare();

    // The bodies' velocities in, and each body's change since back out, added to its double velocities.
    void load(std::span<const SolverBody> bodies);
    void store(std::span<SolverBody> bodies);
    // A body's move and turn since the frame began, for the next sweep that finds p.
    void track(std::size_t body, const Vec3& moved, const Mat3& turned);

    // Every total applied again. `kept` (per row, when the frame is recorded): the velocity each visit read and the
    // total it applied.
    void warm_start(WideVisit* kept);
    // One sweep of solve (biased) or relax; `moved`: each point's p found first. `kept` as above.
    template <bool biased, bool moved>
    void sweep(WideVisit* kept);

    // Each row's total, its largest lambda_n, and its total in world coordinates, g = C lambda (as a visit applies
    // it, in the lanes: what the memory keeps for next frame), in doubles.
    void totals(std::span<Axes> total, std::span<double> most_pushed, std::span<Vec3> world) const;

    std::size_t record_count() const { return records_.size(); }
    // The bases the records keep once prepared: one a record where each of its pairs' points share one.
    std::size_t basis_count() const;

private:
    void keep_bases_once();
    template <bool keeping>
    void warm_start_records(WideVisit* kept);
    template <bool biased, bool moved, bool keeping>
    void sweep_records(WideVisit* kept);

    WideSoftness softness_;
    std::pmr::memory_resource* scratch_;
    std::pmr::vector<RecordX4> records_;
    // From the scratch, written by place and prepare alone: a vector's resize would write every point once more
    // (5 MB on Box3D's large pyramid) before place writes it.
    std::span<PointX4> points_;
    // Per point quad as placed, then per record, or per point quad where a pair's points have bases of their own
    // (RecordX4::basis); from the scratch as the points.
    std::span<Mat3x4> bases_;
    std::pmr::vector<std::array<Float4, 3>> tangent_response_;  // per point quad: K_tt (11, 12, 22)
    std::pmr::vector<std::uint32_t> place_;                     // per row: its point quad * 4 + its lane
    std::pmr::vector<std::uint32_t> row_of_;  // per point quad * 4 + lane: its row, or none (an empty lane)
    // Per body, the last the static body (zero throughout): its velocities, which every visit gathers and scatters
    // (24 bytes, apart from its move, which only the sweep that finds p reads), and its move and turn since the frame
    // began.
    struct BodyVelocity {
        float velocity[3];
        float angular_velocity[3];
    };
    struct BodyMove {
        float moved[3];
        float turned[9];  // by columns, as Mat3x4
    };
    std::pmr::vector<BodyVelocity> velocities_;
    std::pmr::vector<BodyVelocity> loaded_;  // as loaded, or last stored
    std::pmr::vector<BodyMove> moves_;
};

}  // namespace impulse
